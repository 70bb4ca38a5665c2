// The message and offer bars float over the top of the frame view instead of taking room above
// it: a bar appearing or going never moves or resizes the view, so the frame stays still under
// the mouse while the user works.
#pragma once

#include <QWidget>

class QVBoxLayout;

namespace fieldsight::ui {

class BarOverlay : public QWidget
{
    Q_OBJECT
public:
    /// Floats over the top edge of `over` (a sibling in the same parent), as wide as it.
    explicit BarOverlay(QWidget* over);
    /// Adds `bar` below those added before; the overlay shows while any of its bars does.
    void addBar(QWidget* bar);

protected:
    bool eventFilter(QObject* watched, QEvent* event) override;
    bool event(QEvent* event) override;

private:
    /// Over the top of the view, as high as the shown bars; hidden (not taking the mouse) when
    /// none is shown.
    void place();

    QWidget* m_over = nullptr;
    QVBoxLayout* m_column = nullptr;
};

} // namespace fieldsight::ui
