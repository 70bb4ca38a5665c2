// Spin boxes, sliders and combo boxes in a scrolled panel take the mouse wheel only when they
// have focus (a click or Tab gives it); otherwise the wheel scrolls the panel, so scrolling past
// a parameter never changes it. A spin box with focus leaves the undo keys (Ctrl+Z, Ctrl+Shift+Z,
// Ctrl+Y) to the window's Edit > Undo and Redo: its value is a document's, undone there.
#pragma once

class QWidget;

namespace fieldsight::ui {

/// Guards every spin box, slider and combo box inside `root` (call after they are made).
void guardWheel(QWidget* root);

} // namespace fieldsight::ui
