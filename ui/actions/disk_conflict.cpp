#include "ui/actions/disk_conflict.h"

#include "ui/actions/menus.h"
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

std::optional<bool> settleDiskChange(const MenuTarget& target, bool changed, const QString& what,
                                     const QString& path, bool& overwrite,
                                     const std::function<bool()>& reload,
                                     const std::function<bool()>& save_as)
{
    overwrite = false;
    if (!changed)
        return std::nullopt;
    switch (askAboutDiskChange(target.parent, what, path)) {
    case DiskChoice::Reload:
        return reload();
    case DiskChoice::SaveAs:
        return save_as();
    case DiskChoice::Overwrite:
        overwrite = true;
        return std::nullopt;
    case DiskChoice::Cancel:
        break;
    }
    target.showMessage(QCoreApplication::translate("DiskConflict",
                                                   "Not saved: %1 changed on disk (your edits of "
                                                   "%2 are kept)")
                           .arg(path, what));
    return false;
}

} // namespace fieldsight::ui
