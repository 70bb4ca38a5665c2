// The one question the window asks before a save would write over a file another window or a
// program changed since the window read or saved it: reload it, save under another name, write
// over it, or cancel (through the Dialogs seam).
#pragma once

#include <QString>

#include <functional>
#include <optional>

class QWidget;

namespace fieldsight::ui {

struct MenuTarget;

enum class DiskChoice { Reload, SaveAs, Overwrite, Cancel };

/// Asks what to do with the unsaved `what` ("the annotations", "the LUT") whose file `path`
/// changed on disk; Save As is the default (it keeps both).
DiskChoice askAboutDiskChange(QWidget* parent, const QString& what, const QString& path);

/// The start of every save of a file another writer may change: nothing when the file is as
/// read (`changed` false) or the user chose Overwrite (`overwrite` then set), and the save goes
/// on writing. Otherwise the save ends here with the result returned: `reload()`'s, `save_as()`'s,
/// or false for Cancel (said in `target`'s message bar, the edits kept).
std::optional<bool> settleDiskChange(const MenuTarget& target, bool changed, const QString& what,
                                     const QString& path, bool& overwrite,
                                     const std::function<bool()>& reload,
                                     const std::function<bool()>& save_as);

} // namespace fieldsight::ui
