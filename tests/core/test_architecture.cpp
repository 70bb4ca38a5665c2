// The paper's architecture, minus its drawbacks: wrappers as the only doors, a controller that can
// skip stages and survives a throwing stage, and no singletons (two cores side by side).
#include "support/synthetic_frames.h"
#include "visioncore/control_wrapper.h"

#include <QtTest>

using namespace fieldsight;

namespace {

/// A DataWrapper over one in-memory frame.
class MemoryDataWrapper : public DataWrapper
{
public:
    MemoryDataWrapper(cv::Mat image, ColourLut lut) : m_image(std::move(image)), m_lut(std::move(lut)) {}
    const cv::Mat& image() const override { return m_image; }
    Horizon kinematicHorizon() const override { return {}; }
    const ColourLut& lut() const override { return m_lut; }
    DebugSink* debugSink() override { return m_sink; }
    DebugSink* m_sink = nullptr;

private:
    cv::Mat m_image;
    ColourLut m_lut;
};

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
        const std::vector<std::string> expected{"green_horizon", "scanlines", "transitions",
                                                "goalposts", "field_lines", "ball", "obstacles"};
        QCOMPARE(pipelineStageIds(), expected);
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
        QCOMPARE(ba.balls.size(), std::size_t(1));
        QCOMPARE(bb.balls.size(), ba.balls.size());
        QCOMPARE(bb.balls[0].x, ba.balls[0].x);
        QCOMPARE(bb.balls[0].radius, ba.balls[0].radius);
        QCOMPARE(bb.goalposts.size(), ba.goalposts.size());
        QCOMPARE(bb.field_lines.size(), ba.field_lines.size());
        QCOMPARE(bb.green_horizon.hull(), ba.green_horizon.hull());
        QCOMPARE(core_c.blackboard().balls.size(), std::size_t(0));
    }

    void skippedStageProducesNothingAndIsNotTimed()
    {
        MemoryDataWrapper data(sceneFrame(), test::testLut());
        ControlWrapper core(data);
        QVERIFY(core.setStageEnabled("ball", false).ok());
        auto report = core.runFrame();
        QVERIFY(report.ok());
        QCOMPARE(core.blackboard().balls.size(), std::size_t(0));
        QVERIFY(!core.blackboard().goalposts.empty());
        for (const StageTiming& t : report.value().stages)
            QCOMPARE(t.ran, t.stage != "ball");
        QVERIFY(core.setStageEnabled("ball", true).ok());
        QVERIFY(core.runFrame().ok());
        QCOMPARE(core.blackboard().balls.size(), std::size_t(1));
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
                static const StageInfo i{"thrower", "Thrower", true, {}, {}, {}};
                return i;
            }
            void run(Blackboard&) override { throw std::runtime_error("bad input to thrower"); }
        };
        std::vector<std::unique_ptr<Stage>> stages = makePipelineStages();
        stages.insert(stages.begin() + 3, std::make_unique<Throwing>());
        Controller controller(std::move(stages));
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
        QCOMPARE(bb.balls.size(), std::size_t(1)); // stages after the throw still ran
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
        data.m_sink = &sink;
        ControlWrapper core(data);
        QVERIFY(core.runFrame().ok());
        QVERIFY(sink.published.empty());
        sink.layers = {"green_horizon.hull", "ball.balls"};
        QVERIFY(core.runFrame().ok());
        QCOMPARE(sink.published.size(), std::size_t(2));
        const DebugDrawing& ball = sink.published.at("ball.balls");
        QCOMPARE(ball.shapes.size(), std::size_t(1));
        QCOMPARE(ball.shapes[0].kind, ShapeKind::Circle);
        QVERIFY(std::abs(ball.shapes[0].points[0].x - 120) < 1.0);
    }

    void everyStageDeclaresIdLayersAndParams()
    {
        Controller c;
        for (const auto& s : c.stages()) {
            const StageInfo& info = s->info();
            QVERIFY(!info.id.empty());
            QVERIFY(!info.layers.empty());
            for (const LayerInfo& l : info.layers)
                QVERIFY2(l.id.rfind(info.id + ".", 0) == 0, l.id.c_str());
            QVERIFY(!s->params().empty());
        }
    }
};

QTEST_APPLESS_MAIN(TestArchitecture)
#include "test_architecture.moc"
