// Help: every shortcut the menus hold, and about.
#include "ui/actions/menus.h"
#include "ui/dialogs/dialogs.h"

#include <QCoreApplication>
#include <QMenuBar>

namespace fieldsight::ui {

namespace {

/// A key a user can press on an ordinary keyboard: not F13-F35 nor the media and launch keys
/// (Qt adds F14 to Undo, the Undo key of some platforms).
bool pressable(const QKeySequence& sequence)
{
    for (int i = 0; i < sequence.count(); ++i) {
        const Qt::Key key = sequence[i].key();
        if ((key >= Qt::Key_F13 && key <= Qt::Key_F35) || key >= Qt::Key_Back)
            return false;
    }
    return !sequence.isEmpty();
}

} // namespace

QString shortcutsHtml(const QMenuBar& bar)
{
    QStringList rows;
    for (QMenu* menu : bar.findChildren<QMenu*>()) {
        // An item of a submenu is named with it ("Detections to annotations: All kinds").
        const QString within = qobject_cast<QMenu*>(menu->parentWidget())
                                   ? menu->title().remove('&') + QStringLiteral(": ")
                                   : QString();
        for (QAction* a : menu->actions()) {
            QStringList keys;
            for (const QKeySequence& k : a->shortcuts())
                if (pressable(k))
                    keys << k.toString(QKeySequence::NativeText);
            if (!keys.isEmpty())
                rows << QStringLiteral("<td><b>%1</b></td><td>%2</td>")
                            .arg(keys.join(QStringLiteral(", ")).toHtmlEscaped(),
                                 (within + a->text().remove('&')).toHtmlEscaped());
        }
    }
    // Two columns of keys side by side, so the list is half as tall.
    const qsizetype half = (rows.size() + 1) / 2;
    QString text = QStringLiteral("<table cellspacing=\"0\" cellpadding=\"1\">");
    for (qsizetype r = 0; r < half; ++r) {
        text += QStringLiteral("<tr>") + rows[r];
        if (r + half < rows.size())
            text += QStringLiteral("<td width=\"24\"></td>") + rows[r + half];
        text += QStringLiteral("</tr>");
    }
    return text + QStringLiteral("</table>");
}

void addHelpMenu(QMenuBar& bar, const MenuTarget& w)
{
    QMenu* help = bar.addMenu(QObject::tr("&Help"));
    QWidget* parent = w.parent;
    QAction* keys =
        help->addAction(QObject::tr("Keyboard shortcuts"), parent, [parent, menus = &bar] {
            Dialogs::current().document(parent, QObject::tr("Keyboard shortcuts"),
                                        shortcutsHtml(*menus));
        });
    keys->setObjectName(QStringLiteral("help.shortcuts"));
    help->addAction(QObject::tr("About Fieldsight"), parent, [parent] {
        Dialogs::current().information(
            parent, QObject::tr("About Fieldsight"),
            QObject::tr("Fieldsight %1: a colour-segmentation robot vision debugger.")
                .arg(QCoreApplication::applicationVersion()));
    });
}

} // namespace fieldsight::ui
