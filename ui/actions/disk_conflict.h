// The one question the window asks before a save would write over a file another window or a
// program changed since the window read or saved it: reload it, save under another name, write
// over it, or cancel (through the Dialogs seam).
#pragma once

#include <QString>

class QWidget;

namespace fieldsight::ui {

enum class DiskChoice { Reload, SaveAs, Overwrite, Cancel };

/// Asks what to do with the unsaved `what` ("the annotations", "the LUT") whose file `path`
/// changed on disk; Save As is the default (it keeps both).
DiskChoice askAboutDiskChange(QWidget* parent, const QString& what, const QString& path);

} // namespace fieldsight::ui
