#include "ui/widgets/bar_overlay.h"

#include <QEvent>
#include <QVBoxLayout>

#include <algorithm>

namespace fieldsight::ui {

BarOverlay::BarOverlay(QWidget* over) : QWidget(over->parentWidget()), m_over(over)
{
    setObjectName(QStringLiteral("bar_overlay"));
    m_column = new QVBoxLayout(this);
    m_column->setContentsMargins(0, 0, 0, 0);
    m_column->setSpacing(0);
    m_over->installEventFilter(this);
    hide();
}

void BarOverlay::addBar(QWidget* bar)
{
    m_column->addWidget(bar);
    bar->installEventFilter(this);
    place();
}

bool BarOverlay::eventFilter(QObject* watched, QEvent* event)
{
    switch (event->type()) {
    case QEvent::Move:
    case QEvent::Resize:
        if (watched == m_over)
            place();
        break;
    case QEvent::ShowToParent:
    case QEvent::HideToParent:
        if (watched != m_over)
            place();
        break;
    default:
        break;
    }
    return false;
}

bool BarOverlay::event(QEvent* event)
{
    if (event->type() == QEvent::LayoutRequest)
        place(); // a bar's text changed its height
    return QWidget::event(event);
}

void BarOverlay::place()
{
    // The shown bars' heights at the view's width (a wrapped question is taller when narrow).
    const int width = m_over->width();
    int height = 0;
    for (int i = 0; i < m_column->count(); ++i) {
        QWidget* bar = m_column->itemAt(i)->widget();
        if (!bar || bar->isHidden())
            continue;
        height += bar->hasHeightForWidth() ? bar->heightForWidth(width) : bar->sizeHint().height();
    }
    if (height == 0) {
        hide();
        return;
    }
    setGeometry(m_over->x(), m_over->y(), width, std::min(height, m_over->height()));
    show();
    raise();
}

} // namespace fieldsight::ui
