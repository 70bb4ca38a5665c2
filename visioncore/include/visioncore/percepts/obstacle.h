// Obstacle percept: an image box of something standing on the field (robots, people).
#pragma once

#include "visioncore/percepts/percept_set.h"

namespace fieldsight {

struct Obstacle
{
    int left = 0;   ///< px, inclusive
    int right = 0;  ///< px, inclusive
    int top = 0;    ///< px, inclusive
    int bottom = 0; ///< px, inclusive; where it stands on the field
};

/// Horizontal intersection over union of two obstacles' inclusive column ranges, in [0, 1].
double horizontalIou(const Obstacle& a, const Obstacle& b);

template <> struct PerceptTraits<Obstacle>
{
    static constexpr std::string_view key = "obstacles";
    static constexpr std::string_view truth_key = key;
    static constexpr std::string_view title = "Obstacles";
    static constexpr Rgb colour{170, 60, 255};
    static void toJson(const std::vector<Obstacle>& obstacles, PerceptNames names,
                       nlohmann::ordered_json& value);
    static std::optional<std::string> fromJson(const nlohmann::json& value, PerceptNames names,
                                               const std::string& where,
                                               std::vector<Obstacle>& out);
    static constexpr ShapeForm form = ShapeForm::Box;
    static EditShape shapeOf(const Obstacle& object);
    static Obstacle fromShape(const EditShape& shape);
    /// Scored by eval as "obstacle": they match when horizontalIou() >= 0.3, the
    /// highest first.
    static constexpr std::string_view class_name = "obstacle";
    static constexpr int class_order = 3;
    static std::optional<double> matchCost(const Obstacle& detected, const Obstacle& truth,
                                           int width, int height);
    static void draw(const std::vector<Obstacle>& obstacles, Rgb ink, double width,
                     DebugDrawing& out);
};

} // namespace fieldsight
