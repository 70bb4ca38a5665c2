// A/B comparison (`fieldsight compare`, visioncore/services/ab_compare.h): a table B that erases
// the ball colour breaks exactly the ball frames A got right; swapping the sides fixes them; the
// JSON has its documented fields and side A's scores equal `eval`'s; a class is scored only where
// its truth is complete (a reviewed class on a frame not done); a concealed ball B misses breaks
// nothing (the matching of eval, concealed objects apart).
#include "support/test_suite.h"
#include "support/child_process.h"
#include "support/synthetic_frames.h"
#include "visioncore/basics/colour_lut.h"
#include "visioncore/percepts/ball.h"
#include "visioncore/services/ab_compare.h"

#include <nlohmann/json.hpp>

#include <QtTest>

#include <QTemporaryDir>

#include <filesystem>
#include <set>

using namespace fieldsight;
using fieldsight::test::Outcome;
using Json = nlohmann::json;

namespace {

std::string lab2()
{
    return test::sampleStreamsDir() + "/lab2";
}

Json parsed(const std::string& text)
{
    return Json::parse(text, nullptr, false);
}

} // namespace

class TestCompare : public QObject
{
    Q_OBJECT

private:
    QTemporaryDir m_dir;
    std::string m_no_orange; ///< lab2's table with every orange cell unclassified

    std::string path(const std::string& name) const
    {
        return m_dir.filePath(name.c_str()).toStdString();
    }

    Outcome fieldsight(const std::vector<std::string>& args)
    {
        return test::runChild(FIELDSIGHT_EXE, args, m_dir.path().toStdString(), RLIM_INFINITY,
                              false, 240);
    }

    /// The ball frames A (lab2's own table) gets right, from the compare JSON's A scores: every
    /// frame scored minus those wrong with A.
    static std::set<std::string> namesOf(const Json& frames)
    {
        std::set<std::string> names;
        for (const Json& f : frames)
            names.insert(f.at("name").get<std::string>());
        return names;
    }

private slots:
    void initTestCase()
    {
        QVERIFY(m_dir.isValid());
        auto lut = ColourLut::load(lab2() + "/default.lut");
        QVERIFY2(lut.ok(), lut ? "" : lut.error().message.c_str());
        ColourLut table = std::move(lut).value();
        std::size_t erased = 0;
        for (std::size_t i = 0; i < ColourLut::kCells; ++i)
            if (table.data()[i] == std::uint8_t(Colour::Orange)) {
                table.setCell(i, Colour::Unclassified);
                ++erased;
            }
        QVERIFY(erased > 500); // 830 cells in lab2's table
        m_no_orange = path("no_orange.lut");
        QVERIFY(table.save(m_no_orange).ok());
    }

    void erasingTheBallColourBreaksTheBallFrames()
    {
        const std::string json = path("compare.json");
        const Outcome o = fieldsight({"compare", lab2(), "--lut-b", m_no_orange, "--json", json});
        QVERIFY2(o.status == 0, o.err.c_str());
        QVERIFY2(o.out.find("broken ball: frame_000000.png (FN 0->1)") != std::string::npos,
                 o.out.c_str());
        const Json doc = parsed(test::readAll(json));
        QVERIFY(doc.is_object());
        QCOMPARE(doc.at("format").get<std::string>(), std::string("fieldsight-compare/1"));
        QCOMPARE(doc.at("stream").get<std::string>(), lab2());
        QCOMPARE(doc.at("truth").get<std::string>(), lab2() + "/annotations.json");
        QCOMPARE(doc.at("a").at("lut").get<std::string>(), lab2() + "/default.lut");
        QCOMPARE(doc.at("b").at("lut").get<std::string>(), m_no_orange);
        QVERIFY(doc.at("a").at("params").is_null());
        QCOMPARE(doc.at("frames").get<int>(), 30);

        const Json& ball = doc.at("classes").at("ball");
        QCOMPARE(ball.at("key").get<std::string>(), std::string("balls"));
        QCOMPARE(ball.at("frames").get<int>(), 30);
        // lab2 has the ball in every frame; without orange B finds none.
        const int balls = ball.at("a").at("tp").get<int>() + ball.at("a").at("fn").get<int>();
        QCOMPARE(balls, 30);
        QCOMPARE(ball.at("b").at("tp").get<int>(), 0);
        QCOMPARE(ball.at("b").at("fn").get<int>(), 30);
        QCOMPARE(ball.at("b").at("recall").get<double>(), 0.0);
        QVERIFY(ball.at("fixed").empty());
        // Broken: every frame A got right (no miss, no false ball), each with its scores.
        const Json& broken = ball.at("broken");
        QCOMPARE(int(broken.size()) + ball.at("wrong_both").get<int>(), 30);
        QVERIFY(broken.size() >= 25);
        for (const Json& f : broken) {
            QCOMPARE(f.at("a").at("fp").get<int>(), 0);
            QCOMPARE(f.at("a").at("fn").get<int>(), 0);
            QCOMPARE(f.at("b").at("fn").get<int>(), 1);
            QCOMPARE(f.at("name").get<std::string>(),
                     "frame_" +
                         std::string(6 - std::to_string(f.at("index").get<int>()).size(), '0') +
                         std::to_string(f.at("index").get<int>()) + ".png");
        }
        for (const char* other : {"goalpost", "obstacle"}) {
            const Json& c = doc.at("classes").at(other);
            for (const char* field : {"key", "frames", "a", "b", "fixed", "broken", "wrong_both"})
                QVERIFY2(c.contains(field), field);
        }
        for (const char* side : {"a", "b"}) {
            const Json& boundary = doc.at("field_boundary").at(side);
            QVERIFY(boundary.at("mean_error_px").is_number());
            QCOMPARE(boundary.at("frames").get<int>(), 30);
        }

        // Side A's scores are `eval`'s on the same stream and table.
        const std::string eval_json = path("eval.json");
        const Outcome e = fieldsight({"eval", lab2(), "--json", eval_json});
        QVERIFY2(e.status == 0, e.err.c_str());
        const Json eval = parsed(test::readAll(eval_json));
        for (const char* c : {"ball", "goalpost", "obstacle", "field_line"})
            for (const char* n : {"tp", "fp", "fn", "concealed_found", "concealed_missed"})
                QCOMPARE(doc.at("classes").at(c).at("a").at(n).get<int>(),
                         eval.at("classes").at(c).at(n).get<int>());
        QCOMPARE(doc.at("field_boundary").at("a").at("mean_error_px").get<double>(),
                 eval.at("field_boundary").at("mean_error_px").get<double>());

        // The sides swapped: what B broke, A fixes.
        const Outcome swapped = fieldsight({"compare", lab2(), "--lut", m_no_orange, "--lut-b",
                                            lab2() + "/default.lut", "--json", "-"});
        QVERIFY2(swapped.status == 0, swapped.err.c_str());
        const Json back = parsed(swapped.out); // JSON alone on standard output
        QVERIFY2(back.is_object(), swapped.out.substr(0, 200).c_str());
        QCOMPARE(namesOf(back.at("classes").at("ball").at("fixed")), namesOf(broken));
        QVERIFY(back.at("classes").at("ball").at("broken").empty());
    }

    void parametersBAloneAreCompared()
    {
        // A minimum radius no ball reaches: the same frames break as without orange.
        const std::string params = path("big_balls.json");
        test::writeBytes(params, R"({"format": "fieldsight-params/1",
                                     "stages": {"ball": {"min_radius": 100}}})");
        const Outcome o = fieldsight({"compare", lab2(), "--params-b", params, "--json", "-"});
        QVERIFY2(o.status == 0, o.err.c_str());
        const Json doc = parsed(o.out);
        QCOMPARE(doc.at("b").at("params").get<std::string>(), params);
        QCOMPARE(doc.at("b").at("lut").get<std::string>(), lab2() + "/default.lut");
        QCOMPARE(doc.at("classes").at("ball").at("b").at("tp").get<int>(), 0);
        QVERIFY(!doc.at("classes").at("ball").at("broken").empty());
        // Goalposts do not depend on the ball's parameters.
        QVERIFY(doc.at("classes").at("goalpost").at("broken").empty());
        QVERIFY(doc.at("classes").at("goalpost").at("fixed").empty());
        QCOMPARE(doc.at("classes").at("goalpost").at("a"),
                 doc.at("classes").at("goalpost").at("b"));
    }

    void aFrameWithFewerErrorsIsFixedEvenWhenNotPerfect()
    {
        // One line a frame at most on side A: frames of several lines keep misses on both sides,
        // yet B (all ten) finds more of them. Fixed and broken count errors per class.
        const std::string params = path("one_line.json");
        test::writeBytes(params, R"({"format": "fieldsight-params/1",
                                     "stages": {"field_lines": {"max_lines": 1}}})");
        const std::string defaults = path("defaults.json");
        test::writeBytes(defaults, R"({"format": "fieldsight-params/1", "stages": {}})");
        const Outcome c = fieldsight(
            {"compare", lab2(), "--params", params, "--params-b", defaults, "--json", "-"});
        QVERIFY2(c.status == 0, c.err.c_str());
        const Json lines = parsed(c.out).at("classes").at("field_line");
        const int recall_gain =
            lines.at("b").at("tp").get<int>() - lines.at("a").at("tp").get<int>();
        QVERIFY2(recall_gain > 0, c.out.substr(0, 400).c_str());
        int fixed_not_perfect = 0;
        for (const Json& f : lines.at("fixed")) {
            const int a = f.at("a").at("fp").get<int>() + f.at("a").at("fn").get<int>();
            const int b = f.at("b").at("fp").get<int>() + f.at("b").at("fn").get<int>();
            QVERIFY(b < a);
            fixed_not_perfect += b > 0;
        }
        for (const Json& f : lines.at("broken"))
            QVERIFY(f.at("b").at("fp").get<int>() + f.at("b").at("fn").get<int>() >
                    f.at("a").at("fp").get<int>() + f.at("a").at("fn").get<int>());
        QVERIFY2(fixed_not_perfect > 0, lines.dump().substr(0, 400).c_str());
    }

    void aStreamsOwnParametersApplyUnderTheCommandLines()
    {
        // lab2 copied, its manifest naming a parameter file no ball passes.
        const std::string stream = path("own_params");
        std::filesystem::create_directories(stream);
        for (const auto& entry : std::filesystem::directory_iterator(lab2()))
            std::filesystem::copy(entry.path(), stream + "/" + entry.path().filename().string());
        Json manifest = parsed(test::readAll(stream + "/stream.json"));
        manifest["params"] = "params.json";
        test::writeBytes(stream + "/stream.json", manifest.dump());
        test::writeBytes(stream + "/params.json", R"({"format": "fieldsight-params/1",
                                                     "stages": {"ball": {"min_radius": 100}}})");
        const std::string json = path("own_params_eval.json");
        const auto ballTp = [&](std::vector<std::string> args) {
            args.insert(args.begin(), {"eval", stream, "--json", json});
            const Outcome o = fieldsight(args);
            if (o.status != 0)
                return -1;
            return parsed(test::readAll(json)).at("classes").at("ball").at("tp").get<int>();
        };
        QCOMPARE(ballTp({}), 0);
        QVERIFY(ballTp({"--set", "ball.min_radius=2"}) > 20); // --set over the stream's file

        // A file the manifest names that is missing: bad input naming it.
        std::filesystem::remove(stream + "/params.json");
        const Outcome o = fieldsight({"eval", stream});
        QCOMPARE(o.status, 2);
        QVERIFY2(o.err.find(stream + "/params.json") != std::string::npos, o.err.c_str());
        QVERIFY2(o.err.find("\"params\"") != std::string::npos, o.err.c_str());
    }

    void badUsageIsRefusedBeforeAnythingIsWritten()
    {
        Outcome o = fieldsight({"compare", lab2()});
        QCOMPARE(o.status, 2);
        QVERIFY2(o.err.find("--lut-b") != std::string::npos, o.err.c_str());
        const std::string truth = lab2() + "/annotations.json";
        const std::string before = test::readAll(truth);
        o = fieldsight({"compare", lab2(), "--lut-b", m_no_orange, "--json", truth});
        QCOMPARE(o.status, 2);
        QVERIFY2(o.err.find("nothing was written") != std::string::npos, o.err.c_str());
        QCOMPARE(test::readAll(truth), before);
        o = fieldsight({"compare", lab2(), "--lut-b", path("missing.lut")});
        QCOMPARE(o.status, 2);
        QVERIFY2(o.err.find(path("missing.lut")) != std::string::npos, o.err.c_str());
    }

    void aClassIsScoredOnlyWhereItsTruthIsComplete()
    {
        // Frame 0 is done; frame 1 is not done but reviewed for balls; frame 2 is neither.
        auto source =
            Annotations::load(lab2() + "/annotations.json", Pipeline::standard().perceptKinds());
        QVERIFY(source.ok());
        Annotations truth;
        truth.frames["frame_000000.png"] = source.value().frames.at("frame_000000.png");
        FrameAnnotation reviewed = source.value().frames.at("frame_000001.png");
        reviewed.done = false;
        reviewed.reviewed = {"balls"};
        truth.frames["frame_000001.png"] = reviewed;
        FrameAnnotation open = source.value().frames.at("frame_000002.png");
        open.done = false;
        truth.frames["frame_000002.png"] = open;

        auto input = openStreamInput(lab2(), "");
        QVERIFY(input.ok());
        auto lut = ColourLut::load(m_no_orange);
        QVERIFY(lut.ok());
        AbSide b;
        b.lut = std::make_shared<const ColourLut>(std::move(lut).value());
        std::vector<std::size_t> progress;
        RunHooks hooks;
        hooks.progress = [&](std::size_t done, std::size_t total) {
            QCOMPARE(total, std::size_t(4));
            progress.push_back(done);
        };
        auto result = compareAb(input.value(), b, truth, "truth.json", 1, hooks);
        QVERIFY2(result.ok(), result ? "" : result.error().message.c_str());
        const AbComparison& c = result.value();
        QCOMPARE(c.frames, std::size_t(2));
        QCOMPARE(progress, (std::vector<std::size_t>{1, 2, 3, 4}));
        QCOMPARE(c.classes.size(), std::size_t(4)); // with field lines, as eval scores them
        QCOMPARE(c.classes[3].name, std::string("field_line"));
        QCOMPARE(c.classes[0].kind, &perceptKind<Ball>());
        QCOMPARE(c.classes[0].frames, std::size_t(2));
        QCOMPARE(c.classes[0].a.tp + c.classes[0].a.fn, 2);
        QCOMPARE(c.classes[1].name, std::string("goalpost"));
        QCOMPARE(c.classes[1].frames, std::size_t(1)); // frame 1 is not reviewed for goalposts
        QCOMPARE(c.boundary_frames_a, std::size_t(1));
        QCOMPARE(input.value().lut_path, lab2() + "/default.lut"); // side A is kept

        // The done frame's ball concealed: B missing it breaks nothing, as eval counts it apart.
        QCOMPARE(c.classes[0].broken.size(), std::size_t(2));
        FrameAnnotation& done = truth.frames.at("frame_000000.png");
        QVERIFY(!done.truth.list<Ball>().empty());
        ObjectFlags concealed;
        concealed.concealed = true;
        done.setFlags("balls", 0, concealed);
        auto hidden = compareAb(input.value(), b, truth, "truth.json", 1);
        QVERIFY(hidden.ok());
        const AbClass& balls = hidden.value().classes[0];
        QCOMPARE(balls.broken.size(), std::size_t(1));
        QCOMPARE(balls.broken[0].name, std::string("frame_000001.png"));
        QCOMPARE(balls.b.concealed_missed, 1);
        QCOMPARE(balls.a.concealed_found, 1);
        QCOMPARE(balls.a.tp + balls.a.fn, 1);
        done.setFlags("balls", 0, ObjectFlags{});

        // A frame with a complete class that the stream lacks is bad input, named.
        truth.frames["frame_000099.png"] = source.value().frames.at("frame_000000.png");
        auto missing = compareAb(input.value(), b, truth, "truth.json", 1);
        QVERIFY(!missing.ok());
        QVERIFY(missing.error().message.find("frame_000099.png") != std::string::npos);

        // Cancelled before it starts: nothing but the flag.
        truth.frames.erase("frame_000099.png");
        std::atomic<bool> cancel{true};
        RunHooks cancelling;
        cancelling.cancel = &cancel;
        auto cancelled = compareAb(input.value(), b, truth, "truth.json", 1, cancelling);
        QVERIFY(cancelled.ok());
        QVERIFY(cancelled.value().cancelled);
        QVERIFY(cancelled.value().classes.empty());
    }
};

FIELDSIGHT_TEST_SUITE(TestCompare, None)

#include "test_compare.moc"
