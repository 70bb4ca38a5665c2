// Sample region: drag a rectangle over the frame; it becomes a sample of the class, kept beside
// the stream to build the table from (again after the light changes).
#pragma once

#include "ui/tools/tool.h"

namespace fieldsight::ui {

class SampleTool : public Tool
{
    Q_OBJECT
public:
    using Tool::Tool;
    ToolInfo info() const override;
    void press(const ToolEvent& event) override;
    void move(const ToolEvent& event) override;
    void release(const ToolEvent& event) override;
    void deactivate() override;
    ToolPreview preview(std::optional<QPoint> pixel) const override;

private:
    std::optional<QPoint> m_from;
    std::optional<QPoint> m_to;
};

} // namespace fieldsight::ui
