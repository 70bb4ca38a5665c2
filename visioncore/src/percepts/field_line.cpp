// Field line percepts in JSON and as a drawing.
#include "visioncore/percepts/field_line.h"

#include "percepts/percept_json.h"

#include <algorithm>
#include <cmath>

namespace fieldsight {

using namespace percept_json;

void PerceptTraits<FieldLine>::toJson(const std::vector<FieldLine>& lines, PerceptNames,
                                      OrderedJson& value)
{
    writeList(lines, value, [](const FieldLine& l) {
        return OrderedJson{{"x1", px(l.x1)}, {"y1", px(l.y1)}, {"x2", px(l.x2)}, {"y2", px(l.y2)}};
    });
}

std::optional<std::string> PerceptTraits<FieldLine>::fromJson(const Json& value, PerceptNames,
                                                              const std::string& where,
                                                              std::vector<FieldLine>& out)
{
    return readList(value, where, out, [](FieldReader& f) {
        return FieldLine{f.number("x1"), f.number("y1"), f.number("x2"), f.number("y2")};
    });
}

void PerceptTraits<FieldLine>::draw(const std::vector<FieldLine>& lines, Rgb ink, double width,
                                    DebugDrawing& out)
{
    for (const FieldLine& l : lines)
        out.add({ShapeKind::Line, {{l.x1, l.y1}, {l.x2, l.y2}}, ink, width, false, width});
}

} // namespace fieldsight

namespace fieldsight {

EditShape PerceptTraits<FieldLine>::shapeOf(const FieldLine& l)
{
    return {{{l.x1, l.y1}, {l.x2, l.y2}}, 0};
}

FieldLine PerceptTraits<FieldLine>::fromShape(const EditShape& s)
{
    const PointF a = s.points.size() > 0 ? s.points[0] : PointF{};
    const PointF b = s.points.size() > 1 ? s.points[1] : a;
    return {a.x, a.y, b.x, b.y};
}

double fieldLineMatchCost(const FieldLine& a, const FieldLine& b)
{
    const double length_a = std::hypot(a.x2 - a.x1, a.y2 - a.y1);
    const double length_b = std::hypot(b.x2 - b.x1, b.y2 - b.y1);
    // Ties go to the first argument as the longer one: the rule is symmetric all the same.
    const FieldLine& longer = length_a >= length_b ? a : b;
    const FieldLine& shorter = length_a >= length_b ? b : a;
    const double length = std::max(length_a, length_b);
    const double limit = std::max(4.0, 0.05 * length);
    if (length < 1e-9) // two points
        return std::hypot(a.x1 - b.x1, a.y1 - b.y1) <= limit ? std::hypot(a.x1 - b.x1, a.y1 - b.y1)
                                                             : -1.0;
    const double ux = (longer.x2 - longer.x1) / length;
    const double uy = (longer.y2 - longer.y1) / length;
    // Along and across the longer segment, from its first end.
    const auto along = [&](double x, double y) {
        return (x - longer.x1) * ux + (y - longer.y1) * uy;
    };
    const auto across = [&](double x, double y) {
        return std::abs((x - longer.x1) * uy - (y - longer.y1) * ux);
    };
    const double d1 = across(shorter.x1, shorter.y1);
    const double d2 = across(shorter.x2, shorter.y2);
    if (d1 > limit || d2 > limit)
        return -1.0;
    const double t1 = along(shorter.x1, shorter.y1);
    const double t2 = along(shorter.x2, shorter.y2);
    const double lo = std::min(t1, t2);
    const double hi = std::max(t1, t2);
    const double overlap = std::min(hi, length) - std::max(lo, 0.0);
    // A point-like shorter segment must lie within the longer one's extent.
    const bool overlaps = hi - lo < 1e-9 ? lo >= 0 && lo <= length : overlap >= 0.5 * (hi - lo);
    return overlaps ? 0.5 * (d1 + d2) : -1.0;
}

std::optional<double> PerceptTraits<FieldLine>::matchCost(const FieldLine& detected,
                                                          const FieldLine& truth, int /*width*/,
                                                          int /*height*/)
{
    if (const double cost = fieldLineMatchCost(detected, truth); cost >= 0)
        return cost;
    return std::nullopt;
}

} // namespace fieldsight
