// The core's services a GUI drives: running a stream with progress, cancel and a per-frame hook,
// the worker pool, and results JSON written and read back.
#include "support/test_suite.h"
#include "support/synthetic_frames.h"
#include "visioncore/percepts/ball.h"
#include "visioncore/percepts/obstacle.h"
#include "visioncore/services/layers.h"
#include "visioncore/services/results_json.h"
#include "visioncore/services/stream_runner.h"
#include "visioncore/services/worker_pool.h"

#include <QtTest>
#include <nlohmann/json.hpp>

#include <QTemporaryDir>

#include <atomic>
#include <filesystem>
#include <fstream>
#include <mutex>
#include <set>

using namespace fieldsight;

namespace {

StreamInput lab1()
{
    auto input = openStreamInput(test::sampleStreamsDir() + "/lab1", "");
    if (!input)
        qFatal("%s", input.error().message.c_str());
    return std::move(input).value();
}

} // namespace

class TestServices : public QObject
{
    Q_OBJECT
private slots:
    /// A stage's debug layer never takes a percept's colour (the trial found the green horizon's
    /// scan points and the field boundary both magenta): with both shown, a user can tell them
    /// apart.
    void noStageLayerSharesAPerceptsColour()
    {
        const std::vector<LayerInfo> layers = allLayers(Pipeline::standard());
        std::vector<const LayerInfo*> percepts;
        for (const LayerInfo& l : layers)
            if (l.id.rfind("percepts.", 0) == 0)
                percepts.push_back(&l);
        QVERIFY(percepts.size() >= 5);
        for (const LayerInfo& l : layers) {
            if (l.by_colour_class || l.id.rfind("percepts.", 0) == 0 ||
                l.id.rfind("truth.", 0) == 0)
                continue;
            for (const LayerInfo* p : percepts)
                QVERIFY2(!(l.colour == p->colour),
                         qPrintable(QString::fromStdString(l.id + " has the colour of " + p->id)));
        }
    }

    void everyWorkerRunsExactlyOnce()
    {
        std::mutex mutex;
        std::multiset<int> ran;
        runOnWorkers(4, [&](int t) {
            std::lock_guard lock(mutex);
            ran.insert(t);
        });
        QCOMPARE(ran, (std::multiset<int>{0, 1, 2, 3}));
        QCOMPARE(workerCount(5, 1), 1); // never more workers than items
        QVERIFY(workerCount(100000, 1000000) <=
                int(std::max(1u, std::thread::hardware_concurrency())));
        QVERIFY(workerCount(0, 10) >= 1);
    }

    void exceptionOnTheCallingWorkerIsRethrownAfterTheJoin()
    {
        std::atomic<int> others{0};
        QVERIFY_THROWS_EXCEPTION(std::runtime_error, runOnWorkers(3, [&](int t) {
                                     if (t == 0)
                                         throw std::runtime_error("worker 0");
                                     ++others;
                                 }));
        QCOMPARE(others.load(), 2);
    }

    void progressCountsEveryFrameAndResultsKeepTheirOrder()
    {
        StreamInput input = lab1();
        const std::vector<std::size_t> indices{7, 3, 12, 0, 5};
        std::vector<std::size_t> seen;
        RunHooks hooks;
        hooks.progress = [&](std::size_t done, std::size_t total) {
            QCOMPARE(total, indices.size());
            seen.push_back(done);
        };
        auto run = runStream(input, indices, 2, hooks);
        QVERIFY(run.ok());
        QVERIFY(!run.value().cancelled);
        QCOMPARE(seen, (std::vector<std::size_t>{1, 2, 3, 4, 5}));
        QCOMPARE(run.value().frames.size(), indices.size());
        for (std::size_t i = 0; i < indices.size(); ++i)
            QCOMPARE(run.value().frames[i].index, indices[i]);
    }

    void cancelKeepsAContiguousPrefix()
    {
        StreamInput input = lab1();
        std::atomic<bool> cancel{false};
        RunHooks hooks;
        hooks.cancel = &cancel;
        hooks.progress = [&](std::size_t done, std::size_t) {
            if (done == 4)
                cancel = true;
        };
        auto run = runStream(input, firstFrames(30), 2, hooks);
        QVERIFY(run.ok());
        QVERIFY(run.value().cancelled);
        const auto& frames = run.value().frames;
        QVERIFY(frames.size() < 30);
        for (std::size_t i = 0; i < frames.size(); ++i)
            QCOMPARE(frames[i].index, i);
    }

    void aFailingFrameHookStopsTheRunAsAFailure()
    {
        StreamInput input = lab1();
        RunHooks hooks;
        hooks.layers = {"ball.edge_points"};
        std::atomic<int> calls{0};
        hooks.on_frame = [&](const FrameResult& r, const Frame& f, const DebugCanvas& canvas) {
            ++calls;
            // The hook sees the frame's image and the layers it asked for.
            if (f.ycbcr.cols != 320 || canvas.requested().count("ball.edge_points") != 1)
                return Status(Error{"wrong frame or layers"});
            return r.index == 2 ? Status(Error{"disk full"}) : Status();
        };
        QVERIFY_THROWS_EXCEPTION(std::runtime_error,
                                 (void)runStream(input, firstFrames(6), 1, hooks));
        QCOMPARE(calls.load(), 3);
    }

    void anUnreadableFrameIsAnErrorUnlessAHookTakesIt()
    {
        // Four frames of lab1, the third cut short as a recording copied half-way.
        namespace fs = std::filesystem;
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        const std::string from = test::sampleStreamsDir() + "/lab1";
        const std::string to = dir.path().toStdString();
        for (int i = 0; i < 4; ++i) {
            const std::string frame = "/frame_00000" + std::to_string(i) + ".png";
            fs::copy_file(from + frame, to + frame);
        }
        fs::resize_file(to + "/frame_000002.png", 300);
        auto opened = openStreamInput(to, from + "/default.lut");
        QVERIFY2(opened.ok(), opened.ok() ? "" : opened.error().message.c_str());
        StreamInput input = std::move(opened).value();

        auto refused = runStream(input, firstFrames(4), 2);
        QVERIFY(!refused.ok());
        QVERIFY2(refused.error().message.find("frame_000002.png") != std::string::npos,
                 refused.error().message.c_str());

        std::mutex mutex;
        std::vector<std::pair<std::size_t, std::string>> unreadable;
        std::set<std::size_t> ran;
        RunHooks hooks;
        hooks.on_unreadable = [&](std::size_t index, const std::string& message) {
            std::lock_guard lock(mutex);
            unreadable.emplace_back(index, message);
        };
        hooks.on_frame = [&](const FrameResult& r, const Frame&, const DebugCanvas&) {
            std::lock_guard lock(mutex);
            ran.insert(r.index);
            return Status();
        };
        auto run = runStream(input, firstFrames(4), 2, hooks);
        QVERIFY2(run.ok(), run.ok() ? "" : run.error().message.c_str());
        QCOMPARE(run.value().frames.size(), std::size_t(4));
        QCOMPARE(ran, (std::set<std::size_t>{0, 1, 3}));
        QCOMPARE(unreadable.size(), std::size_t(1));
        QCOMPARE(unreadable[0].first, std::size_t(2));
        QVERIFY2(unreadable[0].second.find("truncated PNG") != std::string::npos,
                 unreadable[0].second.c_str());
        QCOMPARE(run.value().frames[2].index, std::size_t(2));
        QCOMPARE(run.value().frames[2].name, std::string("frame_000002.png"));
    }

    void badSettingsAreRefusedBeforeAnyFrameRuns()
    {
        StreamInput input = lab1();
        input.skip = {"scanlines"};
        auto run = runStream(input, firstFrames(3), 1);
        QVERIFY(!run.ok());
        QVERIFY(QString::fromStdString(run.error().message).contains("cannot be skipped"));
        input.skip = {};
        input.params.set("ball", "min_radius", -1);
        QVERIFY(!runStream(input, firstFrames(3), 1).ok());
    }

    void resultsJsonReadsBackToTheSameText()
    {
        StreamInput input = lab1();
        input.skip = {"obstacles"};
        auto run = runStream(input, firstFrames(5), 2);
        QVERIFY(run.ok());
        const std::vector<std::string> ids = Pipeline::standard().ids();
        const std::string text = resultsJson(resultsHeader(input), run.value().frames, ids);
        auto back = readResults(text, "results.json");
        QVERIFY2(back.ok(), back.ok() ? "" : back.error().message.c_str());
        const ResultsFile& file = back.value();
        QCOMPARE(file.header.skipped_stages, std::vector<std::string>{"obstacles"});
        QCOMPARE(file.frames.size(), std::size_t(5));
        // Skipped lists stay absent, others present; timings stay in pipeline order.
        QVERIFY(file.frames[0].percepts.find<Obstacle>() == nullptr);
        QVERIFY(file.frames[0].percepts.find<Ball>() != nullptr);
        QCOMPARE(file.frames[0].report.stages.front().stage, std::string("green_horizon"));
        // Written again, every frame is the same (the summary is recomputed from rounded times).
        const auto frames = [](const std::string& t) {
            return nlohmann::json::parse(t)["frames"].dump();
        };
        QCOMPARE(frames(resultsJson(file.header, file.frames, ids)), frames(text));

        // The whole file, summary included, is a fixed point once read: times are read to the
        // precision written, so the summary of what was read is the summary of its numbers.
        const std::string once = resultsJson(file.header, file.frames, ids);
        auto reread = readResults(once, "results.json");
        QVERIFY(reread.ok());
        QCOMPARE(resultsJson(reread.value().header, reread.value().frames, ids), once);
        // A time that is negative, not finite or absurd is refused by name.
        for (const char* bad : {"-1", "1e300", "\"1\""}) {
            const std::string doc = R"({"format": "fieldsight-results/1", "frames": [{"index": 0,
                "name": "a.png", "time_ms": {"total": 1, "ball": )" +
                                    std::string(bad) + "}}]}";
            auto refused = readResults(doc, "r.json");
            QVERIFY2(!refused.ok(), bad);
            QVERIFY2(refused.error().message.find("frames[0].time_ms.ball") != std::string::npos,
                     refused.error().message.c_str());
        }

        QVERIFY(!readResults("{", "r.json").ok());
        QVERIFY(!readResults(R"({"format": "fieldsight-results/1", "frames": [{"index": 0}]})",
                             "r.json")
                     .ok());
    }
};

FIELDSIGHT_TEST_SUITE(TestServices, Core)

#include "test_services.moc"
