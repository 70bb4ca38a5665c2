// A dock's content in a scroll area.
#include "ui/widgets/scroll_area.h"

#include <QScrollArea>

namespace fieldsight::ui {

QScrollArea* inScrollArea(QWidget* content)
{
    auto* area = new QScrollArea(content->parentWidget());
    area->setWidget(content);
    area->setWidgetResizable(true);
    area->setFrameShape(QFrame::NoFrame);
    return area;
}

} // namespace fieldsight::ui
