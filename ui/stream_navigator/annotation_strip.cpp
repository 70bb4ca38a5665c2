#include "ui/stream_navigator/annotation_strip.h"

#include "ui/document/annotations_document.h"
#include "ui/document/stream_document.h"

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
const QColor kDone(60, 200, 90);
const QColor kAnnotated(110, 130, 160);
} // namespace

AnnotationStrip::AnnotationStrip(const AnnotationsDocument& annotations,
                                 const StreamDocument& stream, const QSlider& slider,
                                 QWidget* parent)
    : QWidget(parent), m_doc(annotations), m_stream(stream), m_slider(slider)
{
    setObjectName(QStringLiteral("annotation_strip"));
    setFixedHeight(6); // a row of the window's background apart from the strip above
    setMouseTracking(true);
    connect(&stream, &StreamDocument::streamChanged, this, [this] {
        readNames();
        refresh();
    });
    connect(&annotations, &AnnotationsDocument::changed, this, &AnnotationStrip::refresh);
    connect(&stream, &StreamDocument::currentIndexChanged, this, [this] {
        update();
        emit statusChanged(currentStatus());
    });
    readNames();
    refresh();
}

void AnnotationStrip::readNames()
{
    m_names.clear();
    const std::size_t n = m_stream.live() ? 0 : m_stream.frameCount();
    m_names.reserve(n);
    for (std::size_t i = 0; i < n; ++i)
        m_names.push_back(m_stream.frameName(i).toStdString());
}

void AnnotationStrip::refresh()
{
    // The annotations are adopted just before their stream: until it follows they are another
    // stream's, matched against the old names.
    m_states = frameStates(m_names, m_doc.annotations());
    m_done = std::size_t(std::count(m_states.done.begin(), m_states.done.end(), true));
    update();
    emit statusChanged(currentStatus());
}

QString AnnotationStrip::frameStatus(std::size_t index) const
{
    if (index >= m_names.size())
        return {};
    const FrameAnnotation* frame = m_doc.frame(m_names[index]);
    if (!frame)
        return tr("not annotated");
    QString text = frame->done ? tr("done") : tr("not done");
    text += tr(" · %n object(s)", nullptr, int(objectCount(*frame)));
    QStringList reviewed;
    for (const PerceptKind* kind : m_doc.kinds())
        if (frame->reviewed.count(kind->truth_key))
            reviewed << QString::fromUtf8(kind->title.data(), qsizetype(kind->title.size()));
    if (!reviewed.isEmpty())
        text += tr(" · reviewed: %1").arg(reviewed.join(QStringLiteral(", ")));
    return text;
}

QString AnnotationStrip::currentStatus() const
{
    if (m_names.empty())
        return {};
    return tr("Annotation: %1 (%2 of %3 frames done)")
        .arg(frameStatus(m_stream.currentIndex()))
        .arg(qulonglong(m_done))
        .arg(qulonglong(m_names.size()));
}

std::pair<double, double> AnnotationStrip::span() const
{
    const int handle = m_slider.style()->pixelMetric(QStyle::PM_SliderLength, nullptr, &m_slider);
    const double left = m_slider.x() - x() + handle / 2.0;
    return {left, std::max(1.0, double(m_slider.width() - handle))};
}

long long AnnotationStrip::frameAt(int px) const
{
    const std::size_t n = m_names.size();
    if (n == 0)
        return -1;
    const auto [left, length] = span();
    const double t = std::clamp((px - left) / length, 0.0, 1.0);
    return std::llround(t * double(n - 1));
}

void AnnotationStrip::paintEvent(QPaintEvent*)
{
    QPainter p(this);
    p.fillRect(rect().adjusted(0, 1, 0, 0), QColor(38, 38, 38));
    const std::size_t n = m_names.size();
    if (n == 0)
        return;
    const auto [left, length] = span();
    const int x0 = std::max(0, int(std::floor(left)));
    const int x1 = std::min(width() - 1, int(std::ceil(left + length)));
    const double per_px = double(n - 1) / length;
    for (int px = x0; px <= x1; ++px) {
        // The frames placed within this column, or the nearest one when frames are wider.
        long long first = std::max(0LL, (long long)std::ceil((px - 0.5 - left) * per_px));
        long long last =
            std::min((long long)n - 1, (long long)std::ceil((px + 0.5 - left) * per_px) - 1);
        if (first > last)
            first = last = frameAt(px);
        bool done = false;
        bool annotated = false;
        for (long long f = first; f <= last; ++f) {
            done |= m_states.done[std::size_t(f)];
            annotated |= m_states.annotated[std::size_t(f)];
        }
        if (done || annotated)
            p.fillRect(px, 1, 1, height() - 1, done ? kDone : kAnnotated);
    }
    const double cx =
        left + length * double(m_stream.currentIndex()) / double(std::max<std::size_t>(1, n - 1));
    p.fillRect(QRectF(cx - 0.5, 1, 1.5, height() - 1), QColor(255, 255, 255, 200));
}

void AnnotationStrip::mousePressEvent(QMouseEvent* event)
{
    const long long frame = frameAt(int(event->position().x()));
    if (event->button() == Qt::LeftButton && frame >= 0)
        emit frameClicked(std::size_t(frame));
}

bool AnnotationStrip::event(QEvent* event)
{
    if (event->type() != QEvent::ToolTip)
        return QWidget::event(event);
    auto* help = static_cast<QHelpEvent*>(event);
    const long long frame = frameAt(help->pos().x());
    if (frame < 0) {
        QToolTip::hideText();
        return true;
    }
    QToolTip::showText(help->globalPos(),
                       tr("Frame %1: %2\n(green: done; blue-grey: annotated, not done)")
                           .arg(frame)
                           .arg(frameStatus(std::size_t(frame))),
                       this);
    return true;
}

} // namespace fieldsight::ui
