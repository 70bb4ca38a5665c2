// Field line percept: one straight white line as an image segment.
#pragma once

#include "visioncore/percepts/percept_set.h"

namespace fieldsight {

struct FieldLine
{
    double x1 = 0; ///< px
    double y1 = 0; ///< px
    double x2 = 0; ///< px
    double y2 = 0; ///< px
};

template <> struct PerceptTraits<FieldLine>
{
    static constexpr std::string_view key = "field_lines";
    static constexpr std::string_view truth_key = key;
    static constexpr std::string_view title = "Field lines";
    static constexpr Rgb colour{255, 0, 0};
    static void toJson(const std::vector<FieldLine>& lines, PerceptNames names,
                       nlohmann::ordered_json& value);
    static std::optional<std::string> fromJson(const nlohmann::json& value, PerceptNames names,
                                               const std::string& where,
                                               std::vector<FieldLine>& out);
    static constexpr ShapeForm form = ShapeForm::Segment;
    static EditShape shapeOf(const FieldLine& object);
    static FieldLine fromShape(const EditShape& shape);
    static void draw(const std::vector<FieldLine>& lines, Rgb ink, double width, DebugDrawing& out);
};

} // namespace fieldsight
