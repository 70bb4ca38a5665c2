// The window's menus, one function per menu, each in its own file: what the window offers and
// its shortcuts, wired to the session, the tools and the window's commands.
#pragma once

#include <QKeySequence>
#include <QMenu>
#include <QObject>

#include <functional>

class QMenuBar;

namespace fieldsight::ui {

class AnnotationsFile;
class BookmarksPanel;
class CalibrateActions;
class EditingSession;
class EvaluationPanel;
class FitActions;
class FrameRecorder;
class FrameView;
class LutPanel;
class SessionFiles;
class StreamNavigator;
class ToolManager;

/// What a menu or a menu's commands act on, the session's documents and the tools, and where they
/// report: the window's message bar and status line. Given this, they never reach into the
/// window's widgets. Copied freely: it holds references and the window's callbacks.
struct MenuTarget
{
    EditingSession& session;
    ToolManager& tools;
    QWidget* parent; ///< what its actions and dialogs belong to
    std::function<void(const QString& text, bool error)> message;
    std::function<void(const QString& text, int timeout_ms)> status;
    /// Hides the message bar; a problem that lasts the session (the settings could not be read)
    /// is shown again instead.
    std::function<void()> clear;
    /// The text the message bar shows, empty while it is hidden.
    std::function<QString()> shown;

    /// Shows `text` in the message bar (red for an error, blue for a note).
    void showMessage(const QString& text, bool error = true) const { message(text, error); }
    /// A note in the status line, for `timeout_ms`.
    void showStatus(const QString& text, int timeout_ms) const { status(text, timeout_ms); }
    void clearMessage() const { clear(); }
    QString shownMessage() const { return shown(); }
};

/// The window's parts the File, Edit, View, Navigate, Pipeline and Calibrate menus work with
/// besides the documents and the tools: built by the window, which the menus never include.
/// Every part lives as long as the window.
struct MenuParts
{
    FrameView& view;
    StreamNavigator& navigator;
    SessionFiles& files;
    AnnotationsFile& annotation_files;
    FrameRecorder& recorder;
    CalibrateActions& calibrate;
    FitActions& fit;
    LutPanel& lut_panel; ///< its colour classes (Edit) and table buttons (Calibrate)
    BookmarksPanel& bookmarks;
    EvaluationPanel& evaluation;
    QMenu& panels; ///< the docks' and toolbars' toggles (View > Panels)
};

void addFileMenu(QMenuBar& bar, const MenuTarget& target, const MenuParts& parts);
void addEditMenu(QMenuBar& bar, const MenuTarget& target, const MenuParts& parts);
void addViewMenu(QMenuBar& bar, const MenuTarget& target, const MenuParts& parts);
void addNavigateMenu(QMenuBar& bar, const MenuParts& parts);
/// What is set on the annotated object selected (concealed, keyframe, propagation).
void addObjectMenu(QMenuBar& bar, const MenuTarget& target);
void addPipelineMenu(QMenuBar& bar, const MenuTarget& target, const MenuParts& parts);
/// The automatic table (CalibrateActions), with its button in the LUT editor.
void addCalibrateMenu(QMenuBar& bar, const MenuParts& parts);
void addAnnotateMenu(QMenuBar& bar, const MenuTarget& target);
void addHelpMenu(QMenuBar& bar, const MenuTarget& target);
/// Help > Keyboard shortcuts' text: every key a user can press for an item of `bar`'s menus (not
/// Qt's platform keys, F14 for Undo), as an HTML table two pairs of columns wide.
QString shortcutsHtml(const QMenuBar& bar);

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
