// A thin strip along the timeline that marks chosen frames (the evaluation's disagreements): a
// tick per marked frame where the slider puts it, a note for each under the mouse; click a tick
// to go there.
#pragma once

#include <QColor>
#include <QString>
#include <QWidget>

#include <map>
#include <utility>

class QSlider;

namespace fieldsight::ui {

/// Left end and length (px, in `strip`'s coordinates) of the span the slider's handle centre
/// moves over, for a strip placed beside the slider in the same layout.
std::pair<double, double> sliderSpan(const QSlider& slider, const QWidget& strip);

class FrameMarksStrip : public QWidget
{
    Q_OBJECT
public:
    /// Frames are placed where `slider` puts them, so the strip lines up with it.
    FrameMarksStrip(const QSlider& slider, QColor colour, QWidget* parent = nullptr);

    /// Marks `marks` (frame index: its note) of a stream of `frames` frames; hidden while none.
    void setMarks(std::map<std::size_t, QString> marks, std::size_t frames);
    const std::map<std::size_t, QString>& marks() const { return m_marks; }
    /// Widget x of frame `frame`'s tick.
    double xOf(std::size_t frame) const;
    /// The marked frame nearest x within a few px, else the frame under x (-1: no frames).
    long long frameAt(int x) const;

signals:
    void frameClicked(std::size_t frame);

protected:
    void paintEvent(QPaintEvent* event) override;
    void mousePressEvent(QMouseEvent* event) override;
    bool event(QEvent* event) override; ///< the note of the frame under the mouse

private:
    const QSlider& m_slider;
    QColor m_colour;
    std::map<std::size_t, QString> m_marks;
    std::size_t m_frames = 0;
};

} // namespace fieldsight::ui
