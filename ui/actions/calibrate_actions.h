// What the Calibrate menu does: the automatic table (issue 33) made from the stream shown, in
// the background with progress and Cancel, and put in as one undo step of the colour table
// (the goal colour it found, when the pipeline's differs, as a step of the pipeline settings
// before it); the message bar then says what each class took. Cancel or an error leaves the
// table as it was.
#pragma once

#include "ui/actions/menus.h"
#include "ui/scans/auto_lut_run.h"

#include <QObject>
#include <QString>

namespace fieldsight::ui {

class CalibrateActions : public QObject
{
    Q_OBJECT
public:
    explicit CalibrateActions(const MenuTarget& target);

    /// Calibrate > Automatic table: starts the run over the stream shown (nothing while one
    /// runs; a message when there is no stream of files).
    void automaticTable();
    bool running() const { return m_run->running(); }
    void cancel() { m_run->cancel(); }
    /// The run, for tests that give it a builder of their own.
    AutoLutRun& run() { return *m_run; }

signals:
    /// A run ended: its table went in (`applied`), or it was cancelled, failed or dropped.
    void finished(bool applied);

private:
    void onFinished(const Result<AutoLut>& result);
    /// The goal colour `goal` into every colour parameter named goal_colour that differs (one
    /// undo step); whether any changed.
    bool setGoalColour(Colour goal);
    /// The message bar's line for a table put in.
    QString summary(const AutoLut& result, std::size_t cells_changed, bool goal_set) const;

    MenuTarget m_target;
    AutoLutRun* m_run = nullptr;
    bool m_stale = false; ///< the stream changed while the run read it
};

} // namespace fieldsight::ui
