#include "ui/tools/lut_edit_tool.h"

#include "ui/adapters/image_adapter.h"
#include "ui/document/editing_session.h"
#include "ui/tools/lut_tool_settings.h"
#include "visioncore/services/lut_compare.h"

#include <QStringList>

#include <opencv2/core.hpp>

namespace fieldsight::ui {

ToolPreview previewOfChanges(std::vector<CellChange> changes, const cv::Mat* frame)
{
    ToolPreview p;
    if (changes.empty())
        return p;
    p.cells.reserve(changes.size());
    for (const CellChange& c : changes)
        p.cells.push_back(c.cell);
    if (frame)
        p.pixels = pixelsIn(*frame, CellMask::of(changes));
    const auto taken = cellsTakenByClass(changes);
    QStringList overlap;
    for (int c = 1; c < kColourCount; ++c)
        if (taken[std::size_t(c)] > 0)
            overlap
                << QStringLiteral("%1 %2").arg(taken[std::size_t(c)]).arg(colourLabel(Colour(c)));
    p.text = Tool::tr("Here: %1 cells would change, %2 px of this frame")
                 .arg(qsizetype(changes.size()))
                 .arg(p.pixels.empty() ? 0 : cv::countNonZero(p.pixels));
    p.text +=
        overlap.isEmpty()
            ? Tool::tr("; none taken from another class")
            : Tool::tr("; taken from another class: %1").arg(overlap.join(QStringLiteral(", ")));
    p.changes = std::move(changes);
    return p;
}

const cv::Mat* LutEditTool::frame() const
{
    const auto& out = m_context.session.stream().current();
    if (!out || out->frame.ycbcr.empty())
        return nullptr;
    return &out->frame.ycbcr;
}

const cv::Mat* LutEditTool::frameAt(QPoint pixel) const
{
    const cv::Mat* image = frame();
    return image && pixel.x() >= 0 && pixel.y() >= 0 && pixel.x() < image->cols &&
                   pixel.y() < image->rows
               ? image
               : nullptr;
}

Colour LutEditTool::target() const
{
    return m_context.settings.colour();
}

std::vector<CellChange> LutEditTool::changesFor(const std::vector<std::uint32_t>& cells,
                                                bool erase) const
{
    const LutToolSettings& s = m_context.settings;
    return changesTo(m_context.session.lut().table(), cells,
                     erase ? Colour::Unclassified : target(), !erase && s.keepOthers(),
                     !erase && s.softClasses());
}

void LutEditTool::apply(PlannedEdit plan, int stroke)
{
    for (const CellChange& c : plan.changes)
        m_stroke_cells.push_back(c.cell);
    m_context.session.lut().edit(plan.text, std::move(plan.changes), stroke);
}

void LutEditTool::press(const ToolEvent& event)
{
    if (event.surface == ToolSurface::UvPlane) {
        if (event.button != Qt::LeftButton)
            return;
        m_stroke = m_context.session.lut().newMerge();
        m_stroke_surface = ToolSurface::UvPlane;
        m_stroke_cells.clear();
        m_last.reset();
        dabUv(event);
        return;
    }
    if (event.button == Qt::RightButton) {
        pickColourAt(m_context, event.point);
        return;
    }
    if (event.button == Qt::LeftButton) {
        m_stroke_surface = ToolSurface::Image;
        m_stroke_cells.clear();
        pressImage(event.point);
    }
}

void LutEditTool::move(const ToolEvent& event)
{
    if (!(event.buttons & Qt::LeftButton))
        return;
    if (event.surface == ToolSurface::UvPlane) {
        if (m_stroke && m_stroke_surface == ToolSurface::UvPlane)
            dabUv(event);
        return;
    }
    dragImage(event.point);
}

void LutEditTool::release(const ToolEvent&)
{
    deactivate();
}

void LutEditTool::deactivate()
{
    const bool was = m_stroke != 0;
    m_stroke = 0;
    m_last.reset();
    if (was)
        emit previewChanged();
}

void LutEditTool::pressImage(QPoint pixel)
{
    if (auto p = plan(pixel))
        apply(std::move(*p));
}

void pickColourAt(ToolContext& context, QPoint pixel)
{
    const auto& out = context.session.stream().current();
    if (!out || out->classes.empty() || pixel.x() < 0 || pixel.y() < 0 ||
        pixel.x() >= out->classes.cols || pixel.y() >= out->classes.rows)
        return;
    context.settings.setColour(Colour(out->classes.at<std::uint8_t>(pixel.y(), pixel.x())));
}

void LutEditTool::dabUv(const ToolEvent& event)
{
    const cv::Point cell(event.point.x(), event.point.y());
    const auto cells = strokeUvCells(m_last.value_or(cell), cell, m_context.settings.brushRadius(),
                                     event.y_lo, event.y_hi, !m_last);
    m_last = cell;
    const Colour colour = target();
    const bool erase = colour == Colour::Unclassified;
    apply({erase ? tr("UV erase, Y cells %1-%2").arg(event.y_lo).arg(event.y_hi)
                 : tr("UV paint → %1, Y cells %2-%3")
                       .arg(colourLabel(colour))
                       .arg(event.y_lo)
                       .arg(event.y_hi),
           changesFor(cells, erase)},
          m_stroke);
}

ToolPreview LutEditTool::preview(std::optional<QPoint> pixel) const
{
    if (m_stroke) { // mid-stroke: what the stroke has changed so far
        ToolPreview p;
        p.cells = m_stroke_cells;
        if (const cv::Mat* image = frame(); image && !p.cells.empty())
            p.pixels = pixelsIn(*image, CellMask::of(p.cells));
        p.text = tr("Stroke: %1 cells changed").arg(qsizetype(p.cells.size()));
        return p;
    }
    if (!pixel || !m_context.settings.previewOn())
        return {};
    std::optional<PlannedEdit> p = plan(*pixel);
    return p ? previewOfChanges(std::move(p->changes), frame()) : ToolPreview{};
}

ToolOutline LutEditTool::outline() const
{
    ToolOutline outline;
    outline.brush_radius = brushOutline() ? m_context.settings.brushRadius() : -1;
    return outline;
}

} // namespace fieldsight::ui
