// Frames of any size (issue 33): lengths given in px follow the frame's width, so the defaults
// find at 1280x720 what they find at 320x240, and a 320x240 frame runs exactly as before.
#include "support/test_suite.h"
#include "synth/synth.h"
#include "visioncore/framework/stage.h"
#include "visioncore/services/evaluation.h"
#include "visioncore/services/stream_runner.h"

#include <QTemporaryDir>
#include <QtTest>

#include <string>

using namespace fieldsight;

namespace {

/// A stage with one length of each type and a count, to read them as a stage does.
class LengthStage : public Stage
{
public:
    const StageInfo& info() const override
    {
        static const StageInfo info{"lengths", "Lengths", "", true, {}, {}, {}, {}};
        return info;
    }
    void run(Blackboard&) override {}

    Param<int> m_run{this, 3, {"run", "px", 0, 100, 1, ""}};
    Param<double> m_error{this, 1.5, {"error", "px", 0, 100, 0.5, ""}};
    Param<int> m_count{this, 6, {"count", "", 0, 100, 1, ""}};
    Param<int> m_spacing{this, 4, {"spacing", "px", 1, 64, 1, ""}};
};

struct Scored
{
    EvaluationScores scores;
    int width = 0;
};

/// Generates `frames` frames of lab2 at width x height (YCbCr .strm, no PNG) and scores them with
/// the default parameters and the stream's ideal table.
Scored generateAndScore(const QString& dir, int width, int height, int frames)
{
    synth::SynthOptions options;
    options.scenario = synth::Scenario::Lab2;
    options.frames = frames;
    options.seed = 1;
    options.width = width;
    options.height = height;
    options.write_strm = true;
    options.write_png = false;
    options.out_dir = dir.toStdString();
    Scored out;
    if (Status s = synth::generateStream(options); !s) {
        qWarning("%s", s.error().message.c_str());
        return out;
    }
    auto input = openStreamInput(options.out_dir + "/image.strm", options.out_dir + "/default.lut");
    if (!input) {
        qWarning("%s", input.error().message.c_str());
        return out;
    }
    const std::string truth_path = options.out_dir + "/annotations.json";
    auto truth = Annotations::load(truth_path, Pipeline::standard().perceptKinds());
    if (!truth)
        return out;
    auto report = evaluateStream(input.value(), truth.value(), truth_path, 2);
    if (!report)
        return out;
    out.scores = report.value().scores;
    out.width = input.value().info().width;
    return out;
}

} // namespace

class TestFrameSize : public QObject
{
    Q_OBJECT

private slots:
    void lengthsReadScaledByTheFrameWidth()
    {
        LengthStage stage;
        QCOMPARE(int(stage.m_run), 3); // before any frame: as set
        stage.setFrameWidth(kParamReferenceWidth);
        QCOMPARE(int(stage.m_run), 3);
        QCOMPARE(double(stage.m_error), 1.5);
        stage.setFrameWidth(1280);
        QCOMPARE(int(stage.m_run), 12);
        QCOMPARE(double(stage.m_error), 6.0);
        QCOMPARE(int(stage.m_count), 6); // a count is no length
        QCOMPARE(stage.pixelScale(), 4.0);
        stage.setFrameWidth(480); // 1.5 times: a whole number rounds
        QCOMPARE(int(stage.m_run), 5);

        // The registry keeps the value as set, at the reference width, and says which scale.
        const std::vector<ParamInfo> params = stage.params();
        QCOMPARE(params.size(), std::size_t(4));
        QCOMPARE(params[0].value, 3.0);
        QVERIFY(params[0].scales_with_width);
        QCOMPARE(params[1].value, 1.5);
        QVERIFY(params[1].scales_with_width);
        QVERIFY(!params[2].scales_with_width);
        QVERIFY(stage.setParam("run", 5).ok());
        QCOMPARE(int(stage.m_run), int(std::lround(5 * 1.5)));
        QCOMPARE(stage.params()[0].value, 5.0);

        // A tiny frame: a length never goes below its range (a scan line spacing of 0 would
        // never end), and one whose range allows 0 may shrink to it.
        stage.setFrameWidth(32);
        QCOMPARE(int(stage.m_spacing), 1);
        QCOMPARE(int(stage.m_run), 1); // 5 x 0.1 = 0.5 rounds up
        QCOMPARE(double(stage.m_error), 0.15);
        stage.setFrameWidth(16);
        QCOMPARE(int(stage.m_run), 0);
    }

    void everyLengthOfTheStandardPipelineScales()
    {
        // Every stage parameter in px is a length in the image: none may be left at 320's size.
        int lengths = 0;
        for (const StageDescriptor& stage : Pipeline::standard().descriptors())
            for (const ParamInfo& p : stage.params) {
                QCOMPARE(p.scales_with_width, p.unit == "px");
                lengths += p.scales_with_width;
            }
        QVERIFY(lengths > 20);
    }

    void hdFrameFindsWhatTheSmallFrameFinds()
    {
        // The same scenes at 320x240 and 1280x720 (lab2: a ball and goalposts in view).
        QTemporaryDir tmp;
        QVERIFY(tmp.isValid());
        const Scored small = generateAndScore(tmp.filePath("sd"), 320, 240, 2);
        const Scored hd = generateAndScore(tmp.filePath("hd"), 1280, 720, 2);
        QCOMPARE(small.width, 320);
        QCOMPARE(hd.width, 1280);
        const EvaluationScores& a = small.scores;
        const EvaluationScores& b = hd.scores;
        qInfo("320x240: ball %d/%d/%d, posts %d/%d/%d, obstacles FP %d; 1280x720: ball "
              "%d/%d/%d, posts %d/%d/%d, obstacles FP %d",
              a.of<Ball>().tp, a.of<Ball>().fp, a.of<Ball>().fn, a.of<Goalpost>().tp,
              a.of<Goalpost>().fp, a.of<Goalpost>().fn, a.of<Obstacle>().fp, b.of<Ball>().tp,
              b.of<Ball>().fp, b.of<Ball>().fn, b.of<Goalpost>().tp, b.of<Goalpost>().fp,
              b.of<Goalpost>().fn, b.of<Obstacle>().fp);
        QVERIFY(a.of<Ball>().tp == 2 && a.of<Goalpost>().tp >= 2);
        QCOMPARE(b.of<Ball>().tp, a.of<Ball>().tp);
        QCOMPARE(b.of<Ball>().fp, 0);
        QVERIFY(b.of<Goalpost>().tp >= a.of<Goalpost>().tp);
        QCOMPARE(b.of<Goalpost>().fp, 0);
        QVERIFY(b.of<Obstacle>().fp <= a.of<Obstacle>().fp);
        QVERIFY(b.boundaryMeanError() >= 0 && b.boundaryMeanError() < 4 * 2.0);
    }
};

FIELDSIGHT_TEST_SUITE(TestFrameSize, Core)

#include "test_frame_size.moc"
