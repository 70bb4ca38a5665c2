// The strip along the timeline that shows the last LUT edit's effect on every frame: a bar for
// the pixels that changed class, green and red ticks where detections appeared or vanished, grey
// where the background scan has not got to yet. Click a frame to go there.
#pragma once

#include "ui/scans/edit_effect_scan.h"

#include <QWidget>

class QSlider;

namespace fieldsight::ui {

class EffectStrip : public QWidget
{
    Q_OBJECT
public:
    /// Frames are placed where `slider` puts them, so the strip lines up with it.
    EffectStrip(const EditEffectScan& scan, const QSlider& slider, QWidget* parent = nullptr);

    /// The frame under x (widget px), or -1 when there are no frames.
    long long frameAt(int x) const;
    /// One line about the last edit's effect (for the status bar and tests).
    QString summary() const;

signals:
    void frameClicked(std::size_t frame);

protected:
    void paintEvent(QPaintEvent* event) override;
    void mousePressEvent(QMouseEvent* event) override;
    bool event(QEvent* event) override; ///< tooltips for the frame under the mouse

private:
    /// Left end and length (px) of the span the slider's handle centre moves over.
    std::pair<double, double> span() const;

    const EditEffectScan& m_scan;
    const QSlider& m_slider;
};

} // namespace fieldsight::ui
