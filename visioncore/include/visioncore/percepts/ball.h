// Ball percept: where a ball was seen in the image.
#pragma once

#include "visioncore/percepts/percept_set.h"

namespace fieldsight {

struct Ball
{
    double x = 0;      ///< px, centre
    double y = 0;      ///< px, centre
    double radius = 0; ///< px
};

template <> struct PerceptTraits<Ball>
{
    static constexpr std::string_view key = "balls";
    static constexpr std::string_view truth_key = key;
    static constexpr std::string_view title = "Balls";
    static constexpr Rgb colour{255, 160, 0};
    static void toJson(const std::vector<Ball>& balls, PerceptNames names,
                       nlohmann::ordered_json& value);
    static std::optional<std::string> fromJson(const nlohmann::json& value, PerceptNames names,
                                               const std::string& where, std::vector<Ball>& out);
    static constexpr ShapeForm form = ShapeForm::Circle;
    static EditShape shapeOf(const Ball& object);
    static Ball fromShape(const EditShape& shape);
    /// Scored by eval as "ball": they match when the centre distance is <=
    /// max(3 px, 0.5 x true radius), the nearest (by that distance) first.
    static constexpr std::string_view class_name = "ball";
    static constexpr int class_order = 1;
    static std::optional<double> matchCost(const Ball& detected, const Ball& truth, int width,
                                           int height);
    static void draw(const std::vector<Ball>& balls, Rgb ink, double width, DebugDrawing& out);
};

} // namespace fieldsight
