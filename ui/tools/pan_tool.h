// Pan: the left button moves the view (and selects cells in the UV plane); nothing is edited.
#pragma once

#include "ui/tools/tool.h"

namespace fieldsight::ui {

class PanTool : public Tool
{
    Q_OBJECT
public:
    using Tool::Tool;
    ToolInfo info() const override
    {
        return {QStringLiteral("pan"), tr("Pan"),
                tr("Drag to move the view; in the UV plane, drag to select cells"),
                QKeySequence(Qt::Key_P)};
    }
    bool pans() const override { return true; }
    QCursor cursor() const override { return Qt::OpenHandCursor; }
};

} // namespace fieldsight::ui
