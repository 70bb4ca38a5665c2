#include "ui/stream_navigator/effect_strip.h"

#include "ui/adapters/image_adapter.h"
#include "ui/stream_navigator/frame_marks_strip.h"

#include <QHelpEvent>
#include <QLocale>
#include <QMouseEvent>
#include <QPainter>
#include <QSlider>
#include <QStyle>
#include <QToolTip>

#include <algorithm>
#include <cmath>

namespace fieldsight::ui {

namespace {

QString signedCount(int appeared, int vanished, const QString& what)
{
    QStringList parts;
    if (appeared)
        parts << QStringLiteral("+%1").arg(appeared);
    if (vanished)
        parts << QStringLiteral("−%1").arg(vanished);
    return parts.isEmpty() ? QString() : parts.join(QLatin1Char(' ')) + QLatin1Char(' ') + what;
}

QString deltaText(const DetectionDelta& d)
{
    QStringList parts;
    for (const KindDelta& k : d.kinds)
        if (const QString part =
                signedCount(k.appeared, k.vanished, perceptNoun(*k.kind).toLower());
            !part.isEmpty())
            parts << part;
    return parts.join(QStringLiteral(", "));
}

} // namespace

EffectStrip::EffectStrip(const EditEffectScan& scan, const QSlider& slider, QWidget* parent)
    : QWidget(parent), m_scan(scan), m_slider(slider)
{
    setObjectName(QStringLiteral("effect_strip"));
    setFixedHeight(22);
    setMouseTracking(true);
    setToolTip(tr("The last LUT edit's effect on every frame"));
    connect(&scan, &EditEffectScan::updated, this, qOverload<>(&QWidget::update));
}

std::pair<double, double> EffectStrip::span() const
{
    return sliderSpan(m_slider, *this);
}

long long EffectStrip::frameAt(int px) const
{
    const std::size_t n = m_scan.effects().size();
    if (n == 0)
        return -1;
    const auto [left, length] = span();
    const double t = std::clamp((px - left) / length, 0.0, 1.0);
    return std::llround(t * double(n - 1));
}

QString EffectStrip::summary() const
{
    const auto& effects = m_scan.effects();
    if (!m_scan.error().isEmpty())
        return tr("Edit effect: %1").arg(m_scan.error());
    if (effects.empty())
        return m_scan.running() ? tr("Edit effect: opening the stream…") : QString();
    std::size_t frames_changed = 0;
    std::uint64_t pixels = 0;
    std::uint64_t unclassified = 0;
    std::uint64_t all = 0;
    DetectionDelta total;
    for (const FrameEffect& e : effects) {
        frames_changed += e.changed_pixels > 0;
        pixels += e.changed_pixels;
        unclassified += e.unclassified;
        all += e.pixels;
        total += e.delta;
    }
    const QLocale locale;
    // Until every frame is in, the sums are partial: say how far the scan is and never call a
    // count final ("no detection changed" before the frames that change are scanned).
    const bool scanning = m_scan.framesDone() < effects.size();
    const QString frames =
        scanning ? tr("scanning %1 of %2 frames")
                       .arg(locale.toString(qulonglong(m_scan.framesDone())),
                            locale.toString(qulonglong(effects.size())))
                 : tr("over %1 frames").arg(locale.toString(qulonglong(effects.size())));
    const QString detections = deltaText(total);
    QString detections_text = detections.isEmpty() ? tr("no detection changed") : detections;
    if (scanning)
        detections_text += tr(" so far");
    QString text;
    const bool light_switch =
        m_scan.showsEdit() && m_scan.showsLightSwitch() && m_scan.changedCells() == 0;
    if (light_switch) {
        text = (m_scan.showsFollowing() ? tr("Follow the light switched on, %1: %2")
                                        : tr("Follow the light switched off, %1: %2"))
                   .arg(frames, detections_text);
    } else if (m_scan.showsEdit() && m_scan.showsSettingsChange() && m_scan.changedCells() == 0) {
        text = tr("Last parameter change, %1: %2").arg(frames, detections_text);
    } else if (m_scan.showsEdit()) {
        text = tr("Last edit (%1 cells), %2: %3 pixels changed class in %4 frames; %5")
                   .arg(locale.toString(qulonglong(m_scan.changedCells())), frames,
                        locale.toString(qulonglong(pixels)),
                        locale.toString(qulonglong(frames_changed)), detections_text);
    } else if (scanning) {
        text = tr("Scanning the stream with this LUT, %1").arg(frames);
    } else {
        text = tr("Stream scanned with this LUT");
    }
    if (all > 0)
        text += tr("; %1% of the pixels scanned unclassified")
                    .arg(100.0 * double(unclassified) / double(all), 0, 'f', 1);
    if (const std::size_t bad = m_scan.unreadableFrames()) {
        const std::size_t first = m_scan.firstUnreadable();
        const QString reason = m_scan.unreadableReason(first);
        text += bad == 1 ? tr("; unreadable frame %1: %2").arg(first).arg(reason)
                         : tr("; %1 unreadable frames, the first %2: %3")
                               .arg(locale.toString(qulonglong(bad)))
                               .arg(first)
                               .arg(reason);
    }
    // Whether the counts are of the table as it is or following the light, as the view is
    // (said first, where the status bar does not cut it).
    if (m_scan.showsFollowing() && !light_switch)
        text = tr("Following the light: %1").arg(text);
    if (!scanning && m_scan.lastScanMs() >= 0)
        text += tr(" (%1 s)").arg(m_scan.lastScanMs() / 1000.0, 0, 'f', 2);
    return text;
}

void EffectStrip::paintEvent(QPaintEvent*)
{
    QPainter p(this);
    p.fillRect(rect(), QColor(38, 38, 38));
    const auto& effects = m_scan.effects();
    if (effects.empty())
        return;
    const auto [left, length] = span();
    const int x0 = std::max(0, int(std::floor(left)));
    const int x1 = std::min(width() - 1, int(std::ceil(left + length)));
    std::uint32_t most = 1;
    for (const FrameEffect& e : effects)
        most = std::max(most, e.changed_pixels);
    const double scale = std::log1p(double(most));
    const int tick = 4; // rows of the appeared and vanished ticks at the top
    const int bar_space = height() - 2 * tick - 1;
    const std::size_t n = effects.size();
    for (int px = x0; px <= x1; ++px) {
        // The frames placed within this column, or the nearest one when frames are wider.
        const double per_px = double(n - 1) / length;
        long long first = (long long)std::ceil((px - 0.5 - left) * per_px);
        long long last = (long long)std::ceil((px + 0.5 - left) * per_px) - 1;
        first = std::max(0LL, first);
        last = std::min((long long)n - 1, last);
        if (first > last)
            first = last = frameAt(px);
        bool pending = false;
        bool unreadable = false;
        std::uint32_t changed = 0;
        int appeared = 0;
        int vanished = 0;
        for (long long f = first; f <= last; ++f) {
            const FrameEffect& e = effects[std::size_t(f)];
            pending |= !e.done;
            unreadable |= e.unreadable;
            changed = std::max(changed, e.changed_pixels);
            appeared += e.delta.appeared();
            vanished += e.delta.vanished();
        }
        if (pending)
            p.fillRect(px, 0, 1, height(), QColor(70, 70, 70));
        if (unreadable)
            p.fillRect(px, 2 * tick + 1, 1, bar_space, QColor(150, 35, 60));
        if (changed > 0) {
            const int h = std::max(1, int(std::lround(bar_space * std::log1p(changed) / scale)));
            p.fillRect(px, height() - h, 1, h, QColor(255, 170, 0));
        }
        if (appeared)
            p.fillRect(px, 0, 1, tick, QColor(60, 220, 90));
        if (vanished)
            p.fillRect(px, tick, 1, tick, QColor(240, 60, 60));
    }
    // The current frame, where the slider's handle is.
    const long long current = m_slider.value();
    if (current >= 0 && std::size_t(current) < n) {
        const double cx = left + length * double(current) / double(std::max<std::size_t>(1, n - 1));
        p.fillRect(QRectF(cx - 0.5, 0, 1.5, height()), QColor(255, 255, 255, 200));
    }
}

void EffectStrip::mousePressEvent(QMouseEvent* event)
{
    const long long frame = frameAt(int(event->position().x()));
    if (event->button() == Qt::LeftButton && frame >= 0)
        emit frameClicked(std::size_t(frame));
}

bool EffectStrip::event(QEvent* event)
{
    if (event->type() != QEvent::ToolTip)
        return QWidget::event(event);
    auto* help = static_cast<QHelpEvent*>(event);
    const long long frame = frameAt(help->pos().x());
    QString text = summary();
    if (frame >= 0) {
        const FrameEffect& e = m_scan.effects()[std::size_t(frame)];
        // 0-based, as the frame counter and Go to frame count.
        QString line = tr("Frame %1: ").arg(frame);
        if (!e.done)
            line += tr("not scanned yet");
        else if (e.unreadable)
            line += tr("unreadable (%1)").arg(m_scan.unreadableReason(std::size_t(frame)));
        else {
            line += tr("%1 pixels changed class").arg(e.changed_pixels);
            if (const QString d = deltaText(e.delta); !d.isEmpty())
                line += QStringLiteral("; ") + d;
        }
        text = line + QLatin1Char('\n') + text;
    }
    // Rich text, so Qt wraps a long summary instead of running it off the screen.
    QToolTip::showText(help->globalPos(),
                       QStringLiteral("<p>") +
                           text.toHtmlEscaped().replace(QLatin1Char('\n'), QStringLiteral("<br>")) +
                           QStringLiteral("</p>"),
                       this);
    return true;
}

} // namespace fieldsight::ui
