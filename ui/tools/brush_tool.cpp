#include "ui/tools/brush_tool.h"

#include "ui/adapters/image_adapter.h"
#include "ui/document/editing_session.h"
#include "ui/tools/lut_tool_settings.h"

namespace fieldsight::ui {

ToolInfo BrushTool::info() const
{
    return {QStringLiteral("brush"), tr("Brush"),
            tr("Paint over the image: every colour under the brush becomes the class"),
            QKeySequence(Qt::Key_B)};
}

ToolInfo EraseTool::info() const
{
    return {QStringLiteral("erase"), tr("Erase"),
            tr("Paint over the image: every colour under the brush becomes unclassified"),
            QKeySequence(Qt::Key_E)};
}

Colour BrushTool::target() const
{
    return erases() ? Colour::Unclassified : LutEditTool::target();
}

PlannedEdit BrushTool::stroke(const std::vector<cv::Point>& pixels) const
{
    const bool erase = erases();
    const Tolerance t = erase ? Tolerance{} : m_context.settings.tolerance();
    return PlannedEdit{erase ? tr("Erase stroke")
                             : tr("Brush stroke → %1").arg(colourLabel(target())),
                       changesFor(cellsOfPixels(*frame(), pixels, t), erase)};
}

std::optional<PlannedEdit> BrushTool::plan(QPoint pixel) const
{
    const cv::Mat* image = frameAt(pixel);
    if (!image)
        return std::nullopt;
    return stroke(
        brushPixels({pixel.x(), pixel.y()}, m_context.settings.brushRadius(), image->size()));
}

void BrushTool::pressImage(QPoint pixel)
{
    m_stroke = m_context.session.lut().newMerge();
    m_last.reset();
    dragImage(pixel);
}

void BrushTool::dragImage(QPoint pixel)
{
    const cv::Mat* image = frame();
    if (!m_stroke || m_stroke_surface != ToolSurface::Image || !image)
        return;
    // Every pixel the brush passed over since the last event (a fast drag skips pixels).
    const cv::Point to(pixel.x(), pixel.y());
    const auto pixels = strokePixels(m_last.value_or(to), to, m_context.settings.brushRadius(),
                                     image->size(), !m_last);
    m_last = to;
    apply(stroke(pixels), m_stroke);
    emit previewChanged();
}

} // namespace fieldsight::ui
