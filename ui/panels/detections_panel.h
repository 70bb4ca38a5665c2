// What the current frame found: each percept list of the result with its numbers, and the
// frame's diagnostics (a stage that threw shows here; the tool goes on).
#pragma once

#include "ui/document/frame_worker.h"

#include <QTreeWidget>

namespace fieldsight::ui {

class DetectionsPanel : public QTreeWidget
{
    Q_OBJECT
public:
    explicit DetectionsPanel(QWidget* parent = nullptr);
    void showOutput(const FrameOutput* output);
    /// The top-level rows' texts ("Balls (1)", "Diagnostics (0)"), for tests.
    QStringList topLevelTexts() const;

signals:
    /// A detection was chosen in the list: its bounds, image px.
    void detectionActivated(const QRectF& bounds);
};

} // namespace fieldsight::ui
