// What the current frame found: each percept list of the result with its numbers, and the
// frame's diagnostics (a stage that threw shows here; the tool goes on).
#pragma once

#include "ui/worker/frame_worker.h"

#include <QTreeWidget>

namespace fieldsight::ui {

class DetectionsPanel : public QTreeWidget
{
    Q_OBJECT
public:
    explicit DetectionsPanel(QWidget* parent = nullptr);
    /// Shows a frame's detections, updating the rows in place (expanded lists stay expanded).
    void showOutput(const FrameOutput* output);
    /// The serial of the output shown (0 for none).
    std::uint64_t shownSerial() const { return m_serial; }
    /// The top-level rows' texts (each kind's title and count, then "Diagnostics (0)"), for tests.
    QStringList topLevelTexts() const;

signals:
    /// A detection was chosen in the list: its bounds, image px.
    void detectionActivated(const QRectF& bounds);

private:
    std::uint64_t m_serial = 0;
};

} // namespace fieldsight::ui
