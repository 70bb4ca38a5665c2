#include "ui/tools/click_tool.h"

#include "ui/adapters/image_adapter.h"
#include "ui/document/editing_session.h"
#include "ui/tools/lut_tool_settings.h"

namespace fieldsight::ui {

ToolInfo ClickTool::info() const
{
    return {QStringLiteral("click"), tr("Click"),
            tr("Click a pixel: its colour, grown by the tolerance box, becomes the class"),
            QKeySequence(Qt::Key_C)};
}

std::optional<PlannedEdit> ClickTool::plan(QPoint pixel) const
{
    const cv::Mat* image = frameAt(pixel);
    if (!image)
        return std::nullopt;
    const cv::Vec3b c = image->at<cv::Vec3b>(pixel.y(), pixel.x());
    const Tolerance t = m_context.settings.tolerance();
    return PlannedEdit{tr("Click (%1, %2, %3) ± (%4, %5, %6) → %7")
                           .arg(c[0])
                           .arg(c[1])
                           .arg(c[2])
                           .arg(t.y)
                           .arg(t.cb)
                           .arg(t.cr)
                           .arg(colourLabel(target())),
                       changesFor(cellsInBox(c[0], c[1], c[2], t), false)};
}

} // namespace fieldsight::ui
