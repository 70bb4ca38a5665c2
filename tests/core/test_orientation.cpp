// A stream's orientation (docs/formats.md): stream.json's "orientation" and the commands'
// --orientation turn the stored pictures upright as they are read, so a stream stored turned gives
// the same frames, horizons and detections as its upright copy; anything but a quarter turn is
// refused naming the file and the value; saving the orientation keeps the manifest's other keys.
#include "support/test_suite.h"
#include "support/synthetic_frames.h"
#include "support/turned_streams.h"
#include "visioncore/datawrappers/stream_data_wrapper.h"
#include "visioncore/io/stream_reader.h"
#include "visioncore/services/results_json.h"
#include "visioncore/services/stream_runner.h"

#include <nlohmann/json.hpp>
#include <opencv2/core.hpp>

#include <QProcess>
#include <QTemporaryDir>
#include <QtTest>

#include <filesystem>
#include <fstream>
#include <sstream>

using namespace fieldsight;
namespace fs = std::filesystem;

namespace {

constexpr int kTurnedFrames = 3;

std::vector<cv::Mat> scenes()
{
    std::vector<cv::Mat> frames;
    for (int i = 0; i < kTurnedFrames; ++i)
        frames.push_back(test::uprightScene(i));
    return frames;
}

/// Horizons that matter: the core searches only below them, and the ball is at row 160.
std::vector<Horizon> horizons()
{
    return {{50, 56}, {58, 52}, {55, 55}};
}

bool samePixels(const cv::Mat& a, const cv::Mat& b)
{
    return a.size() == b.size() && a.type() == b.type() && cv::norm(a, b, cv::NORM_INF) == 0;
}

std::string readText(const std::string& path)
{
    std::ifstream in(path, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

void writeText(const std::string& path, const std::string& text)
{
    std::ofstream(path, std::ios::binary) << text;
}

/// The frames of a results document without their timings: what the pipeline found.
nlohmann::json foundIn(const std::string& results_text)
{
    nlohmann::json doc = nlohmann::json::parse(results_text, nullptr, false);
    if (!doc.is_object() || !doc.contains("frames"))
        return nullptr;
    nlohmann::json frames = doc["frames"];
    for (auto& f : frames)
        f.erase("time_ms");
    return frames;
}

/// Runs the pipeline over `stream` (opened with `options`) with `threads` workers.
nlohmann::json detect(const std::string& stream, StreamOptions options = {}, int threads = 1)
{
    auto input = openStreamInput(stream, "", Pipeline::standard(), options);
    if (!input) {
        qWarning("%s", input.error().message.c_str());
        return nullptr;
    }
    auto run = runStream(input.value(), firstFrames(input.value().info().frame_count), threads);
    if (!run)
        return nullptr;
    return foundIn(
        resultsJson(resultsHeader(input.value()), run.value().frames, Pipeline::standard().ids()));
}

std::string openError(const std::string& stream)
{
    auto opened = openStream(stream);
    return opened ? std::string("(opened)") : opened.error().message;
}

} // namespace

class TestOrientation : public QObject
{
    Q_OBJECT

    QTemporaryDir m_dir;
    std::string m_upright;      ///< the scenes as they are, with their horizons
    std::string m_half;         ///< stored upside down, "orientation": 180
    std::string m_half_unnamed; ///< stored upside down, no "orientation"

    std::string path(const std::string& name) const
    {
        return m_dir.filePath(QString::fromStdString(name)).toStdString();
    }

    struct Outcome
    {
        int status = -1;
        QByteArray out, err;
    };
    Outcome fieldsight(const QStringList& args)
    {
        QProcess process;
        process.setWorkingDirectory(m_dir.path());
        process.start(QStringLiteral(FIELDSIGHT_EXE), args);
        Outcome o;
        if (!process.waitForFinished(120000)) {
            process.kill();
            process.waitForFinished();
            return o;
        }
        o.status = process.exitStatus() == QProcess::NormalExit ? process.exitCode() : -1;
        o.out = process.readAllStandardOutput();
        o.err = process.readAllStandardError();
        return o;
    }

private slots:
    void initTestCase()
    {
        QVERIFY(m_dir.isValid());
        m_upright = path("upright");
        m_half = path("half");
        m_half_unnamed = path("half_unnamed");
        QVERIFY(
            test::writeTurnedStream(m_upright, scenes(), {Orientation::Upright, {}, horizons()}));
        QVERIFY(test::writeTurnedStream(m_half, scenes(), {Orientation::Half, 180, horizons()}));
        QVERIFY(test::writeTurnedStream(m_half_unnamed, scenes(),
                                        {Orientation::Half, std::nullopt, horizons()}));
    }

    void halfTurnedStreamGivesTheUprightFramesAndHorizons()
    {
        auto half = openStream(m_half);
        QVERIFY(half);
        const StreamInfo& info = half.value()->info();
        QCOMPARE(info.orientation, Orientation::Half);
        QCOMPARE(info.stream_orientation, Orientation::Half);
        QCOMPARE(info.width, 320);
        QCOMPARE(info.height, 240);
        for (int i = 0; i < kTurnedFrames; ++i) {
            auto frame = half.value()->read(std::size_t(i));
            QVERIFY(frame);
            QVERIFY2(samePixels(frame.value().ycbcr, test::uprightScene(i)),
                     qPrintable(QString("frame %1").arg(i)));
            // The stored picture's horizon turns with it.
            QVERIFY(frame.value().horizon);
            QCOMPARE(*frame.value().horizon, horizons()[std::size_t(i)]);
        }
        // The same through the DataWrapper the commands use.
        StreamDataWrapper data(std::move(half).value(), test::testLut());
        QCOMPARE(data.orientation(), Orientation::Half);
        QVERIFY(data.seek(2));
        QVERIFY(samePixels(data.image(), test::uprightScene(2)));
        QCOMPARE(data.kinematicHorizon(), horizons()[2]);
    }

    void halfTurnedStreamGivesTheUprightDetections()
    {
        const nlohmann::json upright = detect(m_upright);
        QVERIFY(upright.is_array());
        QCOMPARE(int(upright.size()), kTurnedFrames);
        for (int i = 0; i < kTurnedFrames; ++i) {
            // Not an empty comparison: the ball is found where it is drawn.
            const nlohmann::json& balls = upright[std::size_t(i)]["balls"];
            QCOMPARE(int(balls.size()), 1);
            QVERIFY(std::abs(balls[0]["x"].get<double>() - (100 + 30 * i)) <= 2.0);
            QVERIFY(std::abs(balls[0]["y"].get<double>() - 160) <= 2.0);
        }
        QCOMPARE(detect(m_half).dump(), upright.dump());
        // Workers with readers of their own turn them alike.
        QCOMPARE(detect(m_half, {}, 2).dump(), upright.dump());
        // The override: the same stored pictures without the manifest's word.
        QCOMPARE(detect(m_half_unnamed, {Orientation::Half}).dump(), upright.dump());
        // And the comparison can fail: the stored pictures as they are give other detections.
        QVERIFY(detect(m_half_unnamed).dump() != upright.dump());
        QVERIFY(detect(m_half, {Orientation::Upright}).dump() != upright.dump());
    }

    void quarterTurnsServeTheUprightPictureWithoutAHorizon()
    {
        const std::string plain = path("plain");
        QVERIFY(test::writeTurnedStream(plain, scenes(), {Orientation::Upright, {}, {}}));
        const nlohmann::json upright = detect(plain);
        for (const Orientation o : {Orientation::Clockwise90, Orientation::Clockwise270}) {
            const std::string dir = path("quarter_" + orientationText(o));
            QVERIFY(test::writeTurnedStream(dir, scenes(), {o, degrees(o), horizons()}));
            auto stored = openStream(dir, {Orientation::Upright});
            QVERIFY(stored);
            QCOMPARE(stored.value()->info().width, 240); // stored on its side
            QCOMPARE(stored.value()->info().height, 320);
            QVERIFY(stored.value()->read(0).value().horizon);

            auto turned = openStream(dir);
            QVERIFY(turned);
            QCOMPARE(turned.value()->info().orientation, o);
            QCOMPARE(turned.value()->info().width, 320);
            QCOMPARE(turned.value()->info().height, 240);
            for (int i = 0; i < kTurnedFrames; ++i) {
                auto frame = turned.value()->read(std::size_t(i));
                QVERIFY(frame);
                QVERIFY(samePixels(frame.value().ycbcr, test::uprightScene(i)));
                // A horizon turned a quarter is no row line: the whole image is searched.
                QVERIFY(!frame.value().horizon);
            }
            // Another reader of the stream (a worker's) serves the same turned frames.
            auto again = turned.value()->reopen();
            QVERIFY(again);
            QCOMPARE(again.value()->info().orientation, o);
            QVERIFY(samePixels(again.value()->read(1).value().ycbcr, test::uprightScene(1)));
            QCOMPARE(detect(dir).dump(), upright.dump());
        }
    }

    void orientationMustBeAQuarterTurn()
    {
        const std::string dir = path("bad_orientation");
        QVERIFY(test::writeTurnedStream(dir, scenes(), {Orientation::Upright, 45, {}}));
        const std::string manifest = (fs::path(dir) / "stream.json").string();
        std::string message = openError(dir);
        QVERIFY2(message.find(manifest) != std::string::npos, message.c_str());
        QVERIFY2(message.find("\"orientation\"") != std::string::npos, message.c_str());
        QVERIFY2(message.find("not 45") != std::string::npos, message.c_str());

        nlohmann::json doc = nlohmann::json::parse(readText(manifest));
        doc["orientation"] = "180";
        writeText(manifest, doc.dump());
        message = openError(dir);
        QVERIFY2(message.find("not \"180\"") != std::string::npos, message.c_str());

        doc["orientation"] = 180.0; // a whole number written as a decimal is still 180
        writeText(manifest, doc.dump());
        QCOMPARE(openStream(dir).value()->info().orientation, Orientation::Half);

        // The older "flipped": true means 180; the two must agree.
        doc.erase("orientation");
        doc["flipped"] = true;
        writeText(manifest, doc.dump());
        QCOMPARE(openStream(dir).value()->info().orientation, Orientation::Half);
        doc["orientation"] = 90;
        writeText(manifest, doc.dump());
        message = openError(dir);
        QVERIFY2(message.find(manifest) != std::string::npos &&
                     message.find("disagree") != std::string::npos,
                 message.c_str());
    }

    void eachManifestWriteReplacesOnlyItsOwnKey()
    {
        const std::string dir = path("to_save");
        QVERIFY(test::writeTurnedStream(dir, scenes(), {Orientation::Half, {}, horizons()}));
        const std::string manifest = (fs::path(dir) / "stream.json").string();
        nlohmann::ordered_json before = nlohmann::ordered_json::parse(readText(manifest));
        before["flipped"] = false;
        before["camera"] = {{"fov_deg", {62.8, 48.8}}};
        writeText(manifest, before.dump());

        QVERIFY(writeStreamOrientation(dir, Orientation::Half));
        nlohmann::ordered_json after = nlohmann::ordered_json::parse(readText(manifest));
        QCOMPARE(after["orientation"].get<int>(), 180);
        QVERIFY(!after.contains("flipped")); // "orientation" replaces it
        after.erase("orientation");
        before.erase("flipped");
        QCOMPARE(after.dump(), before.dump()); // every other key, in its order
        QCOMPARE(openStream(dir).value()->info().orientation, Orientation::Half);
        QCOMPARE(detect(dir).dump(), detect(m_upright).dump());

        // The table and the parameter file are written the same way: their one key replaced in
        // the manifest as it is on disk then (another writer's keys kept), named from the folder.
        before = nlohmann::ordered_json::parse(readText(manifest));
        before["by_another_writer"] = "kept";
        writeText(manifest, before.dump());
        QVERIFY(writeStreamLut(dir, (fs::path(dir) / "venue.lut").string()));
        QVERIFY(writeStreamParams(dir, (fs::path(dir) / "venue_params.json").string()));
        after = nlohmann::ordered_json::parse(readText(manifest));
        before["lut"] = "venue.lut"; // replaced where it was
        before["params"] = "venue_params.json";
        QCOMPARE(after.dump(), before.dump());

        // A folder without a manifest gets one with the format and the orientation.
        const std::string bare = path("bare");
        QVERIFY(test::writeTurnedStream(bare, scenes(), {Orientation::Half, {}, {}}));
        fs::remove(fs::path(bare) / "stream.json");
        QVERIFY(writeStreamOrientation(bare, Orientation::Clockwise90));
        QCOMPARE(
            readText((fs::path(bare) / "stream.json").string()),
            std::string("{\n \"format\": \"fieldsight-stream/1\",\n \"orientation\": 90\n}\n"));

        // A manifest the stream does not open with is never written over.
        writeText(manifest, "{\"format\": \"fieldsight-stream/1\", ");
        Status damaged = writeStreamOrientation(dir, Orientation::Upright);
        QVERIFY(!damaged);
        QVERIFY2(damaged.error().message.find(manifest) != std::string::npos,
                 damaged.error().message.c_str());
        QCOMPARE(readText(manifest), std::string("{\"format\": \"fieldsight-stream/1\", "));

        // Nor is a read-only folder written into (even by root, who could).
        fs::remove(fs::path(bare) / "stream.json");
        fs::permissions(bare, fs::perms::owner_read | fs::perms::owner_exec);
        Status read_only = writeStreamOrientation(bare, Orientation::Half);
        fs::permissions(bare, fs::perms::owner_all);
        QVERIFY(!read_only);
        QVERIFY2(read_only.error().message.find("read-only") != std::string::npos,
                 read_only.error().message.c_str());
        QVERIFY(!fs::exists(fs::path(bare) / "stream.json"));
    }

    void commandsTakeOrientation()
    {
        const QString half = QString::fromStdString(m_half_unnamed);
        const QString upright_json = m_dir.filePath("upright.json");
        QCOMPARE(
            fieldsight({"run", QString::fromStdString(m_upright), "--out", upright_json}).status,
            0);
        const QString half_json = m_dir.filePath("half.json");
        const Outcome run = fieldsight({"run", half, "--orientation", "180", "--out", half_json});
        QCOMPARE(run.status, 0);
        const std::string upright_text = readText(upright_json.toStdString());
        const std::string half_text = readText(half_json.toStdString());
        QCOMPARE(foundIn(half_text).dump(), foundIn(upright_text).dump());
        const nlohmann::json doc = nlohmann::json::parse(half_text);
        QCOMPARE(doc["orientation"].get<int>(), 180);
        QVERIFY(!nlohmann::json::parse(upright_text).contains("orientation"));

        // A quarter turn reports the turned size.
        const QString quarter_json = m_dir.filePath("quarter.json");
        QCOMPARE(
            fieldsight({"run", QString::fromStdString(path("quarter_90")), "--out", quarter_json})
                .status,
            0);
        const nlohmann::json quarter = nlohmann::json::parse(readText(quarter_json.toStdString()));
        QCOMPARE(quarter["width"].get<int>(), 320);
        QCOMPARE(quarter["height"].get<int>(), 240);
        QCOMPARE(quarter["orientation"].get<int>(), 90);

        // Anything but a quarter turn is bad usage, named.
        const Outcome bad = fieldsight({"run", half, "--orientation", "45", "--out", "-"});
        QCOMPARE(bad.status, 2);
        QVERIFY2(bad.err.contains("--orientation") && bad.err.contains("'45'"),
                 bad.err.constData());
        QCOMPARE(bad.err.count('\n'), 1);

        // bench and eval take it too: the annotations are in the upright frame.
        nlohmann::json frames = nlohmann::json::object();
        for (int i = 0; i < kTurnedFrames; ++i) {
            char name[32];
            std::snprintf(name, sizeof name, "frame_%06d.png", i);
            frames[name] = {{"done", true},
                            {"balls", {{{"x", 100 + 30 * i}, {"y", 160}, {"radius", 9}}}}};
        }
        const std::string truth = path("truth.json");
        writeText(
            truth,
            nlohmann::json{{"format", "fieldsight-annotations/1"}, {"frames", frames}}.dump());
        const auto ballTp = [&](const QStringList& extra) {
            const QString json = m_dir.filePath("eval.json");
            QStringList args{"eval",   half, "--truth", QString::fromStdString(truth),
                             "--json", json};
            const Outcome o = fieldsight(args + extra);
            if (o.status != 0)
                return -1;
            return nlohmann::json::parse(readText(json.toStdString()))["classes"]["ball"]["tp"]
                .get<int>();
        };
        QCOMPARE(ballTp({"--orientation", "180"}), kTurnedFrames);
        QVERIFY(ballTp({}) < kTurnedFrames);

        const QString bench_json = m_dir.filePath("bench.json");
        const Outcome bench = fieldsight({"bench", QString::fromStdString(path("quarter_270")),
                                          "--orientation", "0", "--json", bench_json});
        QCOMPARE(bench.status, 0);
        const nlohmann::json b = nlohmann::json::parse(readText(bench_json.toStdString()));
        QCOMPARE(b["width"].get<int>(), 240); // as stored: the override wins over the manifest
        QCOMPARE(b["height"].get<int>(), 320);

        // lut build reads the samples' pixels in the frame they were drawn on.
        const std::string samples = path("samples.json");
        writeText(samples, R"({"format": "fieldsight-lut-samples/1", "smoothing": 0, "samples": [
            {"frame": "frame_000000.png", "colour": "orange",
             "polygon": [[97,157],[103,157],[103,163],[97,163]]}]})");
        const auto orangeFound = [&](const QStringList& extra) {
            const QString out = m_dir.filePath("built.lut");
            QFile::remove(out);
            const Outcome o =
                fieldsight(QStringList{"lut", "build", half, "--samples",
                                       QString::fromStdString(samples), "--out", out} +
                           extra);
            if (o.status != 0)
                return false;
            const auto lut = ColourLut::load(out.toStdString());
            const test::ClassPixel p = test::pixelFor(Colour::Orange);
            return lut && lut.value().classify(p.y, p.cb, p.cr) == Colour::Orange;
        };
        QVERIFY(orangeFound({"--orientation", "180"}));
        QVERIFY(!orangeFound({}));
    }
};

FIELDSIGHT_TEST_SUITE(TestOrientation, Core)

#include "test_orientation.moc"
