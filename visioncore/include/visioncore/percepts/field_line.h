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

/// The field line rule (docs/formats.md, an extension of SPEC §5.3): with S the shorter segment
/// and L the longer, both ends of S lie within max(4 px, 5% of L's length) of the straight line
/// through L, and S's projection onto L overlaps L over at least half S's projected length. The
/// cost (mean distance of S's ends from L's line, px) when they match, else a negative value.
/// Symmetric in its arguments.
double fieldLineMatchCost(const FieldLine& a, const FieldLine& b);

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
    /// Scored by eval as "field_line": they match by fieldLineMatchCost(), the
    /// smallest cost first.
    static constexpr std::string_view class_name = "field_line";
    static constexpr int class_order = 4;
    static std::optional<double> matchCost(const FieldLine& detected, const FieldLine& truth,
                                           int width, int height);
    static void draw(const std::vector<FieldLine>& lines, Rgb ink, double width, DebugDrawing& out);
};

} // namespace fieldsight
