// File > Export annotations as COCO: the open stream's annotations written as COCO JSON for other
// tools (visioncore/io/coco_export.h), by the same rules as `fieldsight annotations export`.
#pragma once

#include <QString>

namespace fieldsight::ui {

struct MenuTarget;

/// Writes the open stream's annotations as the annotations document holds them (unsaved edits
/// too) as COCO JSON to `path`, in the orientation the window shows the stream; atomically and
/// never over an input (the stream's files, the annotations file). The outcome is shown in the
/// window; false when nothing was written.
bool exportAnnotationsAsCoco(const MenuTarget& target, const QString& path);

} // namespace fieldsight::ui
