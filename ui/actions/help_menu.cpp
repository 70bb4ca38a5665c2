// Help: every shortcut the menus hold, and about.
#include "ui/actions/menus.h"
#include "ui/dialogs/dialogs.h"
#include "ui/main_window.h"

#include <QCoreApplication>
#include <QMenuBar>

namespace fieldsight::ui {

void addHelpMenu(MainWindow& w)
{
    QMenu* help = w.menuBar()->addMenu(QObject::tr("&Help"));
    help->addAction(QObject::tr("Keyboard shortcuts"), &w, [&w] {
        // A table: the keys in one column, what they do in the other.
        QString text = QStringLiteral("<table cellspacing=\"2\">");
        for (QMenu* menu : w.menuBar()->findChildren<QMenu*>())
            for (QAction* a : menu->actions())
                if (!a->shortcut().isEmpty()) {
                    QStringList keys;
                    for (const QKeySequence& k : a->shortcuts())
                        keys << k.toString(QKeySequence::NativeText);
                    text += QStringLiteral("<tr><td><b>%1</b></td><td>&nbsp;&nbsp;%2</td></tr>")
                                .arg(keys.join(QStringLiteral(", ")).toHtmlEscaped(),
                                     a->text().remove('&').toHtmlEscaped());
                }
        text += QStringLiteral("</table>");
        Dialogs::current().information(&w, QObject::tr("Keyboard shortcuts"), text);
    });
    help->addAction(QObject::tr("About Fieldsight"), &w, [&w] {
        Dialogs::current().information(
            &w, QObject::tr("About Fieldsight"),
            QObject::tr("Fieldsight %1: a colour-segmentation robot vision debugger.")
                .arg(QCoreApplication::applicationVersion()));
    });
}

} // namespace fieldsight::ui
