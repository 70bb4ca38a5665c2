// The current frame's pixels in chosen colour-table cells, lit in the frame view and found again
// for every frame shown: the UV plane's selection (cyan) and the LUT compare dialog's chosen row
// (orange).
#pragma once

#include "visioncore/services/lut_compare.h"

#include <QObject>

#include <cstdint>
#include <optional>
#include <vector>

namespace fieldsight::ui {

class FrameView;
class StreamDocument;

class CellHighlights : public QObject
{
    Q_OBJECT
public:
    /// Lights `stream`'s frames in `view`; `selection` is the UV plane's, read at each refresh.
    CellHighlights(FrameView& view, StreamDocument& stream,
                   const std::optional<CellMask>& selection, QObject* parent = nullptr);

    /// The compare dialog's chosen row (empty: none).
    void setCompareCells(const std::vector<std::uint32_t>& cells);
    /// Finds the pixels again (a new frame, or another selection).
    void refresh();

private:
    FrameView& m_view;
    StreamDocument& m_stream;
    const std::optional<CellMask>& m_selection;
    std::optional<CellMask> m_compare;
};

} // namespace fieldsight::ui
