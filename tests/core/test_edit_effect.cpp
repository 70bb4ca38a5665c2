// The whole-stream edit-effect scanner (visioncore/services/edit_effect.h) on a copy of the lab1
// sample stream: a first scan records, an edit's counts agree with a pixel-by-pixel count and an
// independent run, frames the edit does not touch are not run again, a damaged frame is passed,
// cancel stops a scan; and the detection delta is reported per percept kind.
#include "support/test_suite.h"
#include "support/synthetic_frames.h"
#include "support/light_ramp.h"
#include "support/test_images.h"

#include "visioncore/percepts/ball.h"
#include "visioncore/percepts/goalpost.h"
#include "visioncore/percepts/obstacle.h"
#include "visioncore/services/edit_effect.h"
#include "visioncore/services/evaluation.h"
#include "visioncore/services/light_tracking.h"

#include <QtTest>

#include <atomic>
#include <filesystem>
#include <functional>

using namespace fieldsight;
namespace fs = std::filesystem;

namespace {

/// A stage that only counts how often the pipeline ran (and calls `on_run`, for cancelling).
class CountingStage : public Stage
{
public:
    static inline std::atomic<int> runs{0};
    static inline std::function<void()> on_run;

    const StageInfo& info() const override
    {
        static const StageInfo info{"count", "Count", "Counts the frames run.", true, {}, {},
                                    {},      {}};
        return info;
    }
    void run(Blackboard&) override
    {
        ++runs;
        if (on_run)
            on_run();
    }
};

Pipeline countingPipeline()
{
    Pipeline pipeline = Pipeline::standard();
    pipeline.add<CountingStage>();
    return pipeline;
}

std::shared_ptr<const ColourLut> lab1Lut()
{
    auto lut = ColourLut::load(test::sampleStreamsDir() + "/lab1/default.lut");
    if (!lut)
        qFatal("%s", lut.error().message.c_str());
    return std::make_shared<const ColourLut>(std::move(lut).value());
}

/// `lut` with every orange cell unclassified.
std::shared_ptr<const ColourLut> withoutOrange(const ColourLut& lut)
{
    ColourLut out = lut;
    for (std::uint32_t i = 0; i < ColourLut::kCells; ++i)
        if (out.cell(i) == Colour::Orange)
            out.setCell(i, Colour::Unclassified);
    return std::make_shared<const ColourLut>(std::move(out));
}

EditEffectProgress scan(EditEffectScanner& scanner, const EditEffectJob& job)
{
    scanner.clearResults();
    scanner.run(job);
    return scanner.collect();
}

} // namespace

class TestEditEffect : public QObject
{
    Q_OBJECT

private slots:
    void init() { CountingStage::runs = 0; }
    void cleanup() { CountingStage::on_run = nullptr; }

    void initTestCase()
    {
        QVERIFY(m_dir.isValid());
        // Frames 0-7 of lab1, then a black frame where nothing is orange.
        for (int i = 0; i < 8; ++i) {
            const std::string name =
                QStringLiteral("frame_%1.png").arg(i, 6, 10, QLatin1Char('0')).toStdString();
            fs::copy_file(test::sampleStreamsDir() + "/lab1/" + name, path() + "/" + name);
        }
        QVERIFY(fieldsight::test::imwrite(path() + "/frame_000008.png",
                                          cv::Mat(240, 320, CV_8UC3, cv::Scalar(0, 0, 0))));
        // The whole of lab1 under a light warming by 30% and dimming by 15% to its end.
        QVERIFY(m_ramp_dir.isValid());
        QCOMPARE(test::writeLightRamp(QString::fromStdString(test::sampleStreamsDir() + "/lab1"),
                                      QString::fromStdString(rampPath()),
                                      {1.3 * 0.85, 0.85, 0.7 * 0.85}),
                 QString());
    }

    void aFirstScanRecordsEveryFrameAndReportsNoDelta()
    {
        const Pipeline pipeline = countingPipeline();
        EditEffectScanner scanner(pipeline);
        scanner.setThreads(2);
        scanner.setStream(path());
        const EditEffectProgress p = scan(scanner, {nullptr, lab1Lut()});
        QVERIFY2(p.error.empty(), p.error.c_str());
        QVERIFY(p.finished);
        QVERIFY(!scanner.collect().finished); // an end is reported once
        QCOMPARE(p.effects.size(), kFrames);
        QCOMPARE(p.done, kFrames);
        QCOMPARE(p.changed_cells, std::size_t(0));
        QCOMPARE(CountingStage::runs.load(), int(kFrames));
        for (const FrameEffect& e : p.effects) {
            QVERIFY(e.done && !e.unreadable);
            QCOMPARE(e.pixels, 320u * 240u);
            QCOMPARE(e.changed_pixels, 0u);
            QCOMPARE(e.delta, DetectionDelta{});
        }
    }

    void erasingOrangeChangesFramesWithOrangeAndMakesTheirBallsVanish()
    {
        const Pipeline pipeline = countingPipeline();
        EditEffectScanner scanner(pipeline);
        scanner.setThreads(2);
        scanner.setStream(path());
        const auto before = lab1Lut();
        const auto after = withoutOrange(*before);
        QVERIFY(scan(scanner, {nullptr, before}).finished);

        CountingStage::runs = 0;
        const EditEffectProgress p = scan(scanner, {before, after});
        QVERIFY2(p.error.empty(), p.error.c_str());
        QVERIFY(p.finished);
        QCOMPARE(p.changed_cells, cellCount(*before, Colour::Orange));

        // The balls the table before found, by an independent run.
        auto input = openStreamInput(path(), test::sampleStreamsDir() + "/lab1/default.lut");
        QVERIFY(input);
        auto run = runStream(input.value(), firstFrames(kFrames), 1);
        QVERIFY(run);
        auto reader = openStream(path());
        QVERIFY(reader);
        int with_orange = 0;
        int balls = 0;
        for (std::size_t i = 0; i < kFrames; ++i) {
            auto frame = reader.value()->read(i);
            QVERIFY(frame);
            const cv::Mat& px = frame.value().ycbcr;
            std::uint32_t orange = 0;
            for (int y = 0; y < px.rows; ++y)
                for (int x = 0; x < px.cols; ++x) {
                    const cv::Vec3b c = px.at<cv::Vec3b>(y, x);
                    orange += before->classify(c[0], c[1], c[2]) == Colour::Orange;
                }
            const FrameEffect& e = p.effects[i];
            QVERIFY(e.done);
            QCOMPARE(e.changed_pixels, orange);
            const int n = int(run.value().frames[i].percepts.list<Ball>().size());
            QCOMPARE(e.delta.of("balls").vanished, n);
            QCOMPARE(e.delta.of("balls").appeared, 0);
            if (orange == 0)
                QCOMPARE(e.delta, DetectionDelta{});
            with_orange += orange > 0;
            balls += n;
        }
        QVERIFY(balls > 0);
        QVERIFY(with_orange > 0 && with_orange < int(kFrames));
        // Only the frames with orange pixels were run again; the others kept their result.
        QCOMPARE(CountingStage::runs.load(), with_orange);

        // A settings change runs every frame again, and compares none.
        CountingStage::runs = 0;
        EditEffectJob settings{nullptr, after};
        settings.rerun_all = true;
        const EditEffectProgress all = scan(scanner, settings);
        QVERIFY(all.finished);
        QCOMPARE(CountingStage::runs.load(), int(kFrames));
    }

    void followingTheLightTheEditIsCountedAndRunInEachFramesLight()
    {
        // The frames under a light warming and dimming to the end, as the window following the
        // light reads them: each through its light's map (trackLight with the edited table).
        const std::string stream = rampPath();
        EditEffectScanner scanner;
        scanner.setThreads(2);
        scanner.setStream(stream);
        const auto before = lab1Lut();
        const auto after = withoutOrange(*before);
        EditEffectJob record{nullptr, before};
        record.adapt = LightTrackingOptions{};
        QVERIFY(scan(scanner, record).finished);
        EditEffectJob edit{before, after};
        edit.adapt = LightTrackingOptions{};
        const EditEffectProgress p = scan(scanner, edit);
        QVERIFY2(p.error.empty(), p.error.c_str());
        QVERIFY(p.finished);

        auto reader = openStream(stream);
        QVERIFY(reader);
        const std::size_t frames = reader.value()->info().frame_count;
        QCOMPARE(p.effects.size(), frames);
        const LightTrack track = trackLight(*reader.value(), after, frames);
        QCOMPARE(track.frames.size(), frames);
        // Balls by an independent run following the light with the table before.
        auto input = openStreamInput(stream, test::sampleStreamsDir() + "/lab1/default.lut");
        QVERIFY(input);
        input.value().adapt = LightTrackingOptions{};
        auto run = runStream(input.value(), firstFrames(frames), 1);
        QVERIFY(run);
        int mapped = 0;
        int differs_from_static = 0;
        for (std::size_t i = 0; i < frames; ++i) {
            auto frame = reader.value()->read(i);
            QVERIFY(frame);
            ColourLut a = *after;
            ColourLut b = *before;
            a.setInputMap(track.frames[i].makeMap());
            b.setInputMap(a.inputMap());
            mapped += a.inputMap() != nullptr;
            const cv::Mat& px = frame.value().ycbcr;
            std::uint32_t changed = 0;
            std::uint32_t unclassified = 0;
            std::uint32_t orange_as_it_is = 0;
            for (int y = 0; y < px.rows; ++y)
                for (int x = 0; x < px.cols; ++x) {
                    const cv::Vec3b c = px.at<cv::Vec3b>(y, x);
                    const Colour now = a.classify(c[0], c[1], c[2]);
                    changed += now != b.classify(c[0], c[1], c[2]);
                    unclassified += now == Colour::Unclassified;
                    orange_as_it_is += before->classify(c[0], c[1], c[2]) == Colour::Orange;
                }
            const FrameEffect& e = p.effects[i];
            QVERIFY(e.done);
            QCOMPARE(e.changed_pixels, changed);
            QCOMPARE(e.unclassified, unclassified);
            differs_from_static += changed != orange_as_it_is;
            const int n = int(run.value().frames[i].percepts.list<Ball>().size());
            QCOMPARE(e.delta.of("balls").vanished, n);
        }
        // The light moved far enough that some frames were read through a map, and there the
        // counts are not those of the table as it is.
        QVERIFY(mapped > 0);
        QVERIFY(differs_from_static > 0);
    }

    void followingTheLightAnEditNoPixelReadsRunsNoFrameAgain()
    {
        // A cell no frame's pixel reads through any of its lights: every frame keeps its result,
        // as without following the light.
        const Pipeline pipeline = countingPipeline();
        EditEffectScanner scanner(pipeline);
        scanner.setThreads(2);
        scanner.setStream(rampPath());
        const auto before = lab1Lut();
        ColourLut edited = *before;
        QCOMPARE(edited.cell(0), Colour::Unclassified);
        edited.setCell(0, Colour::Orange);
        const auto after = std::make_shared<const ColourLut>(std::move(edited));
        EditEffectJob record{nullptr, before};
        record.adapt = LightTrackingOptions{};
        QVERIFY(scan(scanner, record).finished);
        const int frames = CountingStage::runs.load();
        QVERIFY(frames > 20);
        CountingStage::runs = 0;
        EditEffectJob edit{before, after};
        edit.adapt = LightTrackingOptions{};
        const EditEffectProgress p = scan(scanner, edit);
        QVERIFY(p.finished);
        QCOMPARE(p.changed_cells, std::size_t(1));
        for (const FrameEffect& e : p.effects)
            QCOMPARE(e.changed_pixels, 0u);
        QCOMPARE(CountingStage::runs.load(), 0);
    }

    void anUnreadableFrameIsMarkedAndTheScanGoesOn()
    {
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        const std::string cut = dir.path().toStdString() + "/frame_000001.png";
        for (int i = 0; i < 3; ++i) {
            const std::string name =
                QStringLiteral("frame_%1.png").arg(i, 6, 10, QLatin1Char('0')).toStdString();
            fs::copy_file(path() + "/" + name, dir.path().toStdString() + "/" + name);
        }
        fs::resize_file(cut, 200);
        EditEffectScanner scanner;
        scanner.setThreads(2);
        scanner.setStream(dir.path().toStdString());
        const EditEffectProgress p = scan(scanner, {nullptr, lab1Lut()});
        QVERIFY2(p.error.empty(), p.error.c_str());
        QVERIFY(p.finished);
        QCOMPARE(p.done, std::size_t(3));
        for (std::size_t i = 0; i < 3; ++i) {
            QVERIFY(p.effects[i].done);
            QCOMPARE(p.effects[i].unreadable, i == 1);
            QCOMPARE(p.effects[i].pixels, i == 1 ? 0u : 320u * 240u);
        }
        QCOMPARE(p.unreadable.size(), std::size_t(1));
        QVERIFY(p.unreadable.at(1).find("truncated PNG") != std::string::npos);
        QVERIFY(p.unreadable.at(1).find("frame_000001.png") != std::string::npos);
    }

    void cancelStopsTheScanAndTheNextScanRunsAgain()
    {
        const Pipeline pipeline = countingPipeline();
        EditEffectScanner scanner(pipeline);
        scanner.setThreads(1);
        scanner.setStream(path());
        CountingStage::on_run = [&] {
            if (CountingStage::runs == 3)
                scanner.cancel();
        };
        const EditEffectProgress p = scan(scanner, {nullptr, lab1Lut()});
        QVERIFY2(p.error.empty(), p.error.c_str());
        QVERIFY(!p.finished);
        QVERIFY2(p.done >= 3 && p.done < kFrames, qPrintable(QString::number(p.done)));
        QVERIFY(CountingStage::runs < int(kFrames));

        CountingStage::on_run = nullptr;
        const EditEffectProgress again = scan(scanner, {nullptr, lab1Lut()});
        QVERIFY(again.finished);
        QCOMPARE(again.done, kFrames);
    }

    /// The frame gate (the window pausing the scan while the user steps) is passed before each
    /// frame is read and again before it runs; a cancel given while a thread is at the gate
    /// stops the scan before that frame is read.
    void theFrameGateIsPassedBeforeEachFrameIsReadAndRun()
    {
        const Pipeline pipeline = countingPipeline();
        EditEffectScanner scanner(pipeline);
        scanner.setThreads(1);
        scanner.setStream(path());
        int passes = 0;
        int runs_at_pass = -1;
        scanner.setFrameGate([&] {
            ++passes;
            runs_at_pass = CountingStage::runs;
        });
        const EditEffectProgress p = scan(scanner, {nullptr, lab1Lut()});
        QVERIFY(p.finished);
        QCOMPARE(passes, 2 * int(kFrames));
        QCOMPARE(runs_at_pass, int(kFrames) - 1); // the last pass came before the last run

        passes = 0;
        scanner.setFrameGate([&] {
            if (++passes == 5) // the third frame's read
                scanner.cancel();
        });
        const EditEffectProgress cut = scan(scanner, {nullptr, lab1Lut()});
        QVERIFY(!cut.finished);
        QCOMPARE(cut.done, std::size_t(2));
        QCOMPARE(passes, 5);
    }

    void aStreamThatCannotBeOpenedIsTheScansError()
    {
        EditEffectScanner scanner;
        scanner.setStream(path() + "/no_such_folder");
        const EditEffectProgress p = scan(scanner, {nullptr, lab1Lut()});
        QVERIFY(!p.finished);
        QVERIFY(p.error.find("no_such_folder") != std::string::npos);
        QVERIFY(p.effects.empty());
    }

    void theDetectionDeltaIsReportedPerKindByKey()
    {
        PerceptSet before, after;
        before.output<Ball>() = {{100, 100, 10}};
        after.output<Ball>() = {{101, 100, 10}}; // the same ball
        before.output<Goalpost>() = {{10, 15, 20, 100, 12.5, 100}, {200, 205, 20, 100, 202, 100}};
        after.output<Goalpost>() = {{11, 16, 20, 101, 13.5, 101}}; // the right post vanished
        before.output<Obstacle>() = {{50, 80, 60, 150}};
        after.output<Obstacle>() = {{55, 85, 60, 150}, {250, 300, 60, 150}}; // one new

        const DetectionDelta d = compareDetections(before, after, 320, 240);
        // Every kind with a matching rule, field lines too (docs/formats.md), in one order.
        QCOMPARE(d.kinds.size(), std::size_t(4));
        QCOMPARE(d.kinds[0].kind, &perceptKind<Ball>());
        QCOMPARE(d.kinds[1].kind, &perceptKind<Goalpost>());
        QCOMPARE(d.kinds[2].kind, &perceptKind<Obstacle>());
        QCOMPARE(d.kinds[3].kind, &perceptKind<FieldLine>());
        QCOMPARE(d.of("balls").appeared + d.of("balls").vanished, 0);
        QCOMPARE(d.of("goalposts").vanished, 1);
        QCOMPARE(d.of("goalposts").appeared, 0);
        QCOMPARE(d.of("obstacles").appeared, 1);
        QCOMPARE(d.of("obstacles").vanished, 0);
        QCOMPARE(d.of("field_lines").appeared, 0); // neither run has lines
        QCOMPARE(d.appeared(), 1);
        QCOMPARE(d.vanished(), 1);

        // Sums add kind by kind; an empty delta equals one whose counts are all zero.
        DetectionDelta total;
        total += d;
        total += compareDetections(after, before, 320, 240);
        QCOMPARE(total.kinds.size(), std::size_t(4));
        QCOMPARE(total.of("goalposts").appeared, 1);
        QCOMPARE(total.of("goalposts").vanished, 1);
        QCOMPARE(total.appeared(), 2);
        QVERIFY(!(total == DetectionDelta{}));
        QCOMPARE(compareDetections(before, before, 320, 240), DetectionDelta{});
    }

private:
    static constexpr std::size_t kFrames = 9;

    std::string path() const { return m_dir.path().toStdString(); }
    std::string rampPath() const { return m_ramp_dir.filePath("ramp").toStdString(); }
    static std::size_t cellCount(const ColourLut& lut, Colour colour)
    {
        std::size_t n = 0;
        for (std::uint32_t i = 0; i < ColourLut::kCells; ++i)
            n += lut.cell(i) == colour;
        return n;
    }

    QTemporaryDir m_dir;
    QTemporaryDir m_ramp_dir;
};

FIELDSIGHT_TEST_SUITE(TestEditEffect, None)

#include "test_edit_effect.moc"
