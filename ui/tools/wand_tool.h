// Magic wand: the pixels connected to the clicked one whose colour is within the tolerance
// become the class.
#pragma once

#include "ui/tools/lut_edit_tool.h"

namespace fieldsight::ui {

class WandTool : public LutEditTool
{
    Q_OBJECT
public:
    using LutEditTool::LutEditTool;
    ToolInfo info() const override;
    std::optional<PlannedEdit> plan(QPoint pixel) const override;
};

} // namespace fieldsight::ui
