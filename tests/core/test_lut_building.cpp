// Building a LUT from samples (visioncore/services/lut_building.h): the samples file, votes into
// exactly the expected cells, smoothing, majority, soft classes, cancel, and a table built from a
// bundled stream's annotations that finds what the stream's ideal LUT finds.
#include "support/test_suite.h"
#include "support/synthetic_frames.h"
#include "visioncore/framework/controller.h"
#include "visioncore/services/evaluation.h"
#include "visioncore/services/lut_building.h"
#include "visioncore/services/lut_editing.h"

#include <nlohmann/json.hpp>

#include <QtTest>

#include <QTemporaryDir>

#include <fstream>
#include <functional>
#include <memory>

using namespace fieldsight;

namespace {

std::uint32_t cellOf(const test::ClassPixel& p)
{
    return std::uint32_t(ColourLut::index(p.y, p.cb, p.cr));
}

std::uint32_t cellAt(std::uint32_t cell, int dy, int db, int dr)
{
    return std::uint32_t(int(cell) + (dy << 14) + (db << 7) + dr);
}

std::vector<cv::Point> rect(int left, int top, int right, int bottom)
{
    return {{left, top}, {right, top}, {right, bottom}, {left, bottom}};
}

/// Classified cells of `lut`, by class.
std::map<Colour, std::set<std::uint32_t>> cellsByClass(const ColourLut& lut)
{
    std::map<Colour, std::set<std::uint32_t>> out;
    for (std::size_t i = 0; i < ColourLut::kCells; ++i)
        if (lut.cell(i) != Colour::Unclassified)
            out[lut.cell(i)].insert(std::uint32_t(i));
    return out;
}

void writeText(const std::string& path, const std::string& text)
{
    std::ofstream(path, std::ios::binary) << text;
}

std::string lab2()
{
    return test::sampleStreamsDir() + "/lab2";
}

/// The samples of a 64 x 48 frame's annotations painted on a frame of one distinct colour a
/// pixel and voted: which class pixel (x, y) voted for (-1: none).
std::function<int(int, int)> votesOfSamples(const Annotations& truth)
{
    const auto samples = samplesFromAnnotations(truth, {64, 48});
    cv::Mat frame(48, 64, CV_8UC3, cv::Scalar(0, 0, 0));
    int i = 0;
    std::vector<const LutSample*> list;
    for (const LutSample& s : samples) {
        if (s.frame != "a.png") // the other frames are not done
            return [](int, int) { return -2; };
        list.push_back(&s);
    }
    for (int y = 0; y < 48; ++y)
        for (int x = 0; x < 64; ++x, ++i)
            frame.at<cv::Vec3b>(y, x) =
                cv::Vec3b(std::uint8_t(2 * (i >> 12)), std::uint8_t(2 * ((i >> 6) & 63)),
                          std::uint8_t(2 * (i & 63)));
    auto votes = std::make_shared<LutVotes>();
    votes->addFrame(frame, list);
    return [votes, frame](int x, int y) {
        const cv::Vec3b p = frame.at<cv::Vec3b>(y, x);
        const auto it = votes->cells().find(std::uint32_t(ColourLut::index(p[0], p[1], p[2])));
        if (it == votes->cells().end())
            return -1;
        for (int c = 0; c < kColourCount; ++c)
            if (it->second[std::size_t(c)])
                return c;
        return -1;
    };
}

} // namespace

class TestLutBuilding : public QObject
{
    Q_OBJECT

private:
    QTemporaryDir m_dir;
    std::string path(const char* name) const { return m_dir.filePath(name).toStdString(); }

private slots:
    void samplesFileRoundTrips()
    {
        LutSamples samples;
        samples.smoothing = 2;
        samples.samples.push_back({"frame_000000.png", Colour::Orange, rect(1, 2, 5, 7), false});
        samples.samples.push_back(
            {"frame_000003", Colour::PinkOrange, {{0, 0}, {9, 0}, {4, 8}}, false});
        samples.samples.push_back({"frame_000003", Colour::Unclassified, rect(3, 3, 4, 4), true});
        const std::string file = path("samples.json");
        QVERIFY(saveLutSamples(file, samples).ok());
        auto loaded = loadLutSamples(file);
        QVERIFY2(loaded.ok(), loaded.ok() ? "" : loaded.error().message.c_str());
        QCOMPARE(loaded.value().smoothing, 2);
        QCOMPARE(loaded.value().samples.size(), samples.samples.size());
        for (std::size_t i = 0; i < samples.samples.size(); ++i) {
            const LutSample& a = samples.samples[i];
            const LutSample& b = loaded.value().samples[i];
            QCOMPARE(b.frame, a.frame);
            QCOMPARE(b.exclude, a.exclude);
            if (!a.exclude)
                QCOMPARE(b.colour, a.colour);
            QCOMPARE(b.polygon, a.polygon);
        }
        QCOMPARE(lutSamplesToJson(loaded.value()), lutSamplesToJson(samples));
        QCOMPARE(defaultLutSamplesPath(lab2()), lab2() + "/lut_samples.json");
    }

    void unknownKeysOfASamplesFileSurviveASave()
    {
        const std::string file = path("newer.json");
        writeText(file, R"({"format": "fieldsight-lut-samples/1", "smoothing": 1, "samples": [
            {"frame": "f.png", "colour": "orange", "polygon": [[0, 0], [4, 0], [0, 4]],
             "author": "kim", "confidence": 0.5}], "camera": {"id": 3}})");
        auto loaded = loadLutSamples(file);
        QVERIFY2(loaded.ok(), loaded.ok() ? "" : loaded.error().message.c_str());
        const std::string saved = lutSamplesToJson(loaded.value());
        const auto json = nlohmann::ordered_json::parse(saved);
        const auto& sample = json.at("samples").at(0);
        QCOMPARE(sample.at("author").get<std::string>(), std::string("kim"));
        QCOMPARE(sample.at("confidence").get<double>(), 0.5);
        QCOMPARE(json.at("camera").at("id").get<int>(), 3);
        std::vector<std::string> keys;
        for (const auto& item : json.items())
            keys.push_back(item.key());
        QCOMPARE(keys, (std::vector<std::string>{"format", "smoothing", "samples", "camera"}));
        auto again = lutSamplesFromJson(saved, "again.json");
        QVERIFY(again.ok());
        QCOMPARE(lutSamplesToJson(again.value()), saved);
    }

    void badSamplesFilesNameTheFileAndTheProblem_data()
    {
        QTest::addColumn<QString>("text");
        QTest::addColumn<QString>("problem");
        const QString ok = R"("frame": "f.png", "colour": "orange")";
        const QString tri = R"("polygon": [[0, 0], [4, 0], [0, 4]])";
        auto file = [](const QString& samples) {
            return R"({"format": "fieldsight-lut-samples/1", "samples": [)" + samples + "]}";
        };
        QTest::newRow("not json") << "{"
                                  << "not valid JSON";
        QTest::newRow("wrong format") << R"({"format": "fieldsight-annotations/1", "samples": []})"
                                      << "unsupported format \"fieldsight-annotations/1\"";
        QTest::newRow("no format") << R"({"samples": []})"
                                   << "missing \"format\"";
        QTest::newRow("no samples") << R"({"format": "fieldsight-lut-samples/1"})"
                                    << "\"samples\" must be a list";
        QTest::newRow("bad smoothing")
            << R"({"format": "fieldsight-lut-samples/1", "smoothing": -1, "samples": []})"
            << "\"smoothing\" must be";
        QTest::newRow("bad colour") << file(R"({"frame": "f.png", "colour": "mauve", )" + tri + "}")
                                    << "samples[0].colour: unknown colour class \"mauve\"";
        QTest::newRow("two points") << file("{" + ok + R"(, "polygon": [[0, 0], [4, 0]]})")
                                    << "samples[0].polygon has 2 points; a region needs at least 3";
        QTest::newRow("fractional point")
            << file("{" + ok + R"(, "polygon": [[0, 0], [4.5, 0], [0, 4]]})") << "whole pixels";
        QTest::newRow("no frame") << file(R"({"colour": "orange", )" + tri + "}")
                                  << "samples[0].frame";
        QTest::newRow("no colour")
            << file("{\"frame\": \"f.png\", " + tri + "}") << "samples[0]: missing \"colour\"";
        QTest::newRow("frame of another stream")
            << file(R"({"frame": "../lab2/f.png", "colour": "orange", )" + tri + "}")
            << "samples[0].frame \"../lab2/f.png\": the frame name has a path separator";
        QTest::newRow("format of the wrong type")
            << R"({"format": 1, "samples": []})"
            << "\"format\" must be the string \"fieldsight-lut-samples/1\", not a number";
        QTest::newRow("second sample")
            << file("{" + ok + ", " + tri + "}, {" + ok + "}") << "samples[1].polygon";
    }

    void badSamplesFilesNameTheFileAndTheProblem()
    {
        QFETCH(QString, text);
        QFETCH(QString, problem);
        const std::string file = path("bad.json");
        writeText(file, text.toStdString());
        const auto loaded = loadLutSamples(file);
        QVERIFY(!loaded.ok());
        const QString message = QString::fromStdString(loaded.error().message);
        QVERIFY2(message.startsWith(QString::fromStdString(file) + ": "), qPrintable(message));
        QVERIFY2(message.contains(problem), qPrintable(message));

        const auto missing = loadLutSamples(path("no_such.json"));
        QVERIFY(!missing.ok());
        QVERIFY(QString::fromStdString(missing.error().message)
                    .contains(QString::fromStdString(path("no_such.json"))));
    }

    void knownColoursGiveExactlyTheirCells()
    {
        // Left half green, right half orange; one 2x2 white patch the samples leave out.
        cv::Mat frame = test::filledFrame(20, 10, Colour::Green);
        test::fillRect(frame, 10, 0, 19, 9, Colour::Orange);
        test::fillRect(frame, 0, 0, 1, 1, Colour::White);
        const LutSample green{"f.png", Colour::Green, rect(0, 0, 9, 9), false};
        const LutSample orange{"f.png", Colour::Orange, rect(10, 0, 19, 9), false};
        const LutSample hole{"f.png", Colour::Unclassified, rect(0, 0, 1, 1), true};
        LutVotes votes;
        QCOMPARE(votes.addFrame(frame, {&green, &orange, &hole}), std::size_t(200 - 4));
        QCOMPARE(votes.pixels(), std::size_t(196));

        LutBuildOptions options;
        options.smoothing = 0;
        const auto cells = cellsByClass(votes.build(options));
        const std::uint32_t g = cellOf(test::pixelFor(Colour::Green));
        const std::uint32_t o = cellOf(test::pixelFor(Colour::Orange));
        QCOMPARE(cells.size(), std::size_t(2));
        QCOMPARE(cells.at(Colour::Green), (std::set<std::uint32_t>{g}));
        QCOMPARE(cells.at(Colour::Orange), (std::set<std::uint32_t>{o}));
        QCOMPARE(votes.cells().at(g)[std::size_t(Colour::Green)], std::uint32_t(96));
        QCOMPARE(votes.cells().at(o)[std::size_t(Colour::Orange)], std::uint32_t(100));

        // Smoothing 1: each class's 3x3x3 block (100 votes weigh 12.5 even at the corners).
        options.smoothing = 1;
        const auto smoothed = cellsByClass(votes.build(options));
        for (const auto& [colour, centre] : {std::pair{Colour::Green, g}, {Colour::Orange, o}}) {
            std::set<std::uint32_t> block;
            for (int dy = -1; dy <= 1; ++dy)
                for (int db = -1; db <= 1; ++db)
                    for (int dr = -1; dr <= 1; ++dr)
                        block.insert(cellAt(centre, dy, db, dr));
            QCOMPARE(smoothed.at(colour), block);
        }
    }

    void smoothingOneSpreadsIntoTheNeighbouringCells()
    {
        // One vote: weight 1/2 in the 6 face neighbours, 1/4 on edges, 1/8 at corners. With a
        // threshold of 1/2 only the cell and its face neighbours are taken; with 1/8 the whole
        // 3x3x3 block; by default (2) none: a lone pixel is noise.
        const std::uint32_t o = cellOf(test::pixelFor(Colour::Orange));
        LutVotes votes;
        votes.add(o, Colour::Orange);
        LutBuildOptions options;
        options.smoothing = 1;
        QVERIFY(cellsByClass(votes.build(options)).empty());
        options.min_weight = 0.5;
        std::set<std::uint32_t> expected{o};
        for (int d : {-1, 1}) {
            expected.insert(cellAt(o, d, 0, 0));
            expected.insert(cellAt(o, 0, d, 0));
            expected.insert(cellAt(o, 0, 0, d));
        }
        QCOMPARE(cellsByClass(votes.build(options)).at(Colour::Orange), expected);

        options.min_weight = 0.125;
        std::set<std::uint32_t> block;
        for (int dy = -1; dy <= 1; ++dy)
            for (int db = -1; db <= 1; ++db)
                for (int dr = -1; dr <= 1; ++dr)
                    block.insert(cellAt(o, dy, db, dr));
        QCOMPARE(cellsByClass(votes.build(options)).at(Colour::Orange), block);
        options.min_weight = 0.13; // just above a corner's weight
        QCOMPARE(cellsByClass(votes.build(options)).at(Colour::Orange).size(), std::size_t(27 - 8));
        // Smoothing 0 keeps the cell alone.
        options.smoothing = 0;
        QCOMPARE(cellsByClass(votes.build(options)).at(Colour::Orange),
                 (std::set<std::uint32_t>{o}));
    }

    void smoothingSplitsTheSpaceBetweenTwoClassesByWeight()
    {
        // Orange (100 votes) and green (10 votes) two cells apart in Cr: the cell between them
        // gets 50 orange against 5 green and goes to orange; each class keeps its own cell.
        const std::uint32_t o = cellOf(test::pixelFor(Colour::Orange));
        const std::uint32_t g = cellAt(o, 0, 0, 2);
        LutVotes votes;
        votes.add(o, Colour::Orange, 100);
        votes.add(g, Colour::Green, 10);
        const ColourLut lut = votes.build(); // smoothing 1
        QCOMPARE(lut.cell(o), Colour::Orange);
        QCOMPARE(lut.cell(cellAt(o, 0, 0, 1)), Colour::Orange);
        QCOMPARE(lut.cell(g), Colour::Green);
        QCOMPARE(lut.cell(cellAt(g, 0, 0, 1)), Colour::Green);        // 5 green, nothing else
        QCOMPARE(lut.cell(cellAt(g, 1, 1, 1)), Colour::Unclassified); // 10/8 < 2
        const auto cells = cellsByClass(lut);
        // Orange: the whole 3x3x3 block (a corner weighs 12.5). Green: on its own Cr layer the
        // 3x3 square (corners 2.5), one layer further the cell and its 4 face neighbours (5 and
        // 2.5); the layer towards orange is orange's.
        QCOMPARE(cells.at(Colour::Orange).size(), std::size_t(27));
        QCOMPARE(cells.at(Colour::Green).size(), std::size_t(9 + 5));
        QCOMPARE(cells.size(), std::size_t(2));
    }

    void votesResolveToTheMajorityClass()
    {
        // 30 pixels of one colour sampled orange, 10 of the same colour sampled yellow.
        cv::Mat frame = test::filledFrame(10, 4, Colour::Orange);
        const LutSample orange{"f.png", Colour::Orange, rect(0, 0, 9, 2), false};
        const LutSample yellow{"f.png", Colour::Yellow, rect(0, 3, 9, 3), false};
        LutVotes votes;
        votes.addFrame(frame, {&orange, &yellow});
        LutBuildOptions options;
        options.smoothing = 0;
        const ColourLut lut = votes.build(options);
        const std::uint32_t o = cellOf(test::pixelFor(Colour::Orange));
        QCOMPARE(lut.cell(o), Colour::Orange);
        // 10 against 30 is not ambiguous at the default ratio; at 1/4 it is.
        QVERIFY(votes.ambiguousCells(options).empty());
        options.ambiguity_ratio = 0.25;
        const auto ambiguous = votes.ambiguousCells(options);
        QCOMPARE(ambiguous.size(), std::size_t(1));
        QCOMPARE(ambiguous[0].cell, o);
        QCOMPARE(ambiguous[0].winner, Colour::Orange);
        QCOMPARE(ambiguous[0].runner_up, Colour::Yellow);
        QCOMPARE(ambiguous[0].winner_weight, 30.0f);
        QCOMPARE(ambiguous[0].runner_up_weight, 10.0f);

        // Background votes win a cell back to unclassified.
        votes.add(o, Colour::Unclassified, 31);
        QCOMPARE(votes.build(options).cell(o), Colour::Unclassified);
    }

    void softClassesWhereOrangeMeetsYellowOrPink()
    {
        const std::uint32_t o = cellOf(test::pixelFor(Colour::Orange));
        const std::uint32_t p = cellOf(test::pixelFor(Colour::Pink));
        const std::uint32_t y = cellOf(test::pixelFor(Colour::Yellow));
        LutVotes votes;
        votes.add(o, Colour::Orange, 10);
        votes.add(o, Colour::Yellow, 8);
        votes.add(p, Colour::Pink, 10);
        votes.add(p, Colour::Orange, 6);
        votes.add(y, Colour::Yellow, 10);
        votes.add(y, Colour::Orange, 2); // too weak to be soft
        LutBuildOptions options;
        options.smoothing = 0;
        ColourLut lut = votes.build(options);
        QCOMPARE(lut.cell(o), Colour::Orange);
        QCOMPARE(lut.cell(p), Colour::Pink);
        QCOMPARE(lut.cell(y), Colour::Yellow);
        options.soft = true;
        lut = votes.build(options);
        QCOMPARE(lut.cell(o), Colour::YellowOrange);
        QCOMPARE(lut.cell(p), Colour::PinkOrange);
        QCOMPARE(lut.cell(y), Colour::Yellow);
        const auto ambiguous = votes.ambiguousCells(options);
        QCOMPARE(ambiguous.size(), std::size_t(2));
    }

    void annotationsBecomeSamplesOfTheirClasses()
    {
        auto truth = Annotations::fromJson(R"({"format": "fieldsight-annotations/1", "frames": {
            "a.png": {"done": true, "balls": [{"x": 30, "y": 30, "radius": 5}],
                      "goalposts": [{"left": 10, "right": 14, "top": 0, "bottom": 20}],
                      "obstacles": [{"left": 40, "right": 50, "top": 5, "bottom": 25}],
                      "field_boundary": [[0, 10], [63, 10]],
                      "field_lines": [{"x1": 0, "y1": 40, "x2": 63, "y2": 40}]},
            "b.png": {"done": false, "balls": [{"x": 30, "y": 30, "radius": 5}]}}})",
                                           "truth", Pipeline::standard().perceptKinds());
        QVERIFY(truth.ok());
        const auto votedAt = votesOfSamples(truth.value());
        QCOMPARE(votedAt(30, 30), int(Colour::Orange));
        QCOMPARE(votedAt(30, 34), int(Colour::Orange)); // radius 5 shrunk by 1
        QCOMPARE(votedAt(30, 35), -1);                  // the ball's rim: a hole in the green
        QCOMPARE(votedAt(12, 10), int(Colour::Yellow));
        QCOMPARE(votedAt(10, 10), -1); // the post's edge column
        QCOMPARE(votedAt(20, 30), int(Colour::Green));
        QCOMPARE(votedAt(20, 5), int(Colour::Unclassified));  // above the boundary: background
        QCOMPARE(votedAt(20, 10), -1);                        // the boundary itself
        QCOMPARE(votedAt(45, 15), int(Colour::Unclassified)); // an obstacle is no class
        QCOMPARE(votedAt(20, 40), int(Colour::White));
        QCOMPARE(votedAt(20, 42), -1); // beside the line
        QCOMPARE(votedAt(20, 44), int(Colour::Green));
    }

    /// A concealed ball or post (half of it is what hides it) votes for nothing.
    void concealedObjectsVoteForNothing()
    {
        auto truth = Annotations::fromJson(R"({"format": "fieldsight-annotations/1", "frames": {
            "a.png": {"done": true,
                      "balls": [{"x": 30, "y": 30, "radius": 5, "concealed": true}],
                      "goalposts": [{"left": 10, "right": 14, "top": 0, "bottom": 20,
                                     "concealed": true},
                                    {"left": 50, "right": 54, "top": 0, "bottom": 20}],
                      "field_boundary": [[0, 10], [63, 10]]}}})",
                                           "truth", Pipeline::standard().perceptKinds());
        QVERIFY(truth.ok());
        const auto votedAt = votesOfSamples(truth.value());
        QCOMPARE(votedAt(30, 30), -1);
        QCOMPARE(votedAt(12, 15), -1);
        QCOMPARE(votedAt(52, 15), int(Colour::Yellow)); // the plain post
        QCOMPARE(votedAt(20, 30), int(Colour::Green));
    }

    void framesAreFoundByStemAndMissingOnesNamed()
    {
        auto reader = openStream(lab2());
        QVERIFY(reader.ok());
        std::vector<LutSample> samples{
            {"frame_000002", Colour::Green, rect(0, 200, 9, 209), false}};
        auto run = collectLutVotes(*reader.value(), samples);
        QVERIFY(run.ok());
        QCOMPARE(run.value().frames, std::size_t(1));
        QCOMPARE(run.value().votes.pixels(), std::size_t(100));

        samples.push_back({"frame_999999.png", Colour::Green, rect(0, 0, 9, 9), false});
        run = collectLutVotes(*reader.value(), samples);
        QVERIFY(!run.ok());
        QVERIFY2(run.error().message.find("frame_999999.png") != std::string::npos,
                 run.error().message.c_str());
    }

    void cancelStopsAfterTheFrameInHand()
    {
        auto reader = openStream(lab2());
        QVERIFY(reader.ok());
        auto truth =
            Annotations::load(defaultTruthPath(lab2()), Pipeline::standard().perceptKinds());
        QVERIFY(truth.ok());
        const auto samples = samplesFromAnnotations(truth.value(), {320, 240});
        std::size_t calls = 0;
        auto run = collectLutVotes(*reader.value(), samples, [&](std::size_t done, std::size_t) {
            ++calls;
            return done < 3;
        });
        QVERIFY(run.ok());
        QVERIFY(run.value().cancelled);
        QCOMPARE(run.value().frames, std::size_t(3));
        QCOMPARE(calls, std::size_t(3));

        // The votes are exactly those of the first three frames.
        std::vector<LutSample> first;
        for (const LutSample& s : samples)
            if (frameStem(s.frame) <= "frame_000002")
                first.push_back(s);
        auto three = collectLutVotes(*reader.value(), first);
        QVERIFY(three.ok());
        QVERIFY(!three.value().cancelled);
        QCOMPARE(run.value().votes.pixels(), three.value().votes.pixels());
        QCOMPARE(run.value().votes.cells(), three.value().votes.cells());
    }

    void tableBuiltFromAnnotationsFindsWhatTheIdealLutFinds()
    {
        auto input = openStreamInput(lab2(), "");
        QVERIFY(input.ok());
        const std::string truth_path = defaultTruthPath(lab2());
        auto truth = Annotations::load(truth_path, Pipeline::standard().perceptKinds());
        QVERIFY(truth.ok());
        auto ideal = evaluateStream(input.value(), truth.value(), truth_path, 2);
        QVERIFY(ideal.ok());

        const StreamInfo& info = input.value().info();
        const auto samples = samplesFromAnnotations(truth.value(), {info.width, info.height});
        auto reader = openStream(lab2());
        QVERIFY(reader.ok());
        auto run = collectLutVotes(*reader.value(), samples);
        QVERIFY(run.ok());
        QCOMPARE(run.value().frames, truth.value().frames.size());
        input.value().lut = std::make_shared<const ColourLut>(run.value().votes.build());
        auto built = evaluateStream(input.value(), truth.value(), truth_path, 2);
        QVERIFY(built.ok());

        const EvaluationScores& a = ideal.value().scores;
        const EvaluationScores& b = built.value().scores;
        qInfo("ball recall %.3f (ideal %.3f), goalpost recall %.3f (ideal %.3f)",
              b.of<Ball>().recall(), a.of<Ball>().recall(), b.of<Goalpost>().recall(),
              a.of<Goalpost>().recall());
        QVERIFY(a.of<Ball>().tp + a.of<Ball>().fn > 0 &&
                a.of<Goalpost>().tp + a.of<Goalpost>().fn > 0);
        QVERIFY(b.of<Ball>().recall() >= a.of<Ball>().recall() - 0.05);
        QVERIFY(b.of<Goalpost>().recall() >= a.of<Goalpost>().recall() - 0.05);
    }
};

FIELDSIGHT_TEST_SUITE(TestLutBuilding, Core)

#include "test_lut_building.moc"
