#include "ui/tools/wand_tool.h"

#include "ui/adapters/image_adapter.h"
#include "ui/tools/lut_tool_settings.h"

namespace fieldsight::ui {

ToolInfo WandTool::info() const
{
    return {QStringLiteral("wand"), tr("Wand"),
            tr("Click a pixel: the connected pixels of similar colour become the class"),
            QKeySequence(Qt::Key_W)};
}

std::optional<PlannedEdit> WandTool::plan(QPoint pixel) const
{
    const cv::Mat* image = frameAt(pixel);
    if (!image)
        return std::nullopt;
    const std::vector<cv::Point> pixels =
        wandPixels(*image, {pixel.x(), pixel.y()}, m_context.settings.tolerance());
    return PlannedEdit{tr("Wand at (%1, %2): %3 px → %4")
                           .arg(pixel.x())
                           .arg(pixel.y())
                           .arg(qsizetype(pixels.size()))
                           .arg(colourLabel(target())),
                       changesFor(cellsOfPixels(*image, pixels), false)};
}

} // namespace fieldsight::ui
