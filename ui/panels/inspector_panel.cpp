#include "ui/panels/inspector_panel.h"

#include "visioncore/services/layers.h"

#include <cmath>

namespace fieldsight::ui {

namespace {

double distanceToSegment(PointF a, PointF b, double x, double y)
{
    const double dx = b.x - a.x, dy = b.y - a.y;
    const double len2 = dx * dx + dy * dy;
    double t = len2 > 0 ? ((x - a.x) * dx + (y - a.y) * dy) / len2 : 0;
    t = std::clamp(t, 0.0, 1.0);
    return std::hypot(a.x + t * dx - x, a.y + t * dy - y);
}

QString pointText(PointF p)
{
    return QStringLiteral("(%1, %2)").arg(p.x, 0, 'f', 0).arg(p.y, 0, 'f', 0);
}

QString shapeText(const DebugShape& s)
{
    switch (s.kind) {
    case ShapeKind::Line:
    case ShapeKind::Rect:
        return pointText(s.points[0]) + QStringLiteral("–") + pointText(s.points[1]);
    case ShapeKind::Circle:
        return QStringLiteral("centre %1, r %2").arg(pointText(s.points[0])).arg(s.size, 0, 'f', 1);
    case ShapeKind::Points:
    case ShapeKind::Polyline:
        break;
    }
    return QStringLiteral("%1 points").arg(qsizetype(s.points.size()));
}

} // namespace

bool shapeCovers(const DebugShape& s, int x, int y)
{
    const double px = x, py = y;
    switch (s.kind) {
    case ShapeKind::Points: {
        const double half = std::max(1.0, s.size) / 2;
        for (const PointF& p : s.points)
            if (std::abs(std::round(p.x) - px) < half && std::abs(std::round(p.y) - py) < half)
                return true;
        return false;
    }
    case ShapeKind::Line:
        return s.points.size() >= 2 && distanceToSegment(s.points[0], s.points[1], px, py) <= 0.5;
    case ShapeKind::Polyline:
        for (std::size_t i = 1; i < s.points.size(); ++i)
            if (distanceToSegment(s.points[i - 1], s.points[i], px, py) <= 0.5)
                return true;
        return false;
    case ShapeKind::Circle: {
        if (s.points.empty())
            return false;
        const double d = std::hypot(s.points[0].x - px, s.points[0].y - py);
        return s.filled ? d <= s.size : std::abs(d - s.size) <= 0.7;
    }
    case ShapeKind::Rect: {
        if (s.points.size() < 2)
            return false;
        const double x0 = std::min(s.points[0].x, s.points[1].x);
        const double x1 = std::max(s.points[0].x, s.points[1].x);
        const double y0 = std::min(s.points[0].y, s.points[1].y);
        const double y1 = std::max(s.points[0].y, s.points[1].y);
        const bool inside = px >= x0 - 0.5 && px <= x1 + 0.5 && py >= y0 - 0.5 && py <= y1 + 0.5;
        if (s.filled || !inside)
            return inside;
        return std::abs(px - x0) <= 0.5 || std::abs(px - x1) <= 0.5 || std::abs(py - y0) <= 0.5 ||
               std::abs(py - y1) <= 0.5;
    }
    }
    return false;
}

InspectorPanel::InspectorPanel(const Pipeline& pipeline, QWidget* parent) : QLabel(parent)
{
    setObjectName(QStringLiteral("inspector"));
    setAlignment(Qt::AlignTop | Qt::AlignLeft);
    setTextInteractionFlags(Qt::TextSelectableByMouse);
    setWordWrap(true);
    setMargin(6);
    QFont mono(QStringLiteral("monospace"));
    mono.setStyleHint(QFont::TypeWriter);
    setFont(mono);
    for (const LayerInfo& layer : allLayers(pipeline))
        m_layer_names[layer.id] = layer.name;
    clearPixel();
}

void InspectorPanel::clearPixel()
{
    setText(tr("Move the cursor over the frame."));
}

void InspectorPanel::inspect(const FrameOutput* out, QPoint pixel)
{
    if (!out || out->frame.ycbcr.type() != CV_8UC3 || out->classes.empty() || out->raw.isNull() ||
        out->classes.size() != out->frame.ycbcr.size() || pixel.x() < 0 || pixel.y() < 0 ||
        pixel.x() >= out->frame.ycbcr.cols || pixel.y() >= out->frame.ycbcr.rows) {
        clearPixel();
        return;
    }
    const int x = pixel.x(), y = pixel.y();
    const cv::Vec3b ycc = out->frame.ycbcr.at<cv::Vec3b>(y, x);
    const QRgb rgb = out->raw.pixel(x, y);
    const auto cls = Colour(out->classes.at<std::uint8_t>(y, x));
    const std::string_view cls_name = colourName(cls);
    QStringList lines;
    lines << tr("x %1  y %2").arg(x).arg(y);
    lines << tr("Y %1  Cb %2  Cr %3").arg(ycc[0]).arg(ycc[1]).arg(ycc[2]);
    lines << tr("R %1  G %2  B %3").arg(qRed(rgb)).arg(qGreen(rgb)).arg(qBlue(rgb));
    lines << tr("class %1 %2")
                 .arg(int(cls))
                 .arg(QString::fromUtf8(cls_name.data(), qsizetype(cls_name.size())));
    int shown = 0;
    for (const DebugDrawing& d : out->drawings) {
        if (d.layer.rfind(kPerceptLayerPrefix, 0) == 0 || d.layer.rfind(kTruthLayerPrefix, 0) == 0)
            continue; // detections have their tooltips and panel
        for (std::size_t i = 0; i < d.shapes.size() && shown < 12; ++i) {
            if (!shapeCovers(d.shapes[i], x, y))
                continue;
            const auto name = m_layer_names.find(d.layer);
            lines << tr("%1 #%2: %3")
                         .arg(QString::fromStdString(name == m_layer_names.end() ? d.layer
                                                                                 : name->second))
                         .arg(i)
                         .arg(shapeText(d.shapes[i]));
            if (const auto note = d.notes.find(i); note != d.notes.end())
                lines.back() += QStringLiteral(": ") + QString::fromStdString(note->second);
            ++shown;
        }
    }
    if (shown == 0)
        lines << tr("(on no scan line or other stage shape)");
    setText(lines.join('\n'));
}

} // namespace fieldsight::ui
