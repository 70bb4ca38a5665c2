// Field boundary percept: the green horizon's hull as a polyline (the detected boundary), or the
// annotated field boundary (the true one).
#pragma once

#include "visioncore/basics/geometry.h"
#include "visioncore/percepts/percept_set.h"

#include <vector>

namespace fieldsight {

/// A frame has at most one. Its JSON is the bare polyline [[x, y], ...], not a list of objects.
struct FieldBoundary
{
    std::vector<PointF> points; ///< px, x ascending
};

template <> struct PerceptTraits<FieldBoundary>
{
    static constexpr std::string_view key = "green_horizon";
    static constexpr std::string_view truth_key = "field_boundary";
    static constexpr std::string_view title = "Field boundary";
    static constexpr Rgb colour{255, 0, 255};
    static void toJson(const std::vector<FieldBoundary>& boundary, PerceptNames names,
                       nlohmann::ordered_json& value);
    static std::optional<std::string> fromJson(const nlohmann::json& value, PerceptNames names,
                                               const std::string& where,
                                               std::vector<FieldBoundary>& out);
    static constexpr ShapeForm form = ShapeForm::Polyline;
    static EditShape shapeOf(const FieldBoundary& object);
    static FieldBoundary fromShape(const EditShape& shape);
    static void draw(const std::vector<FieldBoundary>& boundary, Rgb ink, double width,
                     DebugDrawing& out);
};

/// The boundary polyline of `set`, or an empty one when it has none.
const std::vector<PointF>& boundaryOf(const PerceptSet& set);

} // namespace fieldsight
