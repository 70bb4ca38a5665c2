#include "ui/frame_view/cell_highlights.h"

#include "ui/adapters/image_adapter.h"
#include "ui/document/stream_document.h"
#include "ui/frame_view/frame_view.h"

namespace fieldsight::ui {

CellHighlights::CellHighlights(FrameView& view, StreamDocument& stream,
                               const std::optional<CellMask>& selection, QObject* parent)
    : QObject(parent), m_view(view), m_stream(stream), m_selection(selection)
{
    connect(&stream, &StreamDocument::frameReady, this, &CellHighlights::refresh);
}

void CellHighlights::setCompareCells(const std::vector<std::uint32_t>& cells)
{
    m_compare.reset();
    if (!cells.empty())
        m_compare = CellMask::of(cells);
    refresh();
}

void CellHighlights::refresh()
{
    const auto& out = m_stream.current();
    const auto light = [&](const QString& id, const std::optional<CellMask>& cells, QColor colour) {
        m_view.setHighlight(id, cells && out && !out->frame.ycbcr.empty()
                                    ? maskToQImage(pixelsIn(out->frame.ycbcr, *cells), colour)
                                    : QImage());
    };
    light(QStringLiteral("uv_selection"), m_selection, QColor(0, 230, 255, 170));
    light(QStringLiteral("compare"), m_compare, QColor(255, 140, 0, 170));
}

} // namespace fieldsight::ui
