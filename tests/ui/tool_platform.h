// The tools for looking (gui_screenshot, lut_trial, the GUI benchmarks) run on a machine without a
// display as they do on a desktop: with no display set, they use Qt's offscreen platform.
#pragma once

#include <QtGlobal>

namespace fieldsight::tools {

/// Call before the QApplication is made: picks the offscreen platform when neither
/// QT_QPA_PLATFORM nor a display (X11 or Wayland) is set, so the tool does not abort.
inline void useOffscreenWithoutDisplay()
{
    if (qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM") && qEnvironmentVariableIsEmpty("DISPLAY") &&
        qEnvironmentVariableIsEmpty("WAYLAND_DISPLAY"))
        qputenv("QT_QPA_PLATFORM", "offscreen");
}

} // namespace fieldsight::tools
