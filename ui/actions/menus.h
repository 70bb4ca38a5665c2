// The window's menus, one function per menu, each in its own file: what the window offers and
// its shortcuts, wired to the session, the tools and the window's commands.
#pragma once

#include <QKeySequence>
#include <QMenu>
#include <QObject>

namespace fieldsight::ui {

class MainWindow;

void addFileMenu(MainWindow& window);
void addEditMenu(MainWindow& window);
void addViewMenu(MainWindow& window);
void addNavigateMenu(MainWindow& window);
/// What is set on the annotated object selected (concealed, keyframe, propagation).
void addObjectMenu(MainWindow& window);
void addPipelineMenu(MainWindow& window);
/// The automatic table (CalibrateCommands), with its button in the LUT editor.
void addCalibrateMenu(MainWindow& window);
void addAnnotateMenu(MainWindow& window);
void addHelpMenu(MainWindow& window);
/// Help > Keyboard shortcuts' text: every key a user can press for a menu item (not Qt's
/// platform keys, F14 for Undo), as an HTML table two pairs of columns wide.
QString shortcutsHtml(const MainWindow& window);

/// A menu item with a shortcut, calling `fn` on `receiver`.
template <class Receiver, class Fn>
QAction* addMenuItem(QMenu* menu, const QString& text, const QKeySequence& key,
                     const Receiver* receiver, Fn fn)
{
    QAction* action = menu->addAction(text);
    action->setShortcut(key);
    QObject::connect(action, &QAction::triggered, receiver, fn);
    return action;
}

} // namespace fieldsight::ui
