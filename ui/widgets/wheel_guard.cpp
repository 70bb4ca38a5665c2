#include "ui/widgets/wheel_guard.h"

#include <QAbstractScrollArea>
#include <QAbstractSlider>
#include <QCoreApplication>
#include <QAbstractSpinBox>
#include <QComboBox>
#include <QEvent>
#include <QKeyEvent>
#include <QKeySequence>
#include <QWidget>

namespace fieldsight::ui {

namespace {

bool isUndoKey(const QKeyEvent& key)
{
    const QKeySequence pressed(key.keyCombination());
    if (key.matches(QKeySequence::Undo) || key.matches(QKeySequence::Redo))
        return true;
    return pressed == QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_Z) ||
           pressed == QKeySequence(Qt::CTRL | Qt::Key_Y);
}

class WheelGuard final : public QObject
{
public:
    using QObject::QObject;

protected:
    bool eventFilter(QObject* watched, QEvent* event) override
    {
        if (event->type() == QEvent::ShortcutOverride) {
            // Not taken by the box's own text undo: the window's undo shortcut fires instead.
            if (isUndoKey(*static_cast<QKeyEvent*>(event))) {
                event->ignore();
                return true;
            }
            return false;
        }
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
