// `fieldsight gui`: the one command that opens a window, so it lives in the executable and the
// command library (commands/) stays headless.
#pragma once

#include "commands/cli.h"

namespace fieldsight::cli {

/// The GUI: makes the QApplication from `argc` and `argv` (which hold the program name, then
/// "gui" or nothing, then the GUI's arguments), opens the main window and runs it.
int guiCommand(int& argc, char** argv, const Context& ctx);

} // namespace fieldsight::cli
