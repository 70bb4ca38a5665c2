// The paper's architecture, minus its drawbacks: wrappers as the only doors, a controller that can
// skip stages and survives a throwing stage, and no singletons (two cores side by side).
#include "support/synthetic_frames.h"
#include "visioncore/framework/control_wrapper.h"
#include "visioncore/datawrappers/memory_data_wrapper.h"
#include "visioncore/percepts/ball.h"
#include "visioncore/percepts/field_line.h"
#include "visioncore/percepts/goalpost.h"
#include "visioncore/percepts/obstacle.h"

#include <QtTest>

using namespace fieldsight;

namespace {

class RecordingSink : public DebugSink
{
public:
    std::set<std::string, std::less<>> requestedLayers() const override { return layers; }
    void publish(const DebugCanvas& canvas) override { published = canvas.drawings(); }
    std::set<std::string, std::less<>> layers;
    std::map<std::string, DebugDrawing, std::less<>> published;
};

cv::Mat sceneFrame()
{
    using test::fillCircle;
    using test::fillRect;
    cv::Mat f = test::filledFrame(320, 240, Colour::Unclassified);
    fillRect(f, 0, 60, 319, 239, Colour::Green);
    fillRect(f, 200, 10, 209, 100, Colour::Yellow);
    fillCircle(f, 120, 160, 9, Colour::Orange);
    test::drawLine(f, 0, 200, 319, 180, 3, Colour::White);
    return f;
}

} // namespace

class TestArchitecture : public QObject
{
    Q_OBJECT
private slots:
    void pipelineHasTheSevenStagesInOrder()
    {
        const std::vector<std::string> expected{"green_horizon", "scanlines",   "transitions",
                                                "goalposts",     "field_lines", "ball",
                                                "obstacles"};
        QCOMPARE(Pipeline::standard().ids(), expected);
    }

    void twoCoresInOneProcessGiveIdenticalResults()
    {
        MemoryDataWrapper a(sceneFrame(), test::testLut());
        MemoryDataWrapper b(sceneFrame(), test::testLut());
        ControlWrapper core_a(a);
        ControlWrapper core_b(b);
        QVERIFY(core_a.runFrame().ok());
        // A different frame through b in between must not disturb a (no shared state).
        MemoryDataWrapper other(test::filledFrame(320, 240, Colour::Green), test::testLut());
        ControlWrapper core_c(other);
        QVERIFY(core_c.runFrame().ok());
        QVERIFY(core_b.runFrame().ok());
        const Blackboard& ba = core_a.blackboard();
        const Blackboard& bb = core_b.blackboard();
        QCOMPARE(ba.percepts.list<Ball>().size(), std::size_t(1));
        QCOMPARE(bb.percepts.list<Ball>().size(), ba.percepts.list<Ball>().size());
        QCOMPARE(bb.percepts.list<Ball>()[0].x, ba.percepts.list<Ball>()[0].x);
        QCOMPARE(bb.percepts.list<Ball>()[0].radius, ba.percepts.list<Ball>()[0].radius);
        QCOMPARE(bb.percepts.list<Goalpost>().size(), ba.percepts.list<Goalpost>().size());
        QCOMPARE(bb.percepts.list<FieldLine>().size(), ba.percepts.list<FieldLine>().size());
        QCOMPARE(bb.green_horizon.hull(), ba.green_horizon.hull());
        QCOMPARE(core_c.blackboard().percepts.list<Ball>().size(), std::size_t(0));
    }

    void skippedStageProducesNothingAndIsNotTimed()
    {
        MemoryDataWrapper data(sceneFrame(), test::testLut());
        ControlWrapper core(data);
        QVERIFY(core.setStageEnabled("ball", false).ok());
        auto report = core.runFrame();
        QVERIFY(report.ok());
        QCOMPARE(core.blackboard().percepts.list<Ball>().size(), std::size_t(0));
        QVERIFY(!core.blackboard().percepts.list<Goalpost>().empty());
        for (const StageTiming& t : report.value().stages)
            QCOMPARE(t.ran, t.stage != "ball");
        QVERIFY(core.setStageEnabled("ball", true).ok());
        QVERIFY(core.runFrame().ok());
        QCOMPARE(core.blackboard().percepts.list<Ball>().size(), std::size_t(1));
    }

    void refusesToSkipStagesOthersNeed()
    {
        MemoryDataWrapper data(sceneFrame(), test::testLut());
        ControlWrapper core(data);
        QVERIFY(!core.setStageEnabled("scanlines", false).ok());
        QVERIFY(!core.setStageEnabled("no_such_stage", false).ok());
        QVERIFY(core.stageEnabled("scanlines"));
    }

    void stageExceptionBecomesDiagnostic()
    {
        // A stage that throws, between two that work: the frame goes on, the throw is recorded.
        class Throwing : public Stage
        {
        public:
            const StageInfo& info() const override
            {
                static const StageInfo i{"thrower", "Thrower", "Always throws.", true, {}, {},
                                         {},        {}};
                return i;
            }
            void run(Blackboard&) override { throw std::runtime_error("bad input to thrower"); }
        };
        Pipeline pipeline = Pipeline::standard();
        pipeline.add([] { return std::make_unique<Throwing>(); }, 3);
        Controller controller(pipeline);
        Blackboard bb;
        const cv::Mat image = sceneFrame();
        const ColourLut lut = test::testLut();
        bb.beginFrame(image, lut, {});
        const FrameReport report = controller.runFrame(bb, {});
        QCOMPARE(bb.diagnostics.size(), std::size_t(1));
        QCOMPARE(bb.diagnostics[0].stage, std::string("thrower"));
        QCOMPARE(bb.diagnostics[0].message, std::string("bad input to thrower"));
        QCOMPARE(report.stages.size(), std::size_t(8));
        QVERIFY(report.stages[3].ran);
        QCOMPARE(bb.percepts.list<Ball>().size(),
                 std::size_t(1)); // stages after the throw still ran
    }

    void refusesOutOfRangeParametersAndEmptyFrames()
    {
        MemoryDataWrapper data(sceneFrame(), test::testLut());
        ControlWrapper core(data);
        // Out of range is refused by the parameter registry...
        QVERIFY(!core.setParam("goalposts", "matching_tolerance", 5).ok());
        QVERIFY(core.setParam("goalposts", "matching_tolerance", 0.2).ok());
        // ...and an empty frame is refused at the wrapper, not crashed on.
        MemoryDataWrapper empty(cv::Mat(), test::testLut());
        ControlWrapper empty_core(empty);
        auto r = empty_core.runFrame();
        QVERIFY(!r.ok());
        QVERIFY(QString::fromStdString(r.error().message).contains("no frame"));
    }

    void debugLayersAreDrawnOnlyWhenRequested()
    {
        MemoryDataWrapper data(sceneFrame(), test::testLut());
        RecordingSink sink;
        data.setDebugSink(&sink);
        ControlWrapper core(data);
        QVERIFY(core.runFrame().ok());
        QVERIFY(sink.published.empty());
        sink.layers = {"green_horizon.scan_points", "ball.edge_points"};
        QVERIFY(core.runFrame().ok());
        QCOMPARE(sink.published.size(), std::size_t(2));
        const DebugDrawing& edges = sink.published.at("ball.edge_points");
        QCOMPARE(edges.shapes.size(), std::size_t(1));
        QCOMPARE(edges.shapes[0].kind, ShapeKind::Points);
        // The ball's edge points lie on its outline (radius 9 around (120, 160)).
        QVERIFY(edges.shapes[0].points.size() >= 8);
        for (const PointF& p : edges.shapes[0].points)
            QVERIFY(std::abs(std::hypot(p.x - 120, p.y - 160) - 9) < 1.5);
    }

    void everyStageDeclaresIdLayersAndParams()
    {
        for (const StageDescriptor& d : Pipeline::standard().descriptors()) {
            QVERIFY(!d.info.id.empty());
            QVERIFY(!d.info.description.empty());
            QVERIFY(!d.info.layers.empty());
            QVERIFY(!d.params.empty());
            for (const ParamInfo& p : d.params) {
                QVERIFY2(!p.description.empty(), p.name.c_str());
                QVERIFY2(p.min <= p.default_value && p.default_value <= p.max, p.name.c_str());
                QCOMPARE(p.value, p.default_value);
                QVERIFY(p.step > 0);
            }
        }
        QVERIFY(Pipeline::standard().validate().ok());
    }

    void blackboardReadsAreCheckedAgainstEarlierWrites()
    {
        // The ball stage moved before the scan lines reads slots nobody has written yet.
        // The standard pipeline's own stages, picked by id.
        const auto factoryOf = [&](const std::string& id) {
            return [id]() {
                for (auto& stage : Pipeline::standard().build())
                    if (stage->info().id == id)
                        return std::move(stage);
                return std::unique_ptr<Stage>();
            };
        };
        Pipeline reordered;
        reordered.add(factoryOf("green_horizon")).add(factoryOf("ball"));
        const Status s = reordered.validate();
        QVERIFY(!s.ok());
        QVERIFY2(QString::fromStdString(s.error().message).contains("'ball' reads"),
                 s.error().message.c_str());
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument, Controller{reordered});
        // A stage listed twice is refused too.
        Pipeline twice = Pipeline::standard();
        twice.add(factoryOf("obstacles"));
        QVERIFY(!twice.validate().ok());
    }

    void skippedStageListsAreAbsentAndRunStagesPresentEvenWhenEmpty()
    {
        MemoryDataWrapper data(test::filledFrame(320, 240, Colour::Green), test::testLut());
        ControlWrapper core(data);
        QVERIFY(core.setStageEnabled("obstacles", false).ok());
        QVERIFY(core.runFrame().ok());
        const PerceptSet& p = core.blackboard().percepts;
        QVERIFY(p.find<Obstacle>() == nullptr);
        QVERIFY(p.find<Ball>() != nullptr);
        QCOMPARE(p.find<Ball>()->size(), std::size_t(0));
        // Lists come in pipeline order, whatever ran first.
        std::vector<std::string> keys;
        for (const PerceptEntry* e : p.entries())
            keys.emplace_back(e->kind().key);
        const std::vector<std::string> expected{"green_horizon", "goalposts", "field_lines",
                                                "balls"};
        QCOMPARE(keys, expected);
    }

    void aStageWritingAnUndeclaredPerceptGetsADiagnostic()
    {
        class Sneaky : public Stage
        {
        public:
            const StageInfo& info() const override
            {
                static const StageInfo i{"sneaky", "Sneaky", "Writes balls.", true, {}, {}, {}, {}};
                return i;
            }
            void run(Blackboard& bb) override { bb.percepts.output<Ball>().push_back({1, 2, 3}); }
        };
        Pipeline pipeline;
        pipeline.add([] { return std::make_unique<Sneaky>(); });
        MemoryDataWrapper data(sceneFrame(), test::testLut());
        ControlWrapper core(data, pipeline);
        QVERIFY(core.runFrame().ok());
        QCOMPARE(core.blackboard().diagnostics.size(), std::size_t(1));
        QCOMPARE(core.blackboard().diagnostics[0].stage, std::string("sneaky"));
    }

    void parametersAreTypedWithDefaultsAndReset()
    {
        MemoryDataWrapper data(sceneFrame(), test::testLut());
        ControlWrapper core(data);
        const auto param = [&](const std::string& stage, const std::string& name) {
            for (const StageDescriptor& d : core.stages())
                if (d.info.id == stage)
                    for (const ParamInfo& p : d.params)
                        if (p.name == name)
                            return p;
            return ParamInfo{};
        };
        QCOMPARE(param("ball", "iterations").kind, ParamKind::Integer);
        QCOMPARE(param("ball", "min_radius").kind, ParamKind::Real);
        QCOMPARE(param("ball", "min_radius").unit, std::string("px"));
        const ParamInfo goal = param("transitions", "goal_colour");
        QCOMPARE(goal.kind, ParamKind::Choice);
        QCOMPARE(goal.choices.size(), std::size_t(kColourCount));
        QCOMPARE(goal.choices[9].name, std::string("blue"));
        QCOMPARE(goal.default_value, double(Colour::Yellow));
        // Whole numbers only for integers and choices.
        QVERIFY(!core.setParam("ball", "iterations", 2.5).ok());
        QVERIFY(!core.setParam("transitions", "goal_colour", 8.5).ok());
        QVERIFY(core.setParam("transitions", "goal_colour", 9).ok());
        QVERIFY(core.setParam("ball", "iterations", 7).ok());
        QCOMPARE(param("ball", "iterations").value, 7.0);
        core.resetParams();
        QCOMPARE(param("ball", "iterations").value, 100.0);
        QCOMPARE(param("transitions", "goal_colour").value, double(Colour::Yellow));
    }

    void paramSetRoundTripsThroughJsonAndAppliesAllOrNothing()
    {
        ParamSet set;
        QVERIFY(set.parseSetting("transitions.goal_colour=9").ok());
        QVERIFY(set.parseSetting("ball.min_radius=3.5").ok());
        QVERIFY(!set.parseSetting("ball.min_radius=abc").ok());
        QVERIFY(!set.parseSetting("min_radius=3").ok());
        auto back = ParamSet::fromJson(set.toJson(), "params.json");
        QVERIFY(back.ok());
        QCOMPARE(back.value().values, set.values);
        QVERIFY(set.check(Pipeline::standard()).ok());

        MemoryDataWrapper data(sceneFrame(), test::testLut());
        ControlWrapper core(data);
        QVERIFY(core.applyParams(set).ok());
        QCOMPARE(core.params().values.at("ball").at("min_radius"), 3.5);
        QCOMPARE(core.params().values.at("transitions").at("goal_colour"), 9.0);

        // One bad value: nothing of the set is applied.
        ParamSet bad;
        bad.set("ball", "min_radius", 4.5);
        bad.set("goalposts", "matching_tolerance", 7); // outside [0, 1]
        const Status s = core.applyParams(bad);
        QVERIFY(!s.ok());
        QVERIFY(QString::fromStdString(s.error().message).contains("goalposts.matching_tolerance"));
        QCOMPARE(core.params().values.at("ball").at("min_radius"), 3.5);
        QVERIFY(!bad.check(Pipeline::standard()).ok());

        QVERIFY(!ParamSet::fromJson("{}", "p.json").ok());
        QVERIFY(!ParamSet::fromJson(R"({"format": "fieldsight-params/1", "stages": {"ball": 3}})",
                                    "p.json")
                     .ok());
    }
};

QTEST_APPLESS_MAIN(TestArchitecture)
#include "test_architecture.moc"
