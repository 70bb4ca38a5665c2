// Click with tolerance: the clicked pixel's colour, grown by the tolerance box, becomes the class.
#pragma once

#include "ui/tools/lut_edit_tool.h"

namespace fieldsight::ui {

class ClickTool : public LutEditTool
{
    Q_OBJECT
public:
    using LutEditTool::LutEditTool;
    ToolInfo info() const override;
    std::optional<PlannedEdit> plan(QPoint pixel) const override;
};

} // namespace fieldsight::ui
