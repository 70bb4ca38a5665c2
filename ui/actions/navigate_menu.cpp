// Navigate: stepping and playing (the navigator's actions) and the bookmarks.
#include "ui/actions/menus.h"
#include "ui/main_window.h"
#include "ui/panels/bookmarks_panel.h"
#include "ui/stream_navigator/stream_navigator.h"

#include <QMenuBar>

namespace fieldsight::ui {

void addNavigateMenu(MainWindow& w)
{
    BookmarksPanel& marks = w.bookmarksPanel();
    QMenu* nav = w.menuBar()->addMenu(QObject::tr("&Navigate"));
    nav->addActions(w.navigator().navigationActions());
    nav->addSeparator();
    addMenuItem(nav, QObject::tr("Bookmark this frame…"), QKeySequence(Qt::CTRL | Qt::Key_B),
                &marks, &BookmarksPanel::markCurrentFrame);
    addMenuItem(nav, QObject::tr("Next bookmark"), QKeySequence(Qt::Key_BracketRight), &marks,
                [&marks] { marks.jump(1); });
    addMenuItem(nav, QObject::tr("Previous bookmark"), QKeySequence(Qt::Key_BracketLeft), &marks,
                [&marks] { marks.jump(-1); });
}

} // namespace fieldsight::ui
