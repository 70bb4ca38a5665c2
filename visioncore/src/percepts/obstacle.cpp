// Obstacle percepts in JSON and as a drawing.
#include "visioncore/percepts/obstacle.h"

#include "percepts/percept_json.h"

#include <algorithm>
#include <cmath>

namespace fieldsight {

using namespace percept_json;

void PerceptTraits<Obstacle>::toJson(const std::vector<Obstacle>& obstacles, PerceptNames,
                                     OrderedJson& value)
{
    writeList(obstacles, value, [](const Obstacle& o) {
        return OrderedJson{
            {"left", o.left}, {"right", o.right}, {"top", o.top}, {"bottom", o.bottom}};
    });
}

std::optional<std::string> PerceptTraits<Obstacle>::fromJson(const Json& value, PerceptNames,
                                                             const std::string& where,
                                                             std::vector<Obstacle>& out)
{
    return readList(value, where, out, [](FieldReader& f) {
        return Obstacle{f.pixel("left"), f.pixel("right"), f.pixel("top"), f.pixel("bottom")};
    });
}

void PerceptTraits<Obstacle>::draw(const std::vector<Obstacle>& obstacles, Rgb ink, double width,
                                   DebugDrawing& out)
{
    for (const Obstacle& o : obstacles)
        out.add({ShapeKind::Rect,
                 {{double(o.left), double(o.top)}, {double(o.right), double(o.bottom)}},
                 ink,
                 width,
                 false,
                 width});
}

} // namespace fieldsight

namespace fieldsight {

EditShape PerceptTraits<Obstacle>::shapeOf(const Obstacle& o)
{
    return {{{double(o.left), double(o.top)}, {double(o.right), double(o.bottom)}}, 0};
}

Obstacle PerceptTraits<Obstacle>::fromShape(const EditShape& s)
{
    const Box box = boxOfShape(s);
    return {box.left, box.right, box.top, box.bottom};
}

double horizontalIou(const Obstacle& a, const Obstacle& b)
{
    const int overlap = std::max(0, std::min(a.right, b.right) - std::max(a.left, b.left) + 1);
    const int union_width = (a.right - a.left + 1) + (b.right - b.left + 1) - overlap;
    return union_width <= 0 ? 0.0 : double(overlap) / double(union_width);
}

std::optional<double> PerceptTraits<Obstacle>::matchCost(const Obstacle& detected,
                                                         const Obstacle& truth, int /*width*/,
                                                         int /*height*/)
{
    const double iou = horizontalIou(detected, truth);
    if (iou >= 0.3)
        return -iou; // the highest overlap is the nearest
    return std::nullopt;
}

} // namespace fieldsight
