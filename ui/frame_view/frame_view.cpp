// The frame view's zoom, pan and fit, and its painting (its mouse and keys: frame_view_input.cpp).
#include "ui/frame_view/frame_view.h"

#include "ui/adapters/overlay_painter.h"
#include "ui/frame_view/percept_labels.h"

#include <QElapsedTimer>
#include <QPainter>
#include <QCursor>
#include <QWheelEvent>

#include <algorithm>
#include <array>
#include <cmath>

namespace fieldsight::ui {

namespace {

/// The detections' opacity while an annotation tool is active: the truth being drawn stands out.
constexpr double kDimmedDetections = 0.35;

/// Zoom steps of the wheel and the zoom actions: whole multiples above 1 keep every image pixel
/// the same size on screen.
constexpr std::array<double, 14> kZoomSteps{0.25, 0.5, 1, 2, 3, 4, 6, 8, 12, 16, 24, 32, 48, 64};
constexpr int kPanelGap = 8; ///< widget px between the two panels of side by side
const QColor kBackground(45, 45, 48);

/// The zoom step after `zoom` towards larger (`direction` > 0) or smaller; `zoom` at the end.
double nextZoomStep(double zoom, int direction)
{
    if (direction > 0) {
        for (double step : kZoomSteps)
            if (step > zoom * 1.0001)
                return step;
    } else {
        for (auto it = kZoomSteps.rbegin(); it != kZoomSteps.rend(); ++it)
            if (*it < zoom * 0.9999)
                return *it;
    }
    return zoom;
}

} // namespace

FrameView::FrameView(QWidget* parent) : QWidget(parent)
{
    setMouseTracking(true);
    setAttribute(Qt::WA_OpaquePaintEvent);
    setFocusPolicy(Qt::StrongFocus);
    setMinimumSize(160, 120);
    setCursor(Qt::CrossCursor);
}

void FrameView::setOutput(std::shared_ptr<const FrameOutput> output)
{
    const QSize before = imageSize();
    m_output = std::move(output);
    if (imageSize() != before && m_fit)
        applyFit();
    refreshTruth();
    update();
}

void FrameView::setVisibleLayers(LayerSet layers)
{
    m_visible = std::move(layers);
    refreshTruth();
    update();
}

void FrameView::setAnnotations(const AnnotationsDocument& annotations)
{
    m_annotations = &annotations;
    connect(&annotations, &AnnotationsDocument::changed, this, [this](const QStringList& frames) {
        if (!m_output)
            return;
        const std::string shown = m_annotations->keyOf(m_output->frame.name);
        if (!frames.isEmpty() && !frames.contains(QString::fromStdString(shown)))
            return;
        refreshTruth();
        update();
    });
    refreshTruth();
    update();
}

void FrameView::refreshTruth()
{
    m_truth.clear();
    // A frame that could not be read or run shows no overlay at all.
    if (!m_annotations || !m_output || !m_output->error.isEmpty())
        return;
    if (const FrameAnnotation* frame = m_annotations->frame(m_output->frame.name))
        m_truth = truthDrawings(m_visible, frame->truth);
}

void FrameView::setMode(ViewMode mode)
{
    m_mode = mode;
    if (m_fit)
        applyFit();
    update();
    emit modeChanged(mode);
}

void FrameView::setLabelsShown(bool shown)
{
    m_labels = shown;
    update();
    emit labelsShownChanged(shown);
}

void FrameView::centreOn(QPointF point)
{
    setImageOrigin((QPointF(rect().center()) - point * m_zoom).toPoint());
}

bool FrameView::shows(const QRectF& r) const
{
    const QRectF shown(QPointF(m_origin) + r.topLeft() * m_zoom, r.size() * m_zoom);
    return QRectF(rect()).contains(shown);
}

QSize FrameView::imageSize() const
{
    if (!m_output || m_output->raw.isNull())
        return {};
    return m_output->raw.size();
}

int FrameView::panelX(int panel) const
{
    return m_origin.x() + panel * (int(std::lround(imageSize().width() * m_zoom)) + kPanelGap);
}

void FrameView::setZoom(double zoom, QPointF anchor)
{
    zoom = std::clamp(zoom, kZoomSteps.front(), kZoomSteps.back());
    // Keep the image point under the anchor in place, in whichever panel it is (the gap
    // between panels does not scale).
    const QSize image = imageSize();
    int panel = 0;
    if (panelCount() == 2 && !image.isEmpty() && anchor.x() >= panelX(1))
        panel = 1;
    const double old_panel_x = panelX(panel);
    const double u = (anchor.x() - old_panel_x) / m_zoom;
    const double v = (anchor.y() - m_origin.y()) / m_zoom;
    m_zoom = zoom;
    const int offset = panel * (int(std::lround(image.width() * m_zoom)) + kPanelGap);
    m_origin = QPoint(int(std::lround(anchor.x() - u * m_zoom)) - offset,
                      int(std::lround(anchor.y() - v * m_zoom)));
    m_fit = false;
    emit zoomChanged(m_zoom);
    update();
    followPointer();
}

void FrameView::zoomIn()
{
    setZoom(nextZoomStep(m_zoom, 1));
}

void FrameView::zoomOut()
{
    setZoom(nextZoomStep(m_zoom, -1));
}

void FrameView::fitToWindow()
{
    m_fit = true;
    applyFit();
    update();
    followPointer();
}

void FrameView::applyFit()
{
    const QSize image = imageSize();
    if (image.isEmpty() || width() <= 0 || height() <= 0)
        return;
    const double room_w = double(width() - (panelCount() - 1) * kPanelGap);
    double zoom =
        std::min(room_w / (image.width() * panelCount()), double(height()) / image.height());
    // Whole zoom factors when they lose little room (every image pixel the same size); a whole
    // factor that would leave more than a quarter of the room empty (1x of a 1.9x fit: a 320 x
    // 240 frame small in a large view) gives way to the fit itself.
    if (zoom >= 1 && std::floor(zoom) >= 0.75 * zoom)
        zoom = std::floor(zoom);
    m_zoom = std::clamp(zoom, kZoomSteps.front(), kZoomSteps.back());
    const int total_w =
        int(std::lround(image.width() * m_zoom)) * panelCount() + (panelCount() - 1) * kPanelGap;
    const int total_h = int(std::lround(image.height() * m_zoom));
    m_origin = QPoint((width() - total_w) / 2, (height() - total_h) / 2);
    emit zoomChanged(m_zoom);
}

void FrameView::setImageOrigin(QPoint origin)
{
    m_origin = origin;
    m_fit = false;
    update();
    followPointer();
}

void FrameView::followPointer()
{
    // The image moved under a still pointer (a zoom key, fit): the tool's preview and the
    // brush outline follow the pixel now under it, or go when there is none.
    const QPointF at = mapFromGlobal(QCursor::pos());
    const std::optional<QPoint> pixel =
        underMouse() && rect().contains(at.toPoint()) ? pixelAt(at) : std::nullopt;
    if (pixel != m_cursor_pixel) {
        m_cursor_pixel = pixel;
        update();
    }
    if (m_tools)
        m_tools->hover(pixel);
}

std::optional<QPointF> FrameView::imagePoint(QPointF pos) const
{
    const QSize image = imageSize();
    if (image.isEmpty())
        return std::nullopt;
    for (int panel = 0; panel < panelCount(); ++panel) {
        const double x = (pos.x() - panelX(panel)) / m_zoom;
        const double y = (pos.y() - m_origin.y()) / m_zoom;
        if (x >= 0 && y >= 0 && x < image.width() && y < image.height())
            return QPointF(x - 0.5, y - 0.5);
    }
    return std::nullopt;
}

std::optional<QPoint> FrameView::pixelAt(QPointF pos) const
{
    const std::optional<QPointF> p = imagePoint(pos);
    if (!p)
        return std::nullopt;
    return QPoint(int(std::floor(p->x() + 0.5)), int(std::floor(p->y() + 0.5)));
}

const PerceptItem* FrameView::itemAt(QPointF pos) const
{
    const std::optional<QPointF> p = imagePoint(pos);
    if (!p || !m_output)
        return nullptr;
    const double margin = std::max(1.0, 3 / m_zoom); // a few screen px to aim with
    const PerceptItem* best = nullptr;
    for (const PerceptItem& item : m_output->items) {
        if (!m_visible.count(item.layer))
            continue;
        const QRectF r = item.bounds.adjusted(-margin, -margin, margin, margin);
        if (r.contains(*p) &&
            (!best || r.width() * r.height() < best->bounds.width() * best->bounds.height()))
            best = &item; // the smallest one under the cursor: the one in front
    }
    return best;
}

void FrameView::setHighlight(const QString& id, const QImage& image)
{
    if (image.isNull()) {
        if (m_highlights.erase(id))
            update();
        return;
    }
    m_highlights[id] = image;
    update();
}

const QImage& FrameView::highlight(const QString& id) const
{
    static const QImage none;
    const auto it = m_highlights.find(id);
    return it == m_highlights.end() ? none : it->second;
}

void FrameView::paintEvent(QPaintEvent*)
{
    QElapsedTimer clock;
    clock.start();
    QPainter p(this);
    p.fillRect(rect(), kBackground);
    if (!m_output) {
        p.setPen(Qt::lightGray);
        p.drawText(rect(), Qt::AlignCenter,
                   tr("No stream open: File > Open stream, or drop a "
                      "folder, .strm or video file here"));
        return;
    }
    const QSize image = imageSize();
    if (!image.isEmpty()) {
        // The core's drawings, then the truth over them (layers.h's order, as a render's).
        std::vector<const DebugDrawing*> layers;
        for (const DebugDrawing& d : m_output->drawings)
            if (m_visible.count(d.layer))
                layers.push_back(&d);
        for (const DebugDrawing& d : m_truth)
            layers.push_back(&d);
        for (int panel = 0; panel < panelCount(); ++panel) {
            p.save();
            p.translate(panelX(panel), m_origin.y());
            p.scale(m_zoom, m_zoom);
            const bool classified = m_mode == ViewMode::Classified || panel == 1;
            p.drawImage(QPointF(0, 0), classified ? m_output->classified : m_output->raw);
            if (m_mode == ViewMode::Blend) {
                p.setOpacity(0.5);
                p.drawImage(QPointF(0, 0), m_output->classified);
                p.setOpacity(1);
            }
            for (const auto& [id, highlight] : m_highlights)
                p.drawImage(QPointF(0, 0), highlight);
            // Drawings stay on their own image (a rejected circle may be larger than the frame):
            // a couple of screen px of margin keeps outlines on the border whole.
            const double margin = 3 / m_zoom;
            p.setClipRect(
                QRectF(-margin, -margin, image.width() + 2 * margin, image.height() + 2 * margin));
            paintDrawings(p, layers, detectionsDimmed() ? kDimmedDetections : 1.0);
            p.restore();
        }
        if (m_labels)
            paintPerceptLabels(p, m_output->items, m_visible, QPointF(panelX(0), m_origin.y()),
                               m_zoom, detectionsDimmed() ? kDimmedDetections : 1.0);
    }
    // The tool's shapes (sample regions, annotated objects): a dark edge under the colour, so a
    // shape shows on any background; the selected one thicker, its handles marked.
    if (m_tools && m_output) {
        const auto toView = [this](const QPolygonF& points) {
            QPolygonF at;
            for (const QPointF& q : points)
                at << QPointF(panelX(0) + (q.x() + 0.5) * m_zoom,
                              m_origin.y() + (q.y() + 0.5) * m_zoom);
            return at;
        };
        const ToolOutline outline = m_tools->active().outline();
        p.setBrush(Qt::NoBrush);
        for (const OutlineShape& shape : outline.shapes) {
            const QPolygonF at = toView(shape.polygon);
            if (at.isEmpty())
                continue;
            const auto draw = [&](const QPen& pen) {
                p.setPen(pen);
                if (shape.radius >= 0)
                    p.drawEllipse(at.front(), shape.radius * m_zoom, shape.radius * m_zoom);
                else if (shape.closed)
                    p.drawPolygon(at);
                else
                    p.drawPolyline(at);
            };
            const double width = shape.selected ? 3 : 1.5;
            draw(QPen(QColor(0, 0, 0, 200), width + 2));
            QPen pen(shape.colour, width);
            if (shape.dashed)
                pen.setDashPattern({3, 2});
            draw(pen);
            if (shape.selected) {
                const QPolygonF handles = shape.handles.isEmpty() ? at : toView(shape.handles);
                for (int h = 0; h < handles.size(); ++h) {
                    const QRectF box(handles[h] - QPointF(3, 3), QSizeF(7, 7));
                    p.fillRect(box, Qt::white);
                    if (h != shape.chosen_handle)
                        continue;
                    p.setPen(QPen(shape.colour, 2)); // the chosen one: ringed in its colour
                    p.setBrush(Qt::NoBrush);
                    p.drawRect(box.adjusted(-3, -3, 3, 3));
                }
            }
        }
    }
    // The brush under the cursor: a circle through the outer pixels' centres, in every panel.
    if (const int radius = brushRadius(); radius >= 0 && m_cursor_pixel) {
        p.setPen(QPen(Qt::white, 1, Qt::DashLine));
        p.setBrush(Qt::NoBrush);
        const double r = (radius + 0.5) * m_zoom;
        for (int panel = 0; panel < panelCount(); ++panel)
            p.drawEllipse(QPointF(panelX(panel) + (m_cursor_pixel->x() + 0.5) * m_zoom,
                                  m_origin.y() + (m_cursor_pixel->y() + 0.5) * m_zoom),
                          r, r);
    }
    // A frame that failed, or a stage that threw: say so in the view, the tool goes on.
    QStringList problems;
    if (!m_output->error.isEmpty())
        problems << m_output->error;
    for (const Diagnostic& d : m_output->result.diagnostics)
        problems << QString::fromStdString(d.stage + ": " + d.message);
    if (!problems.isEmpty()) {
        const QString text = problems.join('\n');
        QRect box = p.fontMetrics().boundingRect(rect().adjusted(8, 8, -8, -8),
                                                 Qt::AlignLeft | Qt::TextWordWrap, text);
        box.adjust(-6, -4, 6, 4);
        p.fillRect(box, QColor(150, 20, 20, 220));
        p.setPen(Qt::white);
        p.drawText(box.adjusted(6, 4, -6, -4), Qt::AlignLeft | Qt::TextWordWrap, text);
    }
    m_painted_serial = m_output->serial;
    m_paint_ms = double(clock.nsecsElapsed()) / 1e6;
    emit painted(m_painted_serial);
}

void FrameView::resizeEvent(QResizeEvent*)
{
    if (m_fit)
        applyFit();
}

void FrameView::wheelEvent(QWheelEvent* event)
{
    // Touchpads and smooth wheels send small deltas: add them up to whole notches.
    m_wheel_delta += event->angleDelta().y();
    const int steps = m_wheel_delta / 120;
    m_wheel_delta -= steps * 120;
    event->accept();
    if (steps == 0)
        return;
    const QPointF anchor = event->position();
    for (int i = 0; i < std::abs(steps); ++i)
        setZoom(nextZoomStep(m_zoom, steps), anchor);
}

void FrameView::setStream(StreamDocument& stream)
{
    connect(&stream, &StreamDocument::frameReady, this,
            [this, &stream] { setOutput(stream.current()); });
    connect(&stream, &StreamDocument::streamChanged, this, [this] {
        setOutput(nullptr);
        fitToWindow();
    });
}

} // namespace fieldsight::ui
