// The evaluation dock: the stream's scores against its annotations (per kind true and false
// positives, misses, precision, recall and concealed objects; the boundary error), what the last
// table or settings change did to them, and the frames where detections and truth disagree.
// Choosing one goes there with the culprits (the missed true object, the false detection) drawn
// emphasised; the window marks the frames on the timeline and steps through them with a key.
// Every kind is named by the percept registry: the dock names none.
#pragma once

#include "ui/document/evaluation_scan.h"
#include "ui/document/stream_document.h"

#include <QImage>
#include <QWidget>

#include <map>

class QLabel;
class QListWidget;
class QProgressBar;
class QPushButton;
class QTableWidget;

namespace fieldsight::ui {

/// "<noun> recall 0.91 → 0.97, <noun> precision 1.00 → 0.96": the precisions, recalls and
/// boundary error that differ between two evaluations, each kind by its noun from the percept
/// registry (two decimals, or three where two would not show the change); "no change in the
/// scores" when none differs.
QString scoreChangeText(const EvaluationScores& before, const EvaluationScores& after);

class EvaluationPanel : public QWidget
{
    Q_OBJECT
public:
    EvaluationPanel(EvaluationScan& scan, StreamDocument& stream, QWidget* parent = nullptr);

    QTableWidget& scores() { return *m_scores; }
    QListWidget& frames() { return *m_frames; }
    /// What the last change did to the scores (empty when the evaluation followed none).
    QString changeText() const;
    QString statusText() const;

    /// Chooses disagreement `row` of the list (EvaluationScan::failing() order): goes to its
    /// frame and draws its culprits emphasised.
    void showDisagreement(int row);
    /// Chooses the first disagreement of frame `index`, if it has one; else goes there.
    void showFrame(std::size_t index);
    /// Chooses the next disagreement after the one chosen, or after the current frame
    /// (direction > 0), or the one before.
    void jump(int direction);
    /// The disagreement chosen (-1: none, or its frame is no longer shown).
    int chosen() const { return m_chosen; }
    /// The frames with a disagreement, each with one line saying what disagrees there.
    std::map<std::size_t, QString> frameMarks() const;

signals:
    /// The culprits of the chosen disagreement, an image of the frame's size, transparent
    /// elsewhere (null: none to show); for the frame view's highlight.
    void highlightChanged(const QImage& image);
    /// The chosen disagreement's culprits lie in `bounds` (image px).
    void culpritsAt(const QRect& bounds);
    /// A new evaluation: frameMarks() changed.
    void marksChanged();

private:
    void refresh();
    void refreshProgress();
    void choose(int row);
    QImage culpritImage(const FailingFrame& failing) const;

    EvaluationScan& m_scan;
    StreamDocument& m_stream;
    QLabel* m_status = nullptr;
    QProgressBar* m_progress = nullptr;
    QPushButton* m_run = nullptr;
    QPushButton* m_cancel = nullptr;
    QTableWidget* m_scores = nullptr;
    std::vector<const PerceptKind*> m_kinds; ///< the scored kinds, one a row of m_scores
    QLabel* m_boundary = nullptr;
    QLabel* m_change = nullptr;
    QListWidget* m_frames = nullptr;
    int m_chosen = -1;
    FailingFrame m_chosen_what; ///< to find it again in the next evaluation
};

} // namespace fieldsight::ui
