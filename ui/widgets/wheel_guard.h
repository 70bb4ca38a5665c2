// Spin boxes, sliders and combo boxes in a scrolled panel take the mouse wheel only when they
// have focus (a click or Tab gives it); otherwise the wheel scrolls the panel, so scrolling past
// a parameter never changes it.
#pragma once

class QWidget;

namespace fieldsight::ui {

/// Guards every spin box, slider and combo box inside `root` (call after they are made).
void guardWheel(QWidget* root);

} // namespace fieldsight::ui
