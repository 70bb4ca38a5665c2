// A dock's content in a scroll area: what does not fit the dock scrolls instead of being cut off.
#pragma once

class QScrollArea;
class QWidget;

namespace fieldsight::ui {

/// `content` in a new frameless scroll area (its parent: content's parent) that resizes it to its
/// width and scrolls what is taller (or wider than its minimum) than the area.
QScrollArea* inScrollArea(QWidget* content);

} // namespace fieldsight::ui
