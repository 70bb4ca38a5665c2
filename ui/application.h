// Who the GUI is to the desktop: its names, its window icon and the id of its desktop entry
// (resources/), set once on the QApplication before the first window.
#pragma once

#include <QString>

namespace fieldsight::ui {

/// The reverse-DNS id naming the desktop entry, the icon and the AppStream metainfo.
QString applicationId();

/// Sets the organisation, application and display names (which settings and titles use), the
/// window icon and the desktop file name (Wayland matches the window to its entry by it).
void identifyApplication();

} // namespace fieldsight::ui
