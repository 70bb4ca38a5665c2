#include "ui/panels/uv_plane_panel.h"

#include "ui/adapters/image_adapter.h"
#include "ui/tools/tool_manager.h"

#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QMouseEvent>
#include <QPainter>
#include <QSpinBox>
#include <QWheelEvent>
#include <QVBoxLayout>

#include <array>
#include <cmath>

namespace fieldsight::ui {

namespace {

constexpr int kSide = 128; // cells along Cb and along Cr

} // namespace

UvCanvas::UvCanvas(LutDocument& lut, StreamDocument& stream, ToolManager& tools, QWidget* parent)
    : QWidget(parent), m_lut(lut), m_stream(stream), m_tools(tools)
{
    setObjectName(QStringLiteral("uv_canvas"));
    setMinimumSize(120, 120);
    setMouseTracking(true);
    setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Expanding);
    connect(&lut, &LutDocument::changed, this, &UvCanvas::refreshPlane);
    connect(&stream, &StreamDocument::frameReady, this, &UvCanvas::refreshScatter);
    // The cells the image tool would change (or has, mid-stroke) are outlined here.
    connect(&tools, &ToolManager::previewChanged, this,
            [this] { setOutlinedCells(m_tools.preview().cells); });
    connect(&tools, &ToolManager::activeChanged, this, [this] {
        m_tool_down = false; // a stroke ends with its tool
        update();
    });
    refreshPlane();
}

void UvCanvas::setYRange(int lo, int hi)
{
    m_y_lo = std::clamp(std::min(lo, hi), 0, kSide - 1);
    m_y_hi = std::clamp(std::max(lo, hi), 0, kSide - 1);
    if (m_selection && m_select_from && m_select_to) // the selection follows the Y range
        m_selection =
            CellMask::of(cellsInUvRect(m_select_from->x(), m_select_from->y(), m_select_to->x(),
                                       m_select_to->y(), m_y_lo, m_y_hi));
    refreshPlane();
    refreshScatter();
    if (m_selection)
        emit selectionChanged();
}

QRectF UvCanvas::planeRect() const
{
    const double side = (std::min(width(), height()) - 2) * m_zoom;
    return {(width() - side) / 2.0 + m_pan.x(), (height() - side) / 2.0 + m_pan.y(), side, side};
}

void UvCanvas::zoomBy(double factor, QPointF anchor)
{
    const QRectF before = planeRect();
    const QPointF t((anchor.x() - before.left()) / before.width(),
                    (anchor.y() - before.top()) / before.height());
    m_zoom = std::clamp(m_zoom * factor, 1.0, 8.0);
    if (m_zoom == 1.0) {
        m_pan = {};
    } else {
        m_pan = {};
        const QRectF after = planeRect();
        m_pan = anchor -
                QPointF(after.left() + t.x() * after.width(), after.top() + t.y() * after.height());
    }
    update();
}

void UvCanvas::wheelEvent(QWheelEvent* event)
{
    const int delta = event->angleDelta().y();
    if (delta != 0)
        zoomBy(delta > 0 ? 1.25 : 0.8, event->position());
    event->accept();
}

QPointF UvCanvas::cellCentre(int cb, int cr) const
{
    const QRectF r = planeRect();
    const double c = r.width() / kSide;
    return {r.left() + (cb + 0.5) * c, r.top() + (kSide - 1 - cr + 0.5) * c};
}

std::optional<QPoint> UvCanvas::cellAt(QPointF pos) const
{
    const QRectF r = planeRect();
    if (!r.contains(pos) || !rect().contains(pos.toPoint()))
        return std::nullopt;
    const double c = r.width() / kSide;
    const int cb = std::clamp(int((pos.x() - r.left()) / c), 0, kSide - 1);
    const int cr = kSide - 1 - std::clamp(int((pos.y() - r.top()) / c), 0, kSide - 1);
    return QPoint(cb, cr);
}

void UvCanvas::refreshPlane()
{
    m_plane_dirty = true; // rebuilt when next painted: nothing to do while the dock is hidden
    update();
}

void UvCanvas::rebuildPlane()
{
    m_plane_dirty = false;
    // Each UV cell shows the class most of its Y cells in the range have (unclassified only
    // when all are). The table is read in memory order, one Y slice after another.
    std::vector<std::array<std::uint16_t, kColourCount>> count(std::size_t(kSide * kSide));
    const std::uint8_t* cells = m_lut.table().data();
    for (int y = m_y_lo; y <= m_y_hi; ++y) {
        const std::uint8_t* slice = cells + (std::size_t(y) << 14);
        for (std::size_t i = 0; i < std::size_t(kSide * kSide); ++i)
            ++count[i][slice[i] % kColourCount];
    }
    std::array<QRgb, kColourCount> colours{};
    for (int c = 0; c < kColourCount; ++c)
        colours[std::size_t(c)] = toQColor(colourDisplayRgb(Colour(c))).rgb();
    colours[0] = qRgb(24, 24, 24);
    m_plane = QImage(kSide, kSide, QImage::Format_RGB32);
    for (int cr = 0; cr < kSide; ++cr) {
        auto* row = reinterpret_cast<QRgb*>(m_plane.scanLine(kSide - 1 - cr));
        for (int cb = 0; cb < kSide; ++cb) {
            const auto& n = count[std::size_t((cb << 7) | cr)];
            int best = 0;
            for (int c = 1; c < kColourCount; ++c)
                if (n[std::size_t(c)] > 0 &&
                    (best == 0 || n[std::size_t(c)] > n[std::size_t(best)]))
                    best = c;
            row[cb] = colours[std::size_t(best)];
        }
    }
}

void UvCanvas::refreshScatter()
{
    m_scatter_dirty = true;
    update();
}

void UvCanvas::rebuildScatter()
{
    m_scatter_dirty = false;
    m_scatter = QImage();
    const auto& out = m_stream.current();
    if (out && !out->frame.ycbcr.empty()) {
        std::vector<int> hist(kSide * kSide, 0);
        const cv::Mat& px = out->frame.ycbcr;
        for (int y = 0; y < px.rows; ++y) {
            const std::uint8_t* p = px.ptr<std::uint8_t>(y);
            for (int x = 0; x < px.cols; ++x, p += 3) {
                const int yc = p[0] >> 1;
                if (yc >= m_y_lo && yc <= m_y_hi)
                    ++hist[std::size_t((p[1] >> 1) + kSide * (p[2] >> 1))];
            }
        }
        const int most = std::max(1, *std::max_element(hist.begin(), hist.end()));
        m_scatter = QImage(kSide, kSide, QImage::Format_ARGB32_Premultiplied);
        m_scatter.fill(0);
        for (int cr = 0; cr < kSide; ++cr) {
            auto* row = reinterpret_cast<QRgb*>(m_scatter.scanLine(kSide - 1 - cr));
            for (int cb = 0; cb < kSide; ++cb)
                if (const int n = hist[std::size_t(cb + kSide * cr)]) {
                    const int alpha =
                        int(90 + 165 * std::log1p(double(n)) / std::log1p(double(most)));
                    row[cb] = qPremultiply(qRgba(255, 255, 255, std::min(255, alpha)));
                }
        }
    }
}

void UvCanvas::setOutlinedCells(const std::vector<std::uint32_t>& cells)
{
    m_outlined = QImage();
    if (!cells.empty()) {
        m_outlined = QImage(kSide, kSide, QImage::Format_ARGB32_Premultiplied);
        m_outlined.fill(0);
        const QRgb mark = qPremultiply(qRgba(255, 0, 255, 200));
        for (std::uint32_t cell : cells) {
            const int cb = int(cell >> 7) & 127;
            const int cr = int(cell) & 127;
            reinterpret_cast<QRgb*>(m_outlined.scanLine(kSide - 1 - cr))[cb] = mark;
        }
    }
    update();
}

void UvCanvas::clearSelection()
{
    m_selection.reset();
    m_select_from.reset();
    m_select_to.reset();
    update();
    emit selectionChanged();
}

bool UvCanvas::selecting(Qt::MouseButtons buttons) const
{
    return (buttons & Qt::RightButton) || ((buttons & Qt::LeftButton) && m_tools.active().pans());
}

bool UvCanvas::toolPaints() const
{
    return !m_tools.active().pans() && m_tools.active().accepts(ToolSurface::UvPlane);
}

ToolEvent UvCanvas::toolEvent(const QMouseEvent* event, QPoint cell) const
{
    ToolEvent e = ToolEvent::of(ToolSurface::UvPlane, *event, cell);
    e.y_lo = m_y_lo;
    e.y_hi = m_y_hi;
    return e;
}

void UvCanvas::mousePressEvent(QMouseEvent* event)
{
    const auto cell = cellAt(event->position());
    if (!cell)
        return;
    if (selecting(event->buttons())) {
        m_select_from = m_select_to = *cell;
        m_selection =
            CellMask::of(cellsInUvRect(cell->x(), cell->y(), cell->x(), cell->y(), m_y_lo, m_y_hi));
        update();
        return;
    }
    if (event->button() == Qt::LeftButton && toolPaints()) {
        m_tool_down = true;
        m_tools.press(toolEvent(event, *cell));
    }
}

void UvCanvas::mouseMoveEvent(QMouseEvent* event)
{
    m_cursor = event->position().toPoint();
    const auto cell = cellAt(event->position());
    if (cell) {
        const int y0 = m_y_lo << 1, y1 = (m_y_hi << 1) + 1;
        emit hovered(tr("Cb %1-%2, Cr %3-%4, Y %5-%6")
                         .arg(cell->x() << 1)
                         .arg((cell->x() << 1) + 1)
                         .arg(cell->y() << 1)
                         .arg((cell->y() << 1) + 1)
                         .arg(y0)
                         .arg(y1));
    }
    if (cell && m_select_from && selecting(event->buttons())) {
        m_select_to = *cell;
        m_selection = CellMask::of(cellsInUvRect(m_select_from->x(), m_select_from->y(), cell->x(),
                                                 cell->y(), m_y_lo, m_y_hi));
    } else if (cell && m_tool_down && (event->buttons() & Qt::LeftButton)) {
        m_tools.move(toolEvent(event, *cell));
    }
    update();
}

void UvCanvas::mouseReleaseEvent(QMouseEvent* event)
{
    if (m_select_from && m_selection) {
        emit selectionChanged();
    }
    if (m_tool_down && event->button() == Qt::LeftButton) {
        m_tool_down = false;
        m_tools.release(toolEvent(event, cellAt(event->position()).value_or(QPoint(-1, -1))));
    }
}

void UvCanvas::leaveEvent(QEvent*)
{
    m_cursor.reset();
    update();
}

void UvCanvas::paintEvent(QPaintEvent*)
{
    if (m_plane_dirty)
        rebuildPlane();
    if (m_scatter_dirty)
        rebuildScatter();
    QPainter p(this);
    p.fillRect(rect(), QColor(40, 40, 40));
    const QRectF r = planeRect();
    p.drawImage(r, m_plane);
    if (!m_scatter.isNull())
        p.drawImage(r, m_scatter);
    if (!m_outlined.isNull())
        p.drawImage(r, m_outlined);
    const double c = r.width() / kSide;
    if (m_select_from && m_select_to) {
        const QPointF a = cellCentre(m_select_from->x(), m_select_from->y());
        const QPointF b = cellCentre(m_select_to->x(), m_select_to->y());
        const QRectF box = QRectF(a, b).normalized().adjusted(-c / 2, -c / 2, c / 2, c / 2);
        p.setPen(QPen(QColor(0, 230, 255), 1.5, Qt::DashLine));
        p.setBrush(Qt::NoBrush);
        p.drawRect(box);
    }
    // The neutral axes (Cb = Cr = 128) for orientation.
    p.setPen(QPen(QColor(255, 255, 255, 60), 1));
    p.drawLine(QPointF(r.center().x(), r.top()), QPointF(r.center().x(), r.bottom()));
    p.drawLine(QPointF(r.left(), r.center().y()), QPointF(r.right(), r.center().y()));
    p.setPen(QColor(200, 200, 200));
    const QRectF labels = r.intersected(QRectF(rect())).adjusted(4, 2, -4, -2);
    p.drawText(labels, Qt::AlignRight | Qt::AlignBottom, tr("Cb →"));
    p.drawText(labels, Qt::AlignLeft | Qt::AlignTop, tr("↑ Cr"));
    if (m_zoom > 1)
        p.drawText(labels, Qt::AlignRight | Qt::AlignTop, tr("×%1").arg(m_zoom, 0, 'f', 1));
    if (toolPaints() && m_cursor && r.contains(*m_cursor)) {
        p.setPen(QPen(Qt::white, 1, Qt::DashLine));
        p.setBrush(Qt::NoBrush);
        const double radius = (m_tools.settings().brushRadius() + 0.5) * c;
        p.drawEllipse(QPointF(*m_cursor), radius, radius);
    }
}

UvPlanePanel::UvPlanePanel(LutDocument& lut, StreamDocument& stream, ToolManager& tools,
                           QWidget* parent)
    : QWidget(parent)
{
    setObjectName(QStringLiteral("uv_panel"));
    auto* column = new QVBoxLayout(this);
    auto* row = new QHBoxLayout;
    m_y_lo = new QSpinBox(this);
    m_y_hi = new QSpinBox(this);
    m_y_lo->setObjectName(QStringLiteral("uv.y_low"));
    m_y_hi->setObjectName(QStringLiteral("uv.y_high"));
    for (QSpinBox* box : {m_y_lo, m_y_hi})
        box->setRange(0, 255);
    m_y_hi->setValue(255);
    row->addWidget(new QLabel(tr("Y from"), this));
    row->addWidget(m_y_lo);
    row->addWidget(new QLabel(tr("to"), this));
    row->addWidget(m_y_hi);
    row->addStretch(1);
    column->addLayout(row);
    m_canvas = new UvCanvas(lut, stream, tools, this);
    column->addWidget(m_canvas, 1);
    m_info = new QLabel(this);
    m_info->setObjectName(QStringLiteral("uv.info"));
    m_info->setWordWrap(true);
    m_info->setText(tr("Paint with the LUT tool; right-drag selects"));
    m_canvas->setToolTip(tr("Left: paint cells with the LUT editor's colour and brush (Erase "
                            "unclassifies; with Pan, left-drag selects). Right-drag: select "
                            "cells; their pixels light up in the image."));
    column->addWidget(m_info);
    const auto apply = [this] { m_canvas->setYRange(m_y_lo->value() >> 1, m_y_hi->value() >> 1); };
    connect(m_y_lo, &QSpinBox::valueChanged, this, apply);
    connect(m_y_hi, &QSpinBox::valueChanged, this, apply);
    connect(m_canvas, &UvCanvas::hovered, m_info, &QLabel::setText);
}

void UvPlanePanel::setYLevels(int lo, int hi)
{
    m_y_lo->setValue(lo);
    m_y_hi->setValue(hi);
}

} // namespace fieldsight::ui
