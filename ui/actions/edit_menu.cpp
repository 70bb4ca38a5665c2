// Edit: undo and redo of the active document, the colour class and the tools.
#include "ui/actions/menus.h"
#include "ui/main_window.h"
#include "ui/panels/lut_panel.h"

#include <QMenuBar>
#include <QUndoGroup>

namespace fieldsight::ui {

void addEditMenu(MainWindow& w)
{
    QMenu* edit = w.menuBar()->addMenu(QObject::tr("&Edit"));
    QUndoGroup& group = w.session().undoGroup();
    QAction* undo = group.createUndoAction(&w, QObject::tr("Undo"));
    undo->setObjectName(QStringLiteral("edit.undo"));
    undo->setShortcuts(QKeySequence::Undo);
    QAction* redo = group.createRedoAction(&w, QObject::tr("Redo"));
    redo->setObjectName(QStringLiteral("edit.redo"));
    // Both Ctrl+Shift+Z and Ctrl+Y, whatever the platform's own binding is.
    QList<QKeySequence> redo_keys = QKeySequence::keyBindings(QKeySequence::Redo);
    for (const QKeySequence& key :
         {QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_Z), QKeySequence(Qt::CTRL | Qt::Key_Y)})
        if (!redo_keys.contains(key))
            redo_keys << key;
    redo->setShortcuts(redo_keys);
    edit->addAction(undo);
    edit->addAction(redo);
    edit->addSeparator();
    QAction* remove = edit->addAction(QObject::tr("Delete selected"));
    remove->setObjectName(QStringLiteral("edit.delete"));
    remove->setShortcut(QKeySequence::Delete);
    QObject::connect(remove, &QAction::triggered, &w, [&w] { w.tools().deleteSelection(); });
    QMenu* classes = edit->addMenu(QObject::tr("Colour class"));
    classes->addActions(w.lutPanel().colourActions());
    QMenu* tools = edit->addMenu(QObject::tr("Tool"));
    tools->addActions(w.tools().actions());
}

} // namespace fieldsight::ui
