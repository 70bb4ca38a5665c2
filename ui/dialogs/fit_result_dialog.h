// Pipeline > Fit to annotations' result, before anything is applied: per class the score of the
// parameters it started from and of the tuned ones, on the frames the search fitted and on the
// frames it held out (so a fit that does not hold shows), then every parameter it changed with
// its old and new value and what that change bought. Apply asks the caller to put them in use
// (FitActions: one undo step of the pipeline settings). Every class, stage and parameter is
// named by the registries and the result: the dialog names none.
#pragma once

#include "visioncore/framework/controller.h"
#include "visioncore/services/param_tuning.h"

#include <QDialog>

class QLabel;
class QPushButton;
class QTableWidget;

namespace fieldsight::ui {

/// A parameter's value as a user reads it: a choice by its name, a switch as on or off, a whole
/// number without decimals, a real with the decimals of its step; the unit after it.
QString paramValueText(const ParamInfo& param, double value);

class FitResultDialog : public QDialog
{
    Q_OBJECT
public:
    FitResultDialog(TuneResult result, const Pipeline& pipeline, QWidget* parent = nullptr);

    const TuneResult& result() const { return m_result; }
    /// Rows: each class scored, the boundary, the total; columns: the class, then fit start,
    /// fit tuned, held-out start, held-out tuned.
    QTableWidget& scores() { return *m_scores; }
    /// One row per change (TuneResult::changes order): parameter, start, tuned, what it bought.
    QTableWidget& changes() { return *m_changes; }
    QPushButton& applyButton() { return *m_apply; }
    /// The lines above the tables: frames, evaluations, time, the total scores.
    QString summary() const;
    /// A line under the tables (the parameters changed while the search ran…); empty hides it.
    void setNote(const QString& note);

signals:
    /// Apply: the caller puts result().params in use.
    void applyRequested();

private:
    void fillScores(const Pipeline& pipeline);
    void fillChanges(const Pipeline& pipeline);
    /// Sized to show both tables whole, within the screen.
    void fitSize();

    TuneResult m_result;
    QLabel* m_summary = nullptr;
    QTableWidget* m_scores = nullptr;
    QTableWidget* m_changes = nullptr;
    QLabel* m_note = nullptr;
    QPushButton* m_apply = nullptr;
};

} // namespace fieldsight::ui
