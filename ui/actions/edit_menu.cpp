// Edit: undo and redo of the active document, the colour class and the tools.
#include "ui/actions/menus.h"
#include "ui/document/editing_session.h"
#include "ui/panels/lut_panel.h"
#include "ui/tools/tool_manager.h"

#include <QMenuBar>
#include <QUndoGroup>
#include <QUndoStack>

namespace fieldsight::ui {

void addEditMenu(QMenuBar& bar, const MenuTarget& w, const MenuParts& parts)
{
    QMenu* edit = bar.addMenu(QObject::tr("&Edit"));
    QUndoGroup& group = w.session.undoGroup();
    // Undo takes back the active document's steps, then those of the document edited before it
    // (the text names that document), so Ctrl+Z walks back through every edit left.
    EditingSession& session = w.session;
    auto* undo = new QAction(QObject::tr("Undo"), w.parent);
    undo->setObjectName(QStringLiteral("edit.undo"));
    undo->setShortcuts(QKeySequence::Undo);
    const auto follow = [&session, undo] {
        QUndoStack* target = session.undoTarget();
        undo->setEnabled(target != nullptr);
        if (!target)
            undo->setText(QObject::tr("Undo"));
        else if (target == session.undoGroup().activeStack())
            undo->setText(QObject::tr("Undo %1").arg(target->undoText()));
        else
            undo->setText(QObject::tr("Undo %1 (%2)")
                              .arg(target->undoText(), session.undoDocumentName(target)));
    };
    QObject::connect(&session, &EditingSession::undoTargetChanged, undo, follow);
    QObject::connect(&group, &QUndoGroup::activeStackChanged, undo, follow);
    QObject::connect(undo, &QAction::triggered, &session, &EditingSession::undo);
    follow();
    QAction* redo = group.createRedoAction(w.parent, QObject::tr("Redo"));
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
    QObject::connect(remove, &QAction::triggered, w.parent,
                     [manager = &w.tools] { manager->deleteSelection(); });
    QMenu* classes = edit->addMenu(QObject::tr("Colour class"));
    classes->addActions(parts.lut_panel.colourActions());
    QMenu* tools = edit->addMenu(QObject::tr("Tool"));
    tools->addActions(w.tools.actions());
}

} // namespace fieldsight::ui
