// The pixel inspector: what is under the cursor (position, Y/Cb/Cr, R/G/B, colour class) and
// which shapes of the stages' layers cover it (the scan line, the segment, a transition).
#pragma once

#include "ui/worker/frame_worker.h"

#include <QLabel>

namespace fieldsight::ui {

class InspectorPanel : public QLabel
{
    Q_OBJECT
public:
    explicit InspectorPanel(const Pipeline& pipeline, QWidget* parent = nullptr);
    void inspect(const FrameOutput* output, QPoint pixel);
    void clearPixel();

private:
    std::map<std::string, std::string, std::less<>> m_layer_names;
};

/// Whether `shape` covers image pixel (x, y) by the painter's conventions (within half a pixel
/// of a line, inside a point's square, on a circle or rect outline, inside a filled one).
bool shapeCovers(const DebugShape& shape, int x, int y);

} // namespace fieldsight::ui
