// The frame view's mouse and keys: the tools it forwards them to (press, drag, release, hover and
// their keys), panning with the middle button or a tool that pans, and the detections' tooltips.
#include "ui/frame_view/frame_view.h"

#include "ui/adapters/image_adapter.h"

#include <QCursor>
#include <QHelpEvent>
#include <QMouseEvent>
#include <QToolTip>

namespace fieldsight::ui {

void FrameView::setTools(ToolManager* tools)
{
    m_tools = tools;
    if (!tools)
        return;
    const auto follow = [this] {
        m_tool_down = false;
        setCursor(m_tools->active().cursor());
        update();
    };
    connect(tools, &ToolManager::activeChanged, this, follow);
    connect(tools, &ToolManager::outlineChanged, this, qOverload<>(&QWidget::update));
    connect(&tools->settings(), &LutToolSettings::changed, this, qOverload<>(&QWidget::update));
    // What the tool would change, lit in the image (kept across frames until it changes).
    connect(tools, &ToolManager::previewChanged, this, [this] {
        const cv::Mat& pixels = m_tools->preview().pixels;
        setHighlight(QStringLiteral("preview"),
                     pixels.empty() ? QImage() : maskToQImage(pixels, QColor(255, 0, 255, 150)));
    });
    follow();
}

bool FrameView::detectionsDimmed() const
{
    return m_tools && m_tools->active().info().group == QLatin1String("annotate");
}

bool FrameView::toolPans() const
{
    return !m_tools || m_tools->active().pans();
}

int FrameView::brushRadius() const
{
    return m_tools ? m_tools->active().outline().brush_radius : -1;
}

void FrameView::mousePressEvent(QMouseEvent* event)
{
    if (event->button() == Qt::MiddleButton || (event->button() == Qt::LeftButton && toolPans())) {
        m_drag_from = event->position().toPoint();
        m_drag_origin = m_origin;
        setCursor(Qt::ClosedHandCursor);
        return;
    }
    if (!m_tools || toolPans())
        return;
    if (const std::optional<QPoint> pixel = pixelAt(event->position())) {
        if (event->button() == Qt::LeftButton)
            m_tool_down = true;
        m_tools->press(toolEvent(*event, *pixel));
    }
}

ToolEvent FrameView::toolEvent(const QMouseEvent& event, QPoint pixel) const
{
    ToolEvent e = ToolEvent::of(ToolSurface::Image, event, pixel);
    e.zoom = m_zoom;
    if (const std::optional<QPointF> at = imagePoint(event.position()))
        e.position = *at;
    return e;
}

void FrameView::keyPressEvent(QKeyEvent* event)
{
    if (m_tools && m_tools->key(event->key()))
        event->accept();
    else
        QWidget::keyPressEvent(event);
}

void FrameView::mouseMoveEvent(QMouseEvent* event)
{
    if (m_drag_from) {
        m_origin = m_drag_origin + (event->position().toPoint() - *m_drag_from);
        m_fit = false;
        update();
    }
    const std::optional<QPoint> pixel = pixelAt(event->position());
    if (brushRadius() >= 0 && pixel != m_cursor_pixel) {
        m_cursor_pixel = pixel;
        update();
    }
    if (pixel && m_tool_down && m_tools)
        m_tools->move(toolEvent(*event, *pixel));
    if (m_tools)
        m_tools->hover(pixel);
    if (pixel)
        emit pixelHovered(*pixel);
    else
        emit hoverLeft();
}

void FrameView::mouseReleaseEvent(QMouseEvent* event)
{
    if (m_tool_down && event->button() == Qt::LeftButton && m_tools) {
        m_tool_down = false;
        const std::optional<QPoint> pixel = pixelAt(event->position());
        m_tools->release(toolEvent(*event, pixel.value_or(QPoint(-1, -1))));
    }
    if (m_drag_from) {
        m_drag_from.reset();
        setCursor(m_tools ? m_tools->active().cursor() : QCursor(Qt::CrossCursor));
    }
}

void FrameView::leaveEvent(QEvent*)
{
    if (m_cursor_pixel) {
        m_cursor_pixel.reset();
        update();
    }
    if (m_tools)
        m_tools->hover(std::nullopt);
    emit hoverLeft();
}

bool FrameView::event(QEvent* event)
{
    if (event->type() == QEvent::ToolTip) {
        const auto* help = static_cast<QHelpEvent*>(event);
        // A detection's tip only while looking (the pan tool): over an editing tool it would
        // cover the pixels being classified (its details are in the Detections dock).
        const bool looking = !m_tools || m_tools->active().pans();
        if (const PerceptItem* item = looking ? itemAt(help->pos()) : nullptr)
            QToolTip::showText(help->globalPos(), item->details, this);
        else
            QToolTip::hideText();
        return true;
    }
    return QWidget::event(event);
}

} // namespace fieldsight::ui
