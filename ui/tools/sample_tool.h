// Sample regions: drag a rectangle over the frame and it becomes a sample of the class, kept
// beside the stream to build the table from (again after the light changes). The frame's samples
// are drawn in their class's colour while the tool is active; a click inside one selects it, a
// drag moves it, Edit > Delete removes it (each an undoable edit of the samples document).
#pragma once

#include "ui/tools/tool.h"

namespace fieldsight::ui {

class SampleTool : public Tool
{
    Q_OBJECT
public:
    explicit SampleTool(ToolContext& context);
    ToolInfo info() const override;
    void press(const ToolEvent& event) override;
    void move(const ToolEvent& event) override;
    void release(const ToolEvent& event) override;
    void deactivate() override;
    ToolPreview preview(std::optional<QPoint> pixel) const override;
    ToolOutline outline() const override;
    bool deleteSelection() override;

    /// The selected sample's index in the samples document (none: no selection).
    std::optional<std::size_t> selected() const { return m_selected; }

private:
    /// The index of the topmost sample of the current frame containing `point`.
    std::optional<std::size_t> sampleAt(QPoint point) const;
    bool onCurrentFrame(std::size_t index) const;

    std::optional<QPoint> m_from; ///< a new rectangle's first corner, while dragging
    std::optional<QPoint> m_to;
    std::optional<std::size_t> m_selected;
    std::optional<QPoint> m_grab; ///< where a move started, while dragging the selection
    QPoint m_offset;              ///< how far the selection has moved so far
};

} // namespace fieldsight::ui
