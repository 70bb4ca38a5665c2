// An eighth stage for tests: a parameter, a debug layer and a percept kind of its own, added to
// the pipeline by a test alone (one Pipeline::add call, the line stage_list.cpp would get).
#pragma once

#include "visioncore/framework/blackboard.h"
#include "visioncore/framework/controller.h"

#include <nlohmann/json.hpp>

#include <cmath>
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
    static void draw(const std::vector<test::FakeMark>& marks, Rgb ink, double, DebugDrawing& out)
    {
        for (const test::FakeMark& m : marks)
            out.add({ShapeKind::Points, {{m.x, m.y}}, ink, 5, true, 1});
    }
};

namespace fieldsight::test {

constexpr Rgb kFakeLayerColour{250, 10, 200};

class FakeStage : public Stage
{
public:
    enum Fault { kNoFault, kThrows, kNotANumber, kFarOutside };

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
        // Faults on every `every`-th frame this stage runs (frame order on one core).
        const int fault = m_runs++ % m_every == m_every - 1 ? int(m_fault) : kNoFault;
        if (fault == kThrows)
            throw std::runtime_error("failed on purpose");
        const double x = fault == kNotANumber ? std::nan("") : fault == kFarOutside ? 1e7 : 40.0;
        bb.percepts.output<FakeMark>().push_back({x, 30, m_level});
        if (auto* d = bb.debug.layer("fake.box"))
            d->add({ShapeKind::Rect, {{10, 10}, {19, 19}}, kFakeLayerColour, 1, true, 1});
    }

private:
    Param<double> m_level{this, 1.5, {"level", "", 0, 10, 0.5, "Written into every mark."}};
    Param<int> m_fault{this,
                       kNoFault,
                       {"fault", "", 0, 3, 1,
                        "0 none; 1 throws; 2 marks at x = NaN; 3 marks at "
                        "x = 10^7 px (a faulty stage's nonsense)."}};
    Param<int> m_every{
        this, 1, {"every", "frames", 1, 100, 1, "The fault strikes every Nth frame."}};
    int m_runs = 0;
};

inline Pipeline withFakeStage()
{
    Pipeline pipeline = Pipeline::standard();
    pipeline.add<FakeStage>();
    return pipeline;
}

} // namespace fieldsight::test
