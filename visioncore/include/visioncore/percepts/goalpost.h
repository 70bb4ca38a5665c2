// Goalpost percept: the image box of one post and the point where it meets the field.
#pragma once

#include "visioncore/percepts/percept_set.h"

namespace fieldsight {

enum class GoalpostSide { Unknown, Left, Right };

struct Goalpost
{
    int left = 0;      ///< px, leftmost column of the post (inclusive)
    int right = 0;     ///< px, rightmost column (inclusive)
    int top = 0;       ///< px, top row (inclusive)
    int bottom = 0;    ///< px, bottom row (inclusive)
    double base_x = 0; ///< px, where the post meets the field
    double base_y = 0; ///< px
    GoalpostSide side = GoalpostSide::Unknown;
};

/// In annotations a post has only its box; the base is then the middle of its bottom row.
template <> struct PerceptTraits<Goalpost>
{
    static constexpr std::string_view key = "goalposts";
    static constexpr std::string_view truth_key = key;
    static constexpr std::string_view title = "Goalposts";
    static constexpr Rgb colour{255, 255, 0};
    static void toJson(const std::vector<Goalpost>& posts, PerceptNames names,
                       nlohmann::ordered_json& value);
    static std::optional<std::string> fromJson(const nlohmann::json& value, PerceptNames names,
                                               const std::string& where,
                                               std::vector<Goalpost>& out);
    static constexpr ShapeForm form = ShapeForm::Box;
    static EditShape shapeOf(const Goalpost& object);
    static Goalpost fromShape(const EditShape& shape);
    /// Scored by eval as "goalpost": they match when |detected base_x - true
    /// (left+right)/2| <= max(4 px, true right-left+1) and the detected bottom is within
    /// max(6 px, 10% of the true height) of the true bottom, the latter waived when the true post
    /// touches the image bottom (bottom >= height-1); the nearest (by base_x distance) first.
    static constexpr std::string_view class_name = "goalpost";
    static constexpr int class_order = 2;
    static std::optional<double> matchCost(const Goalpost& detected, const Goalpost& truth,
                                           int width, int height);
    static void draw(const std::vector<Goalpost>& posts, Rgb ink, double width, DebugDrawing& out);
};

} // namespace fieldsight
