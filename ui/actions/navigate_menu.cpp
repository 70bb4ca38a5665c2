// Navigate: stepping and playing (the navigator's actions), the bookmarks and the evaluation's
// disagreements.
#include "ui/actions/menus.h"
#include "ui/panels/bookmarks_panel.h"
#include "ui/panels/evaluation_panel.h"
#include "ui/stream_navigator/stream_navigator.h"

#include <QMenuBar>

namespace fieldsight::ui {

void addNavigateMenu(QMenuBar& bar, const MenuParts& parts)
{
    BookmarksPanel& marks = parts.bookmarks;
    QMenu* nav = bar.addMenu(QObject::tr("&Navigate"));
    nav->addActions(parts.navigator.navigationActions());
    nav->addSeparator();
    addMenuItem(nav, QObject::tr("Bookmark this frame…"), QKeySequence(Qt::CTRL | Qt::Key_B),
                &marks, &BookmarksPanel::markCurrentFrame);
    addMenuItem(nav, QObject::tr("Next bookmark"), QKeySequence(Qt::Key_BracketRight), &marks,
                [&marks] { marks.jump(1); });
    addMenuItem(nav, QObject::tr("Previous bookmark"), QKeySequence(Qt::Key_BracketLeft), &marks,
                [&marks] { marks.jump(-1); });
    nav->addSeparator();
    EvaluationPanel& evaluation = parts.evaluation;
    QAction* next = addMenuItem(nav, QObject::tr("Next disagreement"), QKeySequence(Qt::Key_F6),
                                &evaluation, [&evaluation] { evaluation.jump(1); });
    next->setObjectName(QStringLiteral("navigate.next_disagreement"));
    next->setToolTip(QObject::tr("The next frame where detections and truth disagree, its "
                                 "culprits drawn emphasised (the Evaluation panel lists them)"));
    QAction* previous =
        addMenuItem(nav, QObject::tr("Previous disagreement"), QKeySequence(Qt::SHIFT | Qt::Key_F6),
                    &evaluation, [&evaluation] { evaluation.jump(-1); });
    previous->setObjectName(QStringLiteral("navigate.previous_disagreement"));
}

} // namespace fieldsight::ui
