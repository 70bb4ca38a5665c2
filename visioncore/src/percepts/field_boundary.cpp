// The field boundary in JSON (a bare polyline) and as a drawing.
#include "visioncore/percepts/field_boundary.h"

#include "percepts/percept_json.h"

#include <algorithm>

namespace fieldsight {

using namespace percept_json;

void PerceptTraits<FieldBoundary>::toJson(const std::vector<FieldBoundary>& boundary, PerceptNames,
                                          OrderedJson& value)
{
    value = OrderedJson::array();
    if (boundary.empty())
        return;
    for (const PointF& p : boundary.front().points)
        value.push_back(OrderedJson::array({px(p.x), px(p.y)}));
}

std::optional<std::string> PerceptTraits<FieldBoundary>::fromJson(const Json& value, PerceptNames,
                                                                  const std::string& where,
                                                                  std::vector<FieldBoundary>& out)
{
    if (!value.is_array())
        return where + " must be an array";
    FieldBoundary boundary;
    for (std::size_t i = 0; i < value.size(); ++i) {
        const Json& item = value[i];
        if (!item.is_array() || item.size() != 2 || !item[0].is_number() || !item[1].is_number())
            return where + "[" + std::to_string(i) + "] must be [x, y]";
        if (!percept_json::saneCoordinate(item[0].get<double>()) ||
            !percept_json::saneCoordinate(item[1].get<double>()))
            return where + "[" + std::to_string(i) + "] must be within ±1000000 px";
        boundary.points.push_back(PointF{item[0].get<double>(), item[1].get<double>()});
    }
    out.push_back(std::move(boundary));
    return std::nullopt;
}

void PerceptTraits<FieldBoundary>::draw(const std::vector<FieldBoundary>& boundary, Rgb ink,
                                        double width, DebugDrawing& out)
{
    for (const FieldBoundary& b : boundary)
        out.add({ShapeKind::Polyline, b.points, ink, width, false, width});
}

const std::vector<PointF>& boundaryOf(const PerceptSet& set)
{
    static const std::vector<PointF> none;
    const auto& list = set.list<FieldBoundary>();
    return list.empty() ? none : list.front().points;
}

} // namespace fieldsight

namespace fieldsight {

EditShape PerceptTraits<FieldBoundary>::shapeOf(const FieldBoundary& b)
{
    return {b.points, 0};
}

FieldBoundary PerceptTraits<FieldBoundary>::fromShape(const EditShape& s)
{
    FieldBoundary b{s.points};
    std::stable_sort(b.points.begin(), b.points.end(),
                     [](const PointF& a, const PointF& c) { return a.x < c.x; });
    return b;
}

} // namespace fieldsight
