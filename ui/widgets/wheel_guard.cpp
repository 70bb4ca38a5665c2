#include "ui/widgets/wheel_guard.h"

#include <QAbstractScrollArea>
#include <QAbstractSlider>
#include <QCoreApplication>
#include <QAbstractSpinBox>
#include <QComboBox>
#include <QEvent>
#include <QWidget>

namespace fieldsight::ui {

namespace {

class WheelGuard final : public QObject
{
public:
    using QObject::QObject;

protected:
    bool eventFilter(QObject* watched, QEvent* event) override
    {
        if (event->type() != QEvent::Wheel)
            return false;
        auto* widget = qobject_cast<QWidget*>(watched);
        if (!widget || widget->hasFocus())
            return false;
        // Given to the scroll area around the panel, which scrolls.
        for (QWidget* p = widget->parentWidget(); p; p = p->parentWidget())
            if (auto* area = qobject_cast<QAbstractScrollArea*>(p)) {
                QCoreApplication::sendEvent(area->viewport(), event);
                break;
            }
        return true;
    }
};

} // namespace

void guardWheel(QWidget* root)
{
    auto* guard = new WheelGuard(root);
    const auto guardEach = [guard](const auto& widgets) {
        for (QWidget* w : widgets) {
            w->setFocusPolicy(Qt::StrongFocus); // the wheel does not give focus
            w->installEventFilter(guard);
        }
    };
    guardEach(root->findChildren<QAbstractSpinBox*>());
    guardEach(root->findChildren<QAbstractSlider*>());
    guardEach(root->findChildren<QComboBox*>());
}

} // namespace fieldsight::ui
