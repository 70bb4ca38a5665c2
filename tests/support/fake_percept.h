// A percept kind for tests, in this one place: its struct, its traits (names, JSON, drawing,
// shape, matching rule and scored class) and the stage that detects it, added to the pipeline by a
// test alone (one Pipeline::add call). Evaluation, the eval command, the evaluation panel, COCO
// export and the annotation tools take it from the registry with no change of theirs.
#pragma once

#include "visioncore/framework/blackboard.h"
#include "visioncore/framework/controller.h"

#include <nlohmann/json.hpp>

#include <cmath>

namespace fieldsight::test {

/// A round spot: the fake stage sees one per frame at kFakeSpotSeen.
struct FakeSpot
{
    double x = 0;      ///< px, centre
    double y = 0;      ///< px, centre
    double radius = 0; ///< px
};

inline constexpr FakeSpot kFakeSpotSeen{40, 30, 4};
/// Spots match when their centres are at most this far apart, px.
inline constexpr double kFakeSpotReach = 5;

} // namespace fieldsight::test

template <> struct fieldsight::PerceptTraits<fieldsight::test::FakeSpot>
{
    static constexpr std::string_view key = "fake_spots";
    static constexpr std::string_view truth_key = key;
    static constexpr std::string_view title = "Fake spots";
    static constexpr Rgb colour{20, 220, 240};
    static void toJson(const std::vector<test::FakeSpot>& spots, PerceptNames,
                       nlohmann::ordered_json& value)
    {
        value = nlohmann::ordered_json::array();
        for (const test::FakeSpot& s : spots)
            value.push_back({{"x", s.x}, {"y", s.y}, {"radius", s.radius}});
    }
    static std::optional<std::string> fromJson(const nlohmann::json& value, PerceptNames,
                                               const std::string& where,
                                               std::vector<test::FakeSpot>& out)
    {
        if (!value.is_array())
            return where + " must be an array";
        for (const auto& s : value) {
            if (!s.is_object())
                return where + "[] must be an object";
            out.push_back({s.value("x", 0.0), s.value("y", 0.0), s.value("radius", 0.0)});
        }
        return std::nullopt;
    }
    static void draw(const std::vector<test::FakeSpot>& spots, Rgb ink, double width,
                     DebugDrawing& out)
    {
        for (const test::FakeSpot& s : spots)
            out.add({ShapeKind::Circle, {{s.x, s.y}}, ink, s.radius, false, width});
    }
    static constexpr ShapeForm form = ShapeForm::Circle;
    static EditShape shapeOf(const test::FakeSpot& s) { return {{{s.x, s.y}}, s.radius}; }
    static test::FakeSpot fromShape(const EditShape& shape)
    {
        const PointF c = shape.points.empty() ? PointF{} : shape.points.front();
        return {c.x, c.y, shape.radius};
    }
    /// Scored by eval as "fake_spot", after the standard classes: centres within
    /// kFakeSpotReach, the nearest first.
    static constexpr std::string_view class_name = "fake_spot";
    static constexpr int class_order = 100;
    static std::optional<double> matchCost(const test::FakeSpot& detected,
                                           const test::FakeSpot& truth, int, int)
    {
        const double distance = std::hypot(detected.x - truth.x, detected.y - truth.y);
        return distance <= test::kFakeSpotReach ? std::optional<double>(distance) : std::nullopt;
    }
};

namespace fieldsight::test {

/// Sees kFakeSpotSeen in every frame.
class FakeSpotStage : public Stage
{
public:
    const StageInfo& info() const override
    {
        static const StageInfo info{"fake_spots",
                                    "Fake spots",
                                    "A test stage: sees one spot per frame.",
                                    true,
                                    {},
                                    {},
                                    {&perceptKind<FakeSpot>()},
                                    {}};
        return info;
    }
    void run(Blackboard& bb) override { bb.percepts.output<FakeSpot>().push_back(kFakeSpotSeen); }
};

/// The standard pipeline and the fake spot stage (the line stage_list.cpp would get).
inline Pipeline withFakePercept()
{
    Pipeline pipeline = Pipeline::standard();
    pipeline.add<FakeSpotStage>();
    return pipeline;
}

} // namespace fieldsight::test
