// Field line percepts in JSON and as a drawing.
#include "visioncore/percepts/field_line.h"

#include "percepts/percept_json.h"

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

} // namespace fieldsight
