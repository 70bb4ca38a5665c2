// An eighth stage for tests: a parameter, a debug layer and a percept kind of its own, added to
// the pipeline by a test alone (one Pipeline::add call, the line stage_list.cpp would get).
#pragma once

#include "visioncore/framework/blackboard.h"
#include "visioncore/framework/controller.h"

#include <nlohmann/json.hpp>

#include <stdexcept>

namespace fieldsight::test {

/// The fake stage's percept: one mark per frame carrying its parameter's value.
struct FakeMark
{
    double x = 0;     ///< px
    double y = 0;     ///< px
    double value = 0; ///< the stage's `level` parameter
};

} // namespace fieldsight::test

template <> struct fieldsight::PerceptTraits<fieldsight::test::FakeMark>
{
    static constexpr std::string_view key = "fake_marks";
    static constexpr std::string_view truth_key = key;
    static constexpr std::string_view title = "Fake marks";
    static constexpr Rgb colour{12, 200, 34};
    static void toJson(const std::vector<test::FakeMark>& marks, PerceptNames,
                       nlohmann::ordered_json& value)
    {
        value = nlohmann::ordered_json::array();
        for (const test::FakeMark& m : marks)
            value.push_back({{"x", m.x}, {"y", m.y}, {"value", m.value}});
    }
    static std::optional<std::string> fromJson(const nlohmann::json& value, PerceptNames,
                                               const std::string& where,
                                               std::vector<test::FakeMark>& out)
    {
        if (!value.is_array())
            return where + " must be an array";
        for (const auto& m : value)
            out.push_back({m.value("x", 0.0), m.value("y", 0.0), m.value("value", 0.0)});
        return std::nullopt;
    }
    static void draw(const std::vector<test::FakeMark>& marks, Rgb colour, double,
                     DebugDrawing& out)
    {
        for (const test::FakeMark& m : marks)
            out.add({ShapeKind::Points, {{m.x, m.y}}, colour, 5, true, 1});
    }
};

namespace fieldsight::test {

constexpr Rgb kFakeLayerColour{250, 10, 200};

class FakeStage : public Stage
{
public:
    const StageInfo& info() const override
    {
        static const StageInfo info{"fake",
                                    "Fake",
                                    "A test stage: marks one point and fills one box.",
                                    true,
                                    {"green_horizon"},
                                    {},
                                    {&perceptKind<FakeMark>()},
                                    {{"fake.box", "Fake box", kFakeLayerColour}}};
        return info;
    }
    void run(Blackboard& bb) override
    {
        if (m_fail)
            throw std::runtime_error("failed on purpose");
        bb.percepts.output<FakeMark>().push_back({40, 30, m_level});
        if (auto* d = bb.debug.layer("fake.box"))
            d->add({ShapeKind::Rect, {{10, 10}, {19, 19}}, kFakeLayerColour, 1, true, 1});
    }

private:
    Param<double> m_level{this, 1.5, {"level", "", 0, 10, 0.5, "Written into every mark."}};
    Param<bool> m_fail{this, false, {"fail", "", 0, 1, 1, "Throws instead of marking."}};
};

inline Pipeline withFakeStage()
{
    Pipeline pipeline = Pipeline::standard();
    pipeline.add<FakeStage>();
    return pipeline;
}

} // namespace fieldsight::test
