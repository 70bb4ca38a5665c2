// Ball percepts in JSON and as a drawing.
#include "visioncore/percepts/ball.h"

#include "percepts/percept_json.h"

#include <algorithm>
#include <cmath>

namespace fieldsight {

using namespace percept_json;

void PerceptTraits<Ball>::toJson(const std::vector<Ball>& balls, PerceptNames, OrderedJson& value)
{
    writeList(balls, value, [](const Ball& b) {
        return OrderedJson{{"x", px(b.x)}, {"y", px(b.y)}, {"radius", px(b.radius)}};
    });
}

std::optional<std::string> PerceptTraits<Ball>::fromJson(const Json& value, PerceptNames,
                                                         const std::string& where,
                                                         std::vector<Ball>& out)
{
    return readList(value, where, out, [](FieldReader& f) {
        return Ball{f.number("x"), f.number("y"), f.size("radius")};
    });
}

void PerceptTraits<Ball>::draw(const std::vector<Ball>& balls, Rgb ink, double width,
                               DebugDrawing& out)
{
    for (const Ball& b : balls)
        out.add({ShapeKind::Circle, {{b.x, b.y}}, ink, b.radius, false, width});
}

} // namespace fieldsight

namespace fieldsight {

EditShape PerceptTraits<Ball>::shapeOf(const Ball& b)
{
    return {{{b.x, b.y}}, b.radius};
}

Ball PerceptTraits<Ball>::fromShape(const EditShape& s)
{
    const PointF c = s.points.empty() ? PointF{} : s.points.front();
    return {c.x, c.y, std::max(0.0, s.radius)};
}

std::optional<double> PerceptTraits<Ball>::matchCost(const Ball& detected, const Ball& truth,
                                                     int /*width*/, int /*height*/)
{
    const double distance = std::hypot(detected.x - truth.x, detected.y - truth.y);
    if (distance <= std::max(3.0, 0.5 * truth.radius))
        return distance;
    return std::nullopt;
}

} // namespace fieldsight
