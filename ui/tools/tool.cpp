#include "ui/tools/tool.h"

#include <QMouseEvent>

namespace fieldsight::ui {

ToolEvent ToolEvent::of(ToolSurface surface, const QMouseEvent& mouse, QPoint point)
{
    ToolEvent e;
    e.surface = surface;
    e.point = point;
    e.position = QPointF(point);
    e.button = mouse.button();
    e.buttons = mouse.buttons();
    e.modifiers = mouse.modifiers();
    e.double_click = mouse.type() == QEvent::MouseButtonDblClick;
    return e;
}

} // namespace fieldsight::ui
