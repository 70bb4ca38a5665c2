// Obstacle percepts in JSON and as a drawing.
#include "visioncore/percepts/obstacle.h"

#include "percepts/percept_json.h"

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

} // namespace fieldsight
