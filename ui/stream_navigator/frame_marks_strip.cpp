#include "ui/stream_navigator/frame_marks_strip.h"

#include <QHelpEvent>
#include <QMouseEvent>
#include <QPainter>
#include <QSlider>
#include <QStyle>
#include <QToolTip>

#include <algorithm>
#include <cmath>

namespace fieldsight::ui {

namespace {

constexpr double kAim = 4; ///< px either side of a tick that still hit it

} // namespace

std::pair<double, double> sliderSpan(const QSlider& slider, const QWidget& strip)
{
    const int handle = slider.style()->pixelMetric(QStyle::PM_SliderLength, nullptr, &slider);
    const double left = slider.x() - strip.x() + handle / 2.0;
    return {left, std::max(1.0, double(slider.width() - handle))};
}

FrameMarksStrip::FrameMarksStrip(const QSlider& slider, QColor colour, QWidget* parent)
    : QWidget(parent), m_slider(slider), m_colour(colour)
{
    setFixedHeight(7);
    setMouseTracking(true);
    hide();
}

void FrameMarksStrip::setMarks(std::map<std::size_t, QString> marks, std::size_t frames)
{
    m_marks = std::move(marks);
    m_frames = frames;
    setVisible(!m_marks.empty() && m_frames > 0);
    update();
}

double FrameMarksStrip::xOf(std::size_t frame) const
{
    const auto [left, length] = sliderSpan(m_slider, *this);
    return left + length * double(frame) / double(std::max<std::size_t>(1, m_frames - 1));
}

long long FrameMarksStrip::frameAt(int x) const
{
    if (m_frames == 0)
        return -1;
    long long best = -1;
    double nearest = kAim + 0.5;
    for (const auto& [frame, note] : m_marks)
        if (const double d = std::abs(xOf(frame) - x); d < nearest) {
            nearest = d;
            best = (long long)frame;
        }
    if (best >= 0)
        return best;
    const auto [left, length] = sliderSpan(m_slider, *this);
    const double t = std::clamp((x - left) / length, 0.0, 1.0);
    return std::llround(t * double(m_frames - 1));
}

void FrameMarksStrip::paintEvent(QPaintEvent*)
{
    QPainter p(this);
    p.fillRect(rect(), QColor(38, 38, 38));
    for (const auto& [frame, note] : m_marks)
        p.fillRect(QRectF(std::floor(xOf(frame)) - 0.5, 0, 2, height()), m_colour);
    const long long current = m_slider.value();
    if (current >= 0 && std::size_t(current) < m_frames)
        p.fillRect(QRectF(xOf(std::size_t(current)) - 0.5, 0, 1.5, height()),
                   QColor(255, 255, 255, 200));
}

void FrameMarksStrip::mousePressEvent(QMouseEvent* event)
{
    const long long frame = frameAt(int(event->position().x()));
    if (event->button() == Qt::LeftButton && frame >= 0)
        emit frameClicked(std::size_t(frame));
}

bool FrameMarksStrip::event(QEvent* event)
{
    if (event->type() != QEvent::ToolTip)
        return QWidget::event(event);
    auto* help = static_cast<QHelpEvent*>(event);
    const long long frame = frameAt(help->pos().x());
    const auto it = frame >= 0 ? m_marks.find(std::size_t(frame)) : m_marks.end();
    if (it != m_marks.end())
        QToolTip::showText(help->globalPos(), it->second, this);
    else
        QToolTip::hideText();
    return true;
}

} // namespace fieldsight::ui
