// The paper's architecture, minus its drawbacks: wrappers as the only doors, a controller that can
// skip stages and survives a throwing stage, no singletons (two cores side by side), and the
// core's layers as folders that include only downwards.
#include "support/test_suite.h"
#include "support/recording_sink.h"
#include "support/synthetic_frames.h"
#include "visioncore/framework/control_wrapper.h"
#include "visioncore/datawrappers/memory_data_wrapper.h"
#include "visioncore/percepts/ball.h"
#include "visioncore/percepts/field_line.h"
#include "visioncore/percepts/goalpost.h"
#include "visioncore/percepts/obstacle.h"

#include <QtTest>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

using namespace fieldsight;

namespace {

namespace fs = std::filesystem;

/// The core's layers, lowest first, as `file` lists them (visioncore/layers.txt: one a line, `#`
/// starts a comment); empty when the file cannot be read.
std::vector<std::string> readLayers(const fs::path& file)
{
    std::vector<std::string> layers;
    std::ifstream in(file);
    std::string line;
    while (std::getline(in, line)) {
        line = line.substr(0, line.find('#'));
        const auto first = line.find_first_not_of(" \t\r");
        if (first == std::string::npos)
            continue;
        layers.push_back(line.substr(first, line.find_last_not_of(" \t\r") - first + 1));
    }
    return layers;
}

/// The core's own list of layers.
const std::vector<std::string>& coreLayers()
{
    static const std::vector<std::string> layers =
        readLayers(fs::path(FIELDSIGHT_SOURCE_DIR) / "visioncore" / "layers.txt");
    return layers;
}

/// The position of `folder` in `layers`, lowest first; -1 when it is not a layer.
int rankOf(const std::vector<std::string>& layers, const std::string& folder)
{
    const auto it = std::find(layers.begin(), layers.end(), folder);
    return it == layers.end() ? -1 : int(it - layers.begin());
}

/// The layer an include path names: "visioncore/io/frame.h" (public) and "io/strm_format.h"
/// (private to the core) are both "io"; empty for anything else.
std::string layerOfInclude(const std::vector<std::string>& layers, std::string path)
{
    if (path.rfind("visioncore/", 0) == 0)
        path.erase(0, std::string("visioncore/").size());
    const auto slash = path.find('/');
    if (slash == std::string::npos)
        return {};
    const std::string layer = path.substr(0, slash);
    return rankOf(layers, layer) >= 0 ? layer : std::string();
}

/// Every quoted include of a file under `core` (a visioncore folder: include/visioncore/<layer>
/// and src/<layer>) that names a layer after the file's own in `layers`, as "<file>: <include>".
/// Loose headers at include/visioncore/ and folders that are in no layer are reported too.
std::vector<std::string> layerViolations(const fs::path& core,
                                         const std::vector<std::string>& layers)
{
    std::vector<std::string> problems;
    const auto check = [&](const fs::path& root) {
        std::error_code ec;
        for (auto it = fs::recursive_directory_iterator(root, ec);
             !ec && it != fs::recursive_directory_iterator(); it.increment(ec)) {
            const fs::path& file = it->path();
            const fs::path relative = file.lexically_relative(root);
            if (it.depth() == 0 && it->is_directory() && rankOf(layers, relative.string()) < 0) {
                problems.push_back(file.string() + ": a folder in no layer");
                continue;
            }
            if (!it->is_regular_file() || (file.extension() != ".h" && file.extension() != ".cpp"))
                continue;
            if (it.depth() == 0) {
                if (root.filename() == "visioncore")
                    problems.push_back(file.string() + ": a header in no layer");
                continue;
            }
            const int own = rankOf(layers, relative.begin()->string());
            if (own < 0)
                continue;
            std::ifstream in(file);
            std::string line;
            while (std::getline(in, line)) {
                const auto open = line.find("#include \"");
                if (open == std::string::npos)
                    continue;
                const auto start = open + std::string("#include \"").size();
                const std::string included = line.substr(start, line.find('"', start) - start);
                if (rankOf(layers, layerOfInclude(layers, included)) > own)
                    problems.push_back(file.string() + ": " + included);
            }
        }
    };
    check(core / "include" / "visioncore");
    check(core / "src");
    return problems;
}

/// Writes `text` to `path`, making its folder.
void writeFile(const fs::path& path, const std::string& text)
{
    fs::create_directories(path.parent_path());
    std::ofstream(path) << text;
}

using test::RecordingSink;

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
    void layersIncludeOnlyDownwards()
    {
        const fs::path core = fs::path(FIELDSIGHT_SOURCE_DIR) / "visioncore";
        QVERIFY(fs::is_directory(core / "include" / "visioncore" / "basics"));
        QVERIFY(rankOf(coreLayers(), "basics") == 0);
        std::string all;
        for (const std::string& problem : layerViolations(core, coreLayers()))
            all += problem + "\n";
        QVERIFY2(all.empty(), all.c_str());
    }

    void readmeTableKeepsTheLayerOrder()
    {
        // The README's table names the public layer folders in the list's order, each once.
        std::ifstream in(fs::path(FIELDSIGHT_SOURCE_DIR) / "README.md");
        QVERIFY(in.good());
        const std::string prefix = "| `visioncore/include/visioncore/";
        std::vector<std::string> rows;
        std::string line;
        while (std::getline(in, line))
            if (line.rfind(prefix, 0) == 0)
                rows.push_back(
                    line.substr(prefix.size(), line.find('/', prefix.size()) - prefix.size()));
        std::vector<std::string> expected;
        const fs::path include =
            fs::path(FIELDSIGHT_SOURCE_DIR) / "visioncore" / "include" / "visioncore";
        for (const std::string& layer : coreLayers())
            if (fs::is_directory(include / layer))
                expected.push_back(layer);
        const auto join = [](const std::vector<std::string>& folders) {
            std::string text;
            for (const std::string& folder : folders)
                text += folder + " ";
            return QString::fromStdString(text);
        };
        QCOMPARE(join(rows), join(expected));
    }

    void layerCheckFindsUpwardIncludes()
    {
        // The check above must be able to fail: a small tree with upward includes, a downward
        // one, a loose header and a folder in no layer.
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        const fs::path core = fs::path(dir.path().toStdString());
        const fs::path include = core / "include" / "visioncore";
        writeFile(include / "loose.h", "#pragma once\n");
        writeFile(include / "extras" / "x.h", "#pragma once\n");
        writeFile(include / "basics" / "ok.h", "#include \"visioncore/basics/result.h\"\n");
        writeFile(include / "basics" / "up.h", "#include \"visioncore/framework/stage.h\"\n");
        writeFile(include / "io" / "up.h", "#include \"visioncore/datawrappers/x.h\"\n");
        writeFile(include / "io" / "ok.h", "#include \"visioncore/percepts/ball.h\"\n");
        writeFile(core / "src" / "io" / "up.cpp", "#include \"visioncore/services/y.h\"\n");
        writeFile(core / "src" / "percepts" / "up.cpp", "#include \"io/strm_format.h\"\n");
        writeFile(core / "src" / "services" / "up.cpp", "#include \"stages/ball/ball.h\"\n");
        writeFile(core / "src" / "framework" / "ok.cpp", "#include <services/not_ours.h>\n");
        std::vector<std::string> found = layerViolations(core, coreLayers());
        for (std::string& f : found)
            f = fs::path(f.substr(0, f.find(':'))).filename().string() + f.substr(f.find(':'));
        std::sort(found.begin(), found.end());
        const std::vector<std::string> expected{
            "extras: a folder in no layer",      "loose.h: a header in no layer",
            "up.cpp: io/strm_format.h",          "up.cpp: stages/ball/ball.h",
            "up.cpp: visioncore/services/y.h",   "up.h: visioncore/datawrappers/x.h",
            "up.h: visioncore/framework/stage.h"};
        QCOMPARE(found, expected);
    }

    void layerCheckRefusesEveryCycle()
    {
        // For every two layers that include each other, exactly one of the includes is reported.
        const std::vector<std::string>& layers = coreLayers();
        QVERIFY(layers.size() >= 6);
        for (std::size_t a = 0; a < layers.size(); ++a)
            for (std::size_t b = a + 1; b < layers.size(); ++b) {
                QTemporaryDir dir;
                QVERIFY(dir.isValid());
                const fs::path src = fs::path(dir.path().toStdString()) / "src";
                writeFile(src / layers[a] / "a.h", "#include \"" + layers[b] + "/b.h\"\n");
                writeFile(src / layers[b] / "b.h", "#include \"" + layers[a] + "/a.h\"\n");
                const std::vector<std::string> found =
                    layerViolations(fs::path(dir.path().toStdString()), layers);
                QCOMPARE(found.size(), std::size_t(1));
                QVERIFY2(found[0].find("a.h: " + layers[b] + "/b.h") != std::string::npos,
                         found[0].c_str());
            }
    }

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

FIELDSIGHT_TEST_SUITE(TestArchitecture, None)

#include "test_architecture.moc"
