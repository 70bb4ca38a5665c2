// The light strip: a bar per frame for how far the light has moved, and its numbers.
#include "ui/stream_navigator/light_strip.h"

#include "ui/stream_navigator/frame_marks_strip.h"

#include <QHelpEvent>
#include <QMouseEvent>
#include <QPainter>
#include <QSlider>
#include <QToolTip>

#include <algorithm>
#include <cmath>

namespace fieldsight::ui {

namespace {

/// The distance the strip's full height stands for: ln gain 0.35, about 40%.
constexpr double kFullScale = 0.35;

std::size_t frameTotal(const LightScan& scan)
{
    if (const auto& track = scan.track())
        return track->frames.size();
    return scan.frameCount();
}

} // namespace

LightStrip::LightStrip(const LightScan& scan, const QSlider& slider, QWidget* parent)
    : QWidget(parent), m_scan(scan), m_slider(slider)
{
    setObjectName(QStringLiteral("light_strip"));
    setFixedHeight(12);
    setMouseTracking(true);
    connect(&scan, &LightScan::progress, this, &LightStrip::follow);
    connect(&scan, &LightScan::trackChanged, this, &LightStrip::follow);
    connect(&slider, &QSlider::valueChanged, this, qOverload<>(&QWidget::update));
    follow();
}

void LightStrip::follow()
{
    setVisible(m_scan.enabled() && !m_scan.stream().isEmpty());
    update();
}

std::vector<double> LightStrip::distances() const
{
    std::vector<double> d;
    if (const auto& track = m_scan.track())
        for (const LightState& s : track->frames)
            d.push_back(s.distance());
    return d;
}

QString LightStrip::frameText(std::size_t index) const
{
    const auto& track = m_scan.track();
    if (!track || index >= track->frames.size())
        return {};
    const LightState& s = track->frames[index];
    QString text = tr("Frame %1: the light is R ×%2, G ×%3, B ×%4 of the table's (moved %5%)")
                       .arg(index + 1)
                       .arg(s.gain[0], 0, 'f', 3)
                       .arg(s.gain[1], 0, 'f', 3)
                       .arg(s.gain[2], 0, 'f', 3)
                       .arg(100 * (std::exp(s.distance()) - 1), 0, 'f', 1);
    if (s.verdict != LightState::Verdict::Followed)
        text += tr("\nthis frame: %1 (%2 carpet and white samples)")
                    .arg(QString::fromUtf8(verdictName(s.verdict)))
                    .arg(s.samples);
    if (s.held_from)
        text += tr("\nthe carpet and the white read G ×%1; the table reads the posts, ball and "
                   "robots as well nearer its own light, so this frame read ×%2")
                    .arg(*s.held_from, 0, 'f', 3)
                    .arg(s.estimate[1], 0, 'f', 3);
    if (s.view_level != 0)
        text +=
            tr("\nG ×%1 of it came faster than a hall's light changes: the view's, as the table "
               "reads\nthe posts, ball and robots as well without it. The frame is read at G "
               "×%2 (moved %3%)")
                .arg(std::exp(s.view_level), 0, 'f', 3)
                .arg(s.readGain()[1], 0, 'f', 3)
                .arg(100 * (std::exp(s.readDistance()) - 1), 0, 'f', 1);
    return text;
}

long long LightStrip::frameAt(int x) const
{
    const std::size_t frames = frameTotal(m_scan);
    if (frames == 0)
        return -1;
    const auto [left, length] = sliderSpan(m_slider, *this);
    const double t = std::clamp((x - left) / length, 0.0, 1.0);
    return std::llround(t * double(frames - 1));
}

void LightStrip::paintEvent(QPaintEvent*)
{
    QPainter p(this);
    p.fillRect(rect(), QColor(38, 38, 38));
    const std::size_t frames = frameTotal(m_scan);
    if (frames == 0)
        return;
    // Not a structured binding: clang 14 cannot capture one in the lambda below.
    const std::pair<double, double> span = sliderSpan(m_slider, *this);
    const double left = span.first;
    const double step = span.second / double(std::max<std::size_t>(1, frames - 1));
    const auto xOf = [&](std::size_t i) { return left + step * double(i); };
    const double w = std::max(1.0, step);
    const auto& track = m_scan.track();
    if (!track) { // scanning: how far it has got
        p.fillRect(QRectF(left, height() - 2,
                          span.second * double(m_scan.framesDone()) / double(frames), 2),
                   QColor(110, 110, 110));
        return;
    }
    for (std::size_t i = 0; i < track->frames.size(); ++i) {
        const LightState& s = track->frames[i];
        // The table's move for the frame, and above it, paler, the view's part of the light's.
        const double h = std::min(1.0, s.distance() / kFullScale) * height();
        const double read = std::min(1.0, s.readDistance() / kFullScale) * height();
        if (h > read)
            p.fillRect(QRectF(xOf(i) - w / 2, height() - h, w, h - read), QColor(120, 100, 60));
        p.fillRect(QRectF(xOf(i) - w / 2, height() - read, w, read), QColor(250, 190, 60));
        if (s.verdict != LightState::Verdict::Followed &&
            s.verdict != LightState::Verdict::Reference)
            p.fillRect(QRectF(xOf(i) - w / 2, 0, w, 3), QColor(230, 60, 50));
        else if (s.held_from || s.view_level != 0) // the table held the level back: violet,
            p.fillRect(QRectF(xOf(i) - w / 2, 0, w, 3), QColor(185, 130, 245)); // apart from the
                                                                                // cyan marks
    }
    const long long current = m_slider.value();
    if (current >= 0 && std::size_t(current) < frames)
        p.fillRect(QRectF(xOf(std::size_t(current)) - 0.5, 0, 1.5, height()),
                   QColor(255, 255, 255, 200));
}

void LightStrip::mousePressEvent(QMouseEvent* event)
{
    const long long frame = frameAt(int(event->position().x()));
    if (event->button() == Qt::LeftButton && frame >= 0)
        emit frameClicked(std::size_t(frame));
}

bool LightStrip::event(QEvent* event)
{
    if (event->type() != QEvent::ToolTip)
        return QWidget::event(event);
    auto* help = static_cast<QHelpEvent*>(event);
    const long long frame = frameAt(help->pos().x());
    QString text = frame >= 0 ? frameText(std::size_t(frame)) : QString();
    if (text.isEmpty() && m_scan.running())
        text = tr("Following the light: %1 of %2 frames")
                   .arg(m_scan.framesDone())
                   .arg(m_scan.frameCount());
    if (!text.isEmpty())
        QToolTip::showText(help->globalPos(), text, this);
    else
        QToolTip::hideText();
    return true;
}

} // namespace fieldsight::ui
