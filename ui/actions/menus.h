// The window's menus, one function per menu, each in its own file: what the window offers and
// its shortcuts, wired to the session, the tools and the window's commands.
#pragma once

#include <QKeySequence>
#include <QMenu>
#include <QObject>

#include <functional>

class QMenuBar;

namespace fieldsight::ui {

class EditingSession;
class MainWindow;
class ToolManager;

/// What a menu acts on, the session's documents and the tools, and where it reports: the window's
/// message bar and status line. A menu given this never reaches into the window's widgets.
struct MenuTarget
{
    EditingSession& session;
    ToolManager& tools;
    QWidget* parent; ///< what its actions and dialogs belong to
    std::function<void(const QString& text, bool error)> message;
    std::function<void(const QString& text, int timeout_ms)> status;

    /// Shows `text` in the message bar (red for an error, blue for a note).
    void showMessage(const QString& text, bool error = true) const { message(text, error); }
    /// A note in the status line, for `timeout_ms`.
    void showStatus(const QString& text, int timeout_ms) const { status(text, timeout_ms); }
};

void addFileMenu(MainWindow& window);
void addEditMenu(MainWindow& window);
void addViewMenu(MainWindow& window);
void addNavigateMenu(MainWindow& window);
/// What is set on the annotated object selected (concealed, keyframe, propagation).
void addObjectMenu(QMenuBar& bar, const MenuTarget& target);
void addPipelineMenu(MainWindow& window);
/// The automatic table (CalibrateActions), with its button in the LUT editor.
void addCalibrateMenu(MainWindow& window);
void addAnnotateMenu(QMenuBar& bar, const MenuTarget& target);
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
