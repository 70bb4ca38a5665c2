// A strip under the timeline plotting how far the light has moved from the table's at every
// frame ("Follow the light"): a bar per frame, taller the further; frames the tracker ignored
// (a flash, a view full of one colour) ticked red, frames whose level the table held back (its
// posts and ball read as well nearer its own light) ticked violet; hover for the numbers, click to
// go there.
#pragma once

#include "ui/scans/light_scan.h"

#include <QWidget>

#include <vector>

class QSlider;

namespace fieldsight::ui {

class LightStrip : public QWidget
{
    Q_OBJECT
public:
    /// Frames are placed where `slider` puts them, so the strip lines up with it.
    LightStrip(const LightScan& scan, const QSlider& slider, QWidget* parent = nullptr);

    /// The plotted value of every frame followed: LightState::distance() (0.1: about 10%).
    std::vector<double> distances() const;
    /// What the tooltip says of frame `index` (empty: nothing known of it).
    QString frameText(std::size_t index) const;

signals:
    void frameClicked(std::size_t frame);

protected:
    void paintEvent(QPaintEvent* event) override;
    void mousePressEvent(QMouseEvent* event) override;
    bool event(QEvent* event) override;

private:
    void follow(); ///< shown while the scan is on
    long long frameAt(int x) const;

    const LightScan& m_scan;
    const QSlider& m_slider;
};

} // namespace fieldsight::ui
