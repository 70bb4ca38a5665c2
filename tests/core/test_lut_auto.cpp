// The automatic table (visioncore/services/lut_auto.h): from the frames alone it finds what the
// stream's ideal table finds on the bundled generated streams, the same frames give the same
// table, a cancel keeps what was read, frames without a carpet give a note and an empty table,
// annotations add their votes, a team's pink and a hidden ball leave the ball orange, the goal's
// colour is the one mostly posts, and the goal-colour parameter is found through the registry.
#include "support/test_suite.h"
#include "support/synthetic_frames.h"
#include "support/test_images.h"
#include "visioncore/basics/ycbcr.h"
#include "visioncore/framework/controller.h"
#include "visioncore/services/evaluation.h"
#include "visioncore/services/lut_auto.h"
#include "visioncore/services/stream_runner.h"

#include <QtTest>

#include <QTemporaryDir>

#include <opencv2/imgproc.hpp>

using namespace fieldsight;

namespace {

std::string bundled(const char* name)
{
    return test::sampleStreamsDir() + "/" + name;
}

EvaluationScores scoresWith(const std::string& stream, const ColourLut* lut)
{
    auto input = openStreamInput(stream, "");
    if (!input.ok())
        qFatal("%s", input.error().message.c_str());
    if (lut)
        input.value().lut = std::make_shared<const ColourLut>(*lut);
    const std::string truth_path = defaultTruthPath(stream);
    auto truth = Annotations::load(truth_path, Pipeline::standard().perceptKinds());
    if (!truth.ok())
        qFatal("%s", truth.error().message.c_str());
    auto report = evaluateStream(input.value(), truth.value(), truth_path, 2);
    if (!report.ok())
        qFatal("%s", report.error().message.c_str());
    return report.value().scores;
}

AutoLut autoTable(const std::string& stream, const AutoLutOptions& options = {})
{
    auto reader = openStream(stream);
    if (!reader.ok())
        qFatal("%s", reader.error().message.c_str());
    auto made = buildAutoLut(*reader.value(), options);
    if (!made.ok())
        qFatal("%s", made.error().message.c_str());
    return std::move(made).value();
}

std::size_t cellsOf(const AutoLut& made, Colour colour)
{
    for (const AutoLutClass& c : made.classes)
        if (c.colour == colour)
            return c.cells;
    return 0;
}

} // namespace

class TestLutAuto : public QObject
{
    Q_OBJECT

private slots:
    void findsWhatTheIdealTableFinds_data()
    {
        QTest::addColumn<QString>("stream");
        QTest::newRow("lab2") << "lab2";
        QTest::newRow("difficult") << "difficult";
    }

    void findsWhatTheIdealTableFinds()
    {
        QFETCH(QString, stream);
        const std::string path = bundled(stream.toUtf8().constData());
        const AutoLut made = autoTable(path);
        QVERIFY(!made.cancelled);
        QCOMPARE(made.goal_colour, std::optional<Colour>(Colour::Yellow));
        for (const Colour c : {Colour::Green, Colour::White, Colour::Orange, Colour::Yellow})
            QVERIFY2(cellsOf(made, c) > 0, colourName(c).data());
        QCOMPARE(cellsOf(made, Colour::Blue), std::size_t(0));

        const EvaluationScores ideal = scoresWith(path, nullptr);
        const EvaluationScores automatic = scoresWith(path, &made.lut);
        qInfo("ball %.3f/%.3f (ideal %.3f/%.3f), goalpost %.3f/%.3f (ideal %.3f/%.3f)",
              automatic.of<Ball>().precision(), automatic.of<Ball>().recall(),
              ideal.of<Ball>().precision(), ideal.of<Ball>().recall(),
              automatic.of<Goalpost>().precision(), automatic.of<Goalpost>().recall(),
              ideal.of<Goalpost>().precision(), ideal.of<Goalpost>().recall());
        QVERIFY(ideal.of<Ball>().tp > 0 && ideal.of<Goalpost>().tp > 0);
        // Measured: lab2 ball 1.000/1.000 (ideal the same), posts 0.980/0.941 (1.000/0.961);
        // difficult ball 0.885/1.000 and posts 1.000/1.000 (the ideal table's the same).
        QVERIFY(automatic.of<Ball>().recall() >= ideal.of<Ball>().recall() - 0.03);
        QVERIFY(automatic.of<Goalpost>().recall() >= ideal.of<Goalpost>().recall() - 0.03);
        QVERIFY(automatic.of<Ball>().precision() >= ideal.of<Ball>().precision() - 0.03);
        QVERIFY(automatic.of<Goalpost>().precision() >= 0.95);
    }

    void theSameFramesGiveTheSameTable()
    {
        AutoLutOptions options;
        options.frames = 8;
        const AutoLut a = autoTable(bundled("lab1"), options);
        const AutoLut b = autoTable(bundled("lab1"), options);
        QCOMPARE(a.frames, std::size_t(8));
        QVERIFY(a.lut == b.lut);
        QCOMPARE(a.classes.size(), b.classes.size());
        for (std::size_t i = 0; i < a.classes.size(); ++i) {
            QCOMPARE(a.classes[i].cells, b.classes[i].cells);
            QCOMPARE(a.classes[i].pixel_share, b.classes[i].pixel_share);
        }
        double share = 0;
        for (const AutoLutClass& c : a.classes)
            share += c.pixel_share;
        QVERIFY(share > 0.5 && share <= 1.0);
    }

    void aCancelKeepsTheFramesRead()
    {
        auto reader = openStream(bundled("lab2"));
        QVERIFY(reader.ok());
        std::size_t calls = 0;
        auto made = buildAutoLut(*reader.value(), {}, [&](std::size_t done, std::size_t total) {
            ++calls;
            return done < 3 && total > 3;
        });
        QVERIFY(made.ok());
        QVERIFY(made.value().cancelled);
        QCOMPARE(made.value().frames, std::size_t(3));
        QCOMPARE(calls, std::size_t(3));
    }

    void framesWithoutACarpetGiveANoteAndAnEmptyTable()
    {
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        for (int i = 0; i < 2; ++i) {
            cv::Mat grey(120, 160, CV_8UC3, cv::Scalar(4, 4, 4)); // too dark for any class
            QVERIFY(fieldsight::test::imwrite(
                dir.filePath(QString("frame_%1.png").arg(i)).toStdString(), grey));
        }
        auto reader = openStream(dir.path().toStdString());
        QVERIFY(reader.ok());
        auto made = buildAutoLut(*reader.value());
        QVERIFY(made.ok());
        QVERIFY(made.value().classes.empty());
        QVERIFY(made.value().lut == ColourLut());
        QVERIFY(!made.value().goal_colour);
        QCOMPARE(made.value().notes.size(), std::size_t(1));
        QVERIFY(made.value().notes[0].find("no carpet") != std::string::npos);
    }

    void annotationsAddTheirVotes()
    {
        const std::string stream = bundled("lab2");
        auto truth =
            Annotations::load(defaultTruthPath(stream), Pipeline::standard().perceptKinds());
        QVERIFY(truth.ok());
        AutoLutOptions options;
        options.frames = 6;
        const AutoLut alone = autoTable(stream, options);
        options.annotations = &truth.value();
        const AutoLut with = autoTable(stream, options);
        QVERIFY(!(alone.lut == with.lut));
        QVERIFY(std::any_of(with.notes.begin(), with.notes.end(), [](const std::string& n) {
            return n.find("the annotations of") != std::string::npos;
        }));
    }

    // A team's pink band that looks like a ball is not the ball, and a ball that a robot hides in
    // most frames (a shape that is not round) does not hold its colour back from the round one.
    // Before the pink hue was told from the warm one, the pink blobs made the ball's colour; before
    // warm shapes that are not round kept out of the ball's core, its colour stayed unclassified.
    void pinkBandsAndHiddenBallsLeaveTheBallOrange()
    {
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        const cv::Scalar carpet(40, 140, 40), wall(150, 150, 150), robot(70, 70, 70); // B, G, R
        const cv::Scalar ball(20, 100, 230), pink(180, 105, 255);
        for (int i = 0; i < 12; ++i) {
            cv::Mat frame(240, 320, CV_8UC3, carpet);
            cv::rectangle(frame, cv::Rect(0, 0, 320, 70), wall, cv::FILLED);
            // Pink bands of far robots standing on the carpet, in every frame.
            for (int k = 0; k < 3; ++k)
                cv::circle(frame, {60 + 90 * k, 110 + 10 * (i % 3)}, 6, pink, cv::FILLED,
                           cv::LINE_8);
            const cv::Point at(80 + 12 * i, 180);
            cv::circle(frame, at, 12, ball, cv::FILLED, cv::LINE_8);
            if (i >= 3) // hidden but for a crescent
                cv::circle(frame, at + cv::Point(5, 0), 11, robot, cv::FILLED, cv::LINE_8);
            QVERIFY(fieldsight::test::imwrite(
                dir.filePath(QString("frame_%1.png").arg(i, 2, 10, QChar('0'))).toStdString(),
                frame));
        }
        const AutoLut made = autoTable(dir.path().toStdString());
        const auto ycc = [](const cv::Scalar& bgr) {
            return bgrToYcbcr(cv::Mat(1, 1, CV_8UC3, bgr)).at<cv::Vec3b>(0, 0);
        };
        const cv::Vec3b b = ycc(ball);
        const cv::Vec3b p = ycc(pink);
        QCOMPARE(made.lut.classify(b[0], b[1], b[2]), Colour::Orange);
        QVERIFY(made.lut.classify(p[0], p[1], p[2]) != Colour::Orange);
    }

    // People in blue standing at the field's edge give more bar-like pixels than the one yellow
    // post in view, but the post is nearly all of its colour's shapes and the legs a small share of
    // theirs: the goal is yellow. (Weighing pixels by share took blue.)
    void theGoalIsTheColourMostlyPosts()
    {
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        const cv::Scalar carpet(40, 140, 40), wall(150, 150, 150); // B, G, R
        const cv::Scalar yellow(0, 220, 230), blue(200, 60, 20);
        for (int i = 0; i < 8; ++i) {
            cv::Mat frame(240, 320, CV_8UC3, carpet);
            cv::rectangle(frame, cv::Rect(0, 0, 320, 100), wall, cv::FILLED);
            const int shift = 3 * i;
            cv::rectangle(frame, cv::Rect(20 + shift, 45, 8, 60), yellow, cv::FILLED);
            for (int k = 0; k < 2; ++k) {
                const int x = 90 + 110 * k + shift;
                cv::rectangle(frame, cv::Rect(x, 0, 90, 60), blue, cv::FILLED);      // a body
                cv::rectangle(frame, cv::Rect(x + 10, 60, 6, 45), blue, cv::FILLED); // legs
                cv::rectangle(frame, cv::Rect(x + 74, 60, 6, 45), blue, cv::FILLED);
            }
            QVERIFY(fieldsight::test::imwrite(
                dir.filePath(QString("frame_%1.png").arg(i, 2, 10, QChar('0'))).toStdString(),
                frame));
        }
        const AutoLut made = autoTable(dir.path().toStdString());
        for (const std::string& note : made.notes)
            qInfo("%s", note.c_str());
        QCOMPARE(made.goal_colour, std::optional<Colour>(Colour::Yellow));
    }

    void theGoalColourParameterComesFromTheRegistry()
    {
        const auto param = goalColourParam(Pipeline::standard());
        QVERIFY(param.has_value());
        ParamSet set;
        set.set(param->stage, param->name, double(int(Colour::Blue)));
        QVERIFY(set.check(Pipeline::standard()).ok());
        QCOMPARE(param->default_value, double(int(Colour::Yellow)));
        QVERIFY(!goalColourParam(Pipeline{}).has_value());
    }
};

FIELDSIGHT_TEST_SUITE(TestLutAuto, Core)

#include "test_lut_auto.moc"
