#include "ui/actions/disk_conflict.h"

#include "ui/dialogs/dialogs.h"

#include <QCoreApplication>

namespace fieldsight::ui {

DiskChoice askAboutDiskChange(QWidget* parent, const QString& what, const QString& path)
{
    const auto tr = [](const char* text) {
        return QCoreApplication::translate("DiskConflict", text);
    };
    const int answer = Dialogs::current().choice(
        parent, tr("Changed on disk"),
        tr("%1 was changed on disk since this window read or saved it (another window or a "
           "program wrote it). Saving now would drop that change.\n\nReload: drop your edits of "
           "%2 and take the file's (Edit > Undo brings your edits back). Save As: keep both. "
           "Overwrite: replace the file with yours.")
            .arg(path, what),
        {tr("Reload"), tr("Save As…"), tr("Overwrite")}, 1);
    switch (answer) {
    case 0:
        return DiskChoice::Reload;
    case 1:
        return DiskChoice::SaveAs;
    case 2:
        return DiskChoice::Overwrite;
    default:
        return DiskChoice::Cancel;
    }
}

} // namespace fieldsight::ui
