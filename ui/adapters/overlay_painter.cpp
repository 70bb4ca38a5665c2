// Paints DebugDrawings with QPainter, crisp and in image coordinates (see overlay_painter.h).
#include "ui/adapters/overlay_painter.h"

#include "ui/adapters/image_adapter.h"

#include "visioncore/percepts/percept_set.h"

#include <QList>
#include <QPainter>
#include <QPen>
#include <QPointF>
#include <QRectF>
#include <QTransform>

#include <algorithm>
#include <cmath>

namespace fieldsight::ui {

namespace {

/// Device px by which shapes are nudged up and left. Qt's aliased line stroker works in 1/64 px
/// fixed point and puts a line that runs exactly through pixel centres at slope -1 one row too low,
/// so it misses its own end pixels; a nudge this small only moves coordinates that fall exactly on
/// a pixel boundary, and breaks all those ties the same way.
constexpr double kTieBreak = 1.0 / 32;

/// Device px per image px (the painter's zoom).
double deviceScale(const QPainter& painter)
{
    return std::sqrt(std::abs(painter.worldTransform().determinant()));
}

/// Where coordinate c of a shape lands, in image coordinates: c + centre.
double centreOffset(const QPainter& painter)
{
    return 0.5 - kTieBreak / std::max(deviceScale(painter), 1e-6);
}

QPointF at(const PointF& p, double centre)
{
    return {p.x + centre, p.y + centre};
}

/// Device px of a dash and of the gap after it (ground truth): the same at every pen width, so a
/// truth outline's dark rim and its white line have their dashes in the same places.
constexpr double kDash = 5;
constexpr double kGap = 3;

QPen cosmeticPen(const QColor& colour, double width, bool dashed = false)
{
    QPen pen(colour, width);
    pen.setCosmetic(true);
    // A square cap keeps both end pixels of a thin line at any zoom; with a flat cap one can drop.
    pen.setCapStyle(dashed ? Qt::FlatCap : Qt::SquareCap);
    pen.setJoinStyle(Qt::MiterJoin);
    if (dashed)
        pen.setDashPattern({kDash / width, kGap / width}); // in pen widths
    return pen;
}

void paintPoints(QPainter& painter, const DebugShape& shape, const QColor& colour, double centre)
{
    const double side = shape.size > 0 ? shape.size : 1.0;
    QList<QRectF> squares;
    squares.reserve(qsizetype(shape.points.size()));
    for (const PointF& p : shape.points)
        squares.append(QRectF(p.x + centre - side / 2, p.y + centre - side / 2, side, side));
    // One call for the whole list: scan-line layers hold thousands of points per frame.
    painter.setPen(Qt::NoPen);
    painter.setBrush(colour);
    painter.drawRects(squares.constData(), int(squares.size()));
}

void paintPolyline(QPainter& painter, const DebugShape& shape, const QColor& colour,
                   std::size_t count, double centre, bool dashed)
{
    if (shape.points.size() < 2)
        return;
    QList<QPointF> points;
    points.reserve(qsizetype(count));
    for (std::size_t i = 0; i < count; ++i)
        points.append(at(shape.points[i], centre));
    painter.setPen(cosmeticPen(colour, std::max(1.0, shape.width), dashed));
    painter.setBrush(Qt::NoBrush);
    painter.drawPolyline(points.constData(), int(points.size()));
}

void paintCircle(QPainter& painter, const DebugShape& shape, const QColor& colour, double centre,
                 bool dashed)
{
    if (shape.points.empty())
        return;
    painter.setPen(cosmeticPen(colour, std::max(1.0, shape.width), dashed));
    painter.setBrush(shape.filled ? QBrush(colour) : QBrush(Qt::NoBrush));
    painter.drawEllipse(at(shape.points[0], centre), shape.size, shape.size);
}

void paintRect(QPainter& painter, const DebugShape& shape, const QColor& colour, double centre,
               bool dashed)
{
    if (shape.points.size() < 2)
        return;
    const QRectF centres =
        QRectF(at(shape.points[0], centre), at(shape.points[1], centre)).normalized();
    if (shape.filled) {
        // The corner pixels' squares, not their centres, bound the filled area.
        painter.setPen(Qt::NoPen);
        painter.setBrush(colour);
        painter.drawRect(centres.adjusted(-0.5, -0.5, 0.5, 0.5));
        return;
    }
    painter.setPen(cosmeticPen(colour, std::max(1.0, shape.width), dashed));
    painter.setBrush(Qt::NoBrush);
    painter.drawRect(centres);
}

} // namespace

bool isTruthLayer(std::string_view layer)
{
    return layer.size() > kTruthLayerPrefix.size() && layer.starts_with(kTruthLayerPrefix) &&
           layer[kTruthLayerPrefix.size()] == '.';
}

bool isPerceptLayer(std::string_view layer)
{
    return layer.size() > kPerceptLayerPrefix.size() && layer.starts_with(kPerceptLayerPrefix) &&
           layer[kPerceptLayerPrefix.size()] == '.';
}

void paintShape(QPainter& painter, const DebugShape& shape, bool dashed)
{
    painter.setRenderHint(QPainter::Antialiasing, false);
    const QColor colour = toQColor(shape.colour);
    const double centre = centreOffset(painter);
    switch (shape.kind) {
    case ShapeKind::Points:
        paintPoints(painter, shape, colour, centre);
        break;
    case ShapeKind::Line:
        paintPolyline(painter, shape, colour, 2, centre, dashed);
        break;
    case ShapeKind::Polyline:
        paintPolyline(painter, shape, colour, shape.points.size(), centre, dashed);
        break;
    case ShapeKind::Circle:
        paintCircle(painter, shape, colour, centre, dashed);
        break;
    case ShapeKind::Rect:
        paintRect(painter, shape, colour, centre, dashed);
        break;
    }
}

void paintDrawing(QPainter& painter, const DebugDrawing& drawing)
{
    painter.save();
    painter.setRenderHint(QPainter::Antialiasing, false);
    const double centre = centreOffset(painter);
    const QTransform transform = painter.worldTransform();
    // Scan lines and segments are thousands of axis-aligned lines a frame. Each is filled as the
    // rectangle the cosmetic pen would cover (its width across, half a width of square cap at
    // each end), mapped to device px by hand: with no transform left, fillRect() takes the raster
    // engine's fast path, about 7 times faster than stroking, with the same pixels
    // (tests/ui/test_overlay_painter.cpp). A rotating transform keeps stroking.
    const bool dashed = isTruthLayer(drawing.layer);
    const bool by_hand = transform.type() <= QTransform::TxScale && !dashed;
    bool device_space = false; // the painter's transform is reset for hand-mapped rectangles
    for (const DebugShape& shape : drawing.shapes) {
        const bool axis_line =
            by_hand && shape.kind == ShapeKind::Line && shape.points.size() >= 2 &&
            (shape.points[0].x == shape.points[1].x || shape.points[0].y == shape.points[1].y);
        if (!axis_line) {
            if (device_space)
                painter.setWorldTransform(transform);
            device_space = false;
            paintShape(painter, shape, dashed);
            continue;
        }
        if (!device_space)
            painter.resetTransform();
        device_space = true;
        const QPointF a = transform.map(at(shape.points[0], centre));
        const QPointF b = transform.map(at(shape.points[1], centre));
        const double half = std::max(1.0, shape.width) / 2;
        painter.fillRect(
            QRectF(QPointF(std::min(a.x(), b.x()) - half, std::min(a.y(), b.y()) - half),
                   QPointF(std::max(a.x(), b.x()) + half, std::max(a.y(), b.y()) + half)),
            toQColor(shape.colour));
    }
    painter.restore();
}

void paintDrawings(QPainter& painter, const std::vector<const DebugDrawing*>& drawings,
                   double detection_opacity)
{
    const double opacity = painter.opacity();
    for (const DebugDrawing* drawing : drawings) {
        if (!drawing)
            continue;
        painter.setOpacity(opacity * (isPerceptLayer(drawing->layer) ? detection_opacity : 1.0));
        paintDrawing(painter, *drawing);
    }
    painter.setOpacity(opacity);
}

QImage renderOverlay(const cv::Mat& ycbcr, const std::vector<const DebugDrawing*>& drawings,
                     int scale)
{
    QImage image = ycbcrToZoomedQImage(ycbcr, scale);
    if (image.isNull())
        return image;
    QPainter painter(&image);
    painter.scale(std::max(1, scale), std::max(1, scale));
    paintDrawings(painter, drawings);
    painter.end();
    return image;
}

} // namespace fieldsight::ui
