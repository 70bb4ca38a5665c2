#include "ui/tools/shape_geometry.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace fieldsight::ui {

namespace {

PointF operator+(PointF a, PointF b)
{
    return {a.x + b.x, a.y + b.y};
}

double distance(PointF a, PointF b)
{
    return std::hypot(a.x - b.x, a.y - b.y);
}

double distanceToSegment(PointF p, PointF a, PointF b)
{
    const double dx = b.x - a.x;
    const double dy = b.y - a.y;
    const double length2 = dx * dx + dy * dy;
    if (length2 <= 0)
        return distance(p, a);
    const double t = std::clamp(((p.x - a.x) * dx + (p.y - a.y) * dy) / length2, 0.0, 1.0);
    return distance(p, {a.x + t * dx, a.y + t * dy});
}

/// A box's corners as {left, top, right, bottom}, whichever way its two points were given.
struct Edges
{
    double left, top, right, bottom;
};

Edges edgesOf(const EditShape& shape)
{
    const PointF a = shape.points.size() > 0 ? shape.points[0] : PointF{};
    const PointF b = shape.points.size() > 1 ? shape.points[1] : a;
    return {std::min(a.x, b.x), std::min(a.y, b.y), std::max(a.x, b.x), std::max(a.y, b.y)};
}

EditShape boxOf(double x0, double y0, double x1, double y1)
{
    return {{{std::min(x0, x1), std::min(y0, y1)}, {std::max(x0, x1), std::max(y0, y1)}}, 0};
}

} // namespace

std::optional<EditShape> shapeFromDrag(ShapeForm form, PointF from, PointF to)
{
    switch (form) {
    case ShapeForm::Circle:
        if (distance(from, to) < 1)
            return std::nullopt;
        return EditShape{{from}, distance(from, to)};
    case ShapeForm::Box:
        if (from.x == to.x && from.y == to.y)
            return std::nullopt;
        return boxOf(from.x, from.y, to.x, to.y);
    case ShapeForm::Segment:
        if (distance(from, to) < 2)
            return std::nullopt;
        return EditShape{{from, to}, 0};
    case ShapeForm::Polyline: // drawn point by point
    case ShapeForm::None:
        break;
    }
    return std::nullopt;
}

double distanceTo(ShapeForm form, const EditShape& shape, PointF p)
{
    if (shape.points.empty())
        return std::numeric_limits<double>::infinity();
    switch (form) {
    case ShapeForm::Circle:
        return std::max(0.0, distance(p, shape.points.front()) - shape.radius);
    case ShapeForm::Box: {
        const Edges e = edgesOf(shape);
        // Inclusive pixels: a box reaches half a pixel beyond its corner pixels' centres.
        const double dx = std::max({e.left - 0.5 - p.x, 0.0, p.x - e.right - 0.5});
        const double dy = std::max({e.top - 0.5 - p.y, 0.0, p.y - e.bottom - 0.5});
        return std::hypot(dx, dy);
    }
    case ShapeForm::Segment:
    case ShapeForm::Polyline:
        if (shape.points.size() == 1)
            return distance(p, shape.points.front());
        return nearestSegment(shape, p)->second;
    case ShapeForm::None:
        break;
    }
    return std::numeric_limits<double>::infinity();
}

double areaOf(ShapeForm form, const EditShape& shape)
{
    if (form == ShapeForm::Circle)
        return std::numbers::pi * shape.radius * shape.radius;
    if (form == ShapeForm::Box) {
        const Edges e = edgesOf(shape);
        return (e.right - e.left + 1) * (e.bottom - e.top + 1);
    }
    return 0;
}

std::vector<PointF> handlesOf(ShapeForm form, const EditShape& shape)
{
    if (shape.points.empty())
        return {};
    switch (form) {
    case ShapeForm::Circle: {
        const PointF c = shape.points.front();
        const double r = shape.radius;
        return {{c.x + r, c.y}, {c.x, c.y + r}, {c.x - r, c.y}, {c.x, c.y - r}};
    }
    case ShapeForm::Box: {
        const Edges e = edgesOf(shape);
        const double mx = (e.left + e.right) / 2;
        const double my = (e.top + e.bottom) / 2;
        return {{e.left, e.top}, {e.right, e.top}, {e.right, e.bottom}, {e.left, e.bottom},
                {mx, e.top},     {e.right, my},    {mx, e.bottom},      {e.left, my}};
    }
    case ShapeForm::Segment:
    case ShapeForm::Polyline:
        return shape.points;
    case ShapeForm::None:
        break;
    }
    return {};
}

std::optional<std::size_t> handleAt(const std::vector<PointF>& handles, PointF p, double tolerance)
{
    std::optional<std::size_t> best;
    double best_distance = tolerance;
    for (std::size_t i = 0; i < handles.size(); ++i) {
        const double d = distance(handles[i], p);
        if (d <= best_distance) {
            best = i;
            best_distance = d;
        }
    }
    return best;
}

EditShape dragHandle(ShapeForm form, const EditShape& shape, std::size_t handle, PointF to)
{
    EditShape out = shape;
    switch (form) {
    case ShapeForm::Circle:
        if (!shape.points.empty())
            out.radius = distance(shape.points.front(), to);
        break;
    case ShapeForm::Box: {
        Edges e = edgesOf(shape);
        // Which edges each handle holds: corners two, edge middles one.
        static constexpr bool kLeft[8] = {true, false, false, true, false, false, false, true};
        static constexpr bool kRight[8] = {false, true, true, false, false, true, false, false};
        static constexpr bool kTop[8] = {true, true, false, false, true, false, false, false};
        static constexpr bool kBottom[8] = {false, false, true, true, false, false, true, false};
        if (handle < 8) {
            if (kLeft[handle])
                e.left = to.x;
            if (kRight[handle])
                e.right = to.x;
            if (kTop[handle])
                e.top = to.y;
            if (kBottom[handle])
                e.bottom = to.y;
        }
        out = boxOf(e.left, e.top, e.right, e.bottom);
        break;
    }
    case ShapeForm::Segment:
    case ShapeForm::Polyline:
        if (handle < out.points.size())
            out.points[handle] = to;
        break;
    case ShapeForm::None:
        break;
    }
    return out;
}

EditShape moved(const EditShape& shape, PointF by)
{
    EditShape out = shape;
    for (PointF& p : out.points)
        p = p + by;
    return out;
}

std::optional<std::pair<std::size_t, double>> nearestSegment(const EditShape& shape, PointF p)
{
    std::optional<std::pair<std::size_t, double>> best;
    for (std::size_t i = 0; i + 1 < shape.points.size(); ++i) {
        const double d = distanceToSegment(p, shape.points[i], shape.points[i + 1]);
        if (!best || d < best->second)
            best = {i, d};
    }
    return best;
}

std::vector<PointF> outlinePoints(ShapeForm form, const EditShape& shape)
{
    if (form == ShapeForm::Box) {
        const Edges e = edgesOf(shape);
        return {{e.left, e.top}, {e.right, e.top}, {e.right, e.bottom}, {e.left, e.bottom}};
    }
    if (form == ShapeForm::Circle)
        return shape.points.empty() ? std::vector<PointF>{} : std::vector{shape.points.front()};
    return shape.points;
}

} // namespace fieldsight::ui
