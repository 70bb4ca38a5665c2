// `fieldsight import`: a B-Human log folder made into a stream folder. A small log made here (one
// frame marked invalid) gives a manifest whose horizons are the log's lines at the image's edges
// and whose parameters open with the stream; outputs that exist, bad rows and missing frames are
// refused naming them, nothing written. On the real log (reference_data, skipped when absent):
// 160 frames, 22 without a horizon, each horizon equal to the one the tests' own reader of
// frames.csv computes.
#include "support/test_suite.h"
#include "support/child_process.h"
#include "support/reference_streams.h"
#include "support/test_images.h"
#include "visioncore/io/bhuman_log.h"
#include "visioncore/services/stream_runner.h"

#include <nlohmann/json.hpp>

#include <QtTest>

#include <QTemporaryDir>

#include <filesystem>

#include <sys/stat.h>

using namespace fieldsight;
using Json = nlohmann::json;
using fieldsight::test::Outcome;

namespace {

const char* kHeader = "frame,timestamp_ms,jpeg_bytes,cam_matrix_valid,horizon_origin_x,"
                      "horizon_origin_y,horizon_dir_x,horizon_dir_y\n";

} // namespace

class TestLogImport : public QObject
{
    Q_OBJECT

    QTemporaryDir m_dir;

    std::string path(const std::string& name) const
    {
        return m_dir.filePath(QString::fromStdString(name)).toStdString();
    }

    Outcome fieldsight(const std::vector<std::string>& args)
    {
        return test::runChild(FIELDSIGHT_EXE, args, m_dir.path().toStdString());
    }

    /// A log of three 32x24 frames; `rows` replaces frames.csv's rows when given.
    std::string makeLog(const std::string& name, const std::string& rows = {})
    {
        const std::string log = path(name);
        std::filesystem::create_directories(log + "/frames_ycbcr");
        for (int i = 0; i < 3; ++i)
            fieldsight::test::imwrite(log + "/frames_ycbcr/f00" + std::to_string(i) + ".png",
                                      cv::Mat(24, 32, CV_8UC3, cv::Scalar(90, 100, 110 + i)));
        test::writeBytes(log + "/frames.csv",
                         kHeader + (rows.empty() ? "0,1000,5,1,15.5,10.0,1.0,0.0\n"
                                                   "1,1040,5,0,15.5,0,1,0\n"
                                                   "2,1080,5,1,15.5,12.0,0.8,0.6\n"
                                                 : rows));
        return log;
    }

private slots:
    void initTestCase() { QVERIFY(m_dir.isValid()); }

    void aLineGivesTheHorizonAtTheImagesEdges()
    {
        // f000 of the real log: origin (159.5, 29.714), direction (0.999921, 0.012589).
        const auto h = horizonOfLine({159.5, 29.714}, {0.999921, 0.012589}, 320);
        QVERIFY(h);
        QVERIFY(std::abs(h->y_left - 27.706) < 1e-3);
        QVERIFY(std::abs(h->y_right - 31.722) < 1e-3);
        QVERIFY(!horizonOfLine({10, 10}, {0, 1}, 320)); // vertical: no row line
    }

    void aLogBecomesAStreamWithItsHorizonsAndParameters()
    {
        const std::string log = makeLog("log");
        const std::string out = path("imported");
        const Outcome o =
            fieldsight({"import", log, "--out", out, "--set", "transitions.goal_colour=9"});
        QVERIFY2(o.status == 0, o.err.c_str());
        QVERIFY2(o.out.find("3 frames") != std::string::npos, o.out.c_str());
        const Json manifest = Json::parse(test::readAll(out + "/stream.json"));
        QCOMPARE(manifest.at("pixel_format").get<std::string>(), std::string("ycbcr"));
        QCOMPARE(manifest.at("params").get<std::string>(), std::string("params.json"));
        const Json& frames = manifest.at("frames");
        QCOMPARE(frames.size(), std::size_t(3));
        QCOMPARE(frames[0].at("horizon"), Json::parse("[10.0, 10.0]"));
        QVERIFY(!frames[1].contains("horizon")); // marked invalid in the log
        // Direction (0.8, 0.6): slope 0.75 through (15.5, 12).
        QCOMPARE(frames[2].at("horizon")[0].get<double>(), 0.375);
        QCOMPARE(frames[2].at("horizon")[1].get<double>(), 23.625);
        QCOMPARE(frames[2].at("timestamp_ms").get<double>(), 1080.0);

        // It opens as a stream, with its horizons and its own parameters.
        auto input = openStreamInput(out, path("none.lut"));
        QVERIFY(!input.ok()); // no table in this log, and none given
        auto reader = openStream(out);
        QVERIFY2(reader.ok(), reader ? "" : reader.error().message.c_str());
        QCOMPARE(reader.value()->info().frame_count, std::size_t(3));
        auto f2 = reader.value()->read(2);
        QVERIFY(f2.ok() && f2.value().horizon);
        QCOMPARE(f2.value().horizon->y_right, 23.625);
        auto params = streamParams(reader.value()->info(), Pipeline::standard());
        QVERIFY(params.ok());
        QCOMPARE(params.value().values.at("transitions").at("goal_colour"), 9.0);
    }

    void nothingIsWrittenOverOrHalfWritten()
    {
        const std::string log = makeLog("log2");
        const std::string taken = path("taken");
        std::filesystem::create_directories(taken);
        test::writeBytes(taken + "/keep.txt", "mine");
        Outcome o = fieldsight({"import", log, "--out", taken});
        QCOMPARE(o.status, 2);
        QVERIFY2(o.err.find("not an empty folder") != std::string::npos, o.err.c_str());
        QCOMPARE(test::readAll(taken + "/keep.txt"), std::string("mine"));

        const std::string bad = makeLog("bad_row", "0,1000,5,1,15.5,ten,1,0\n");
        o = fieldsight({"import", bad, "--out", path("from_bad")});
        QCOMPARE(o.status, 2);
        QVERIFY2(o.err.find("frames.csv: line 2: horizon_origin_y is not a number") !=
                     std::string::npos,
                 o.err.c_str());
        QVERIFY(!std::filesystem::exists(path("from_bad")));

        const std::string gap = makeLog("gap", "0,1000,5,1,15.5,10,1,0\n7,1040,5,1,15.5,10,1,0\n");
        o = fieldsight({"import", gap, "--out", path("from_gap")});
        QCOMPARE(o.status, 2);
        QVERIFY2(o.err.find("f007.png is missing") != std::string::npos, o.err.c_str());
        QVERIFY(!std::filesystem::exists(path("from_gap")));

        o = fieldsight({"import", path("taken"), "--out", path("x")});
        QCOMPARE(o.status, 2);
        QVERIFY2(o.err.find("not a log folder") != std::string::npos, o.err.c_str());
    }

    void aByteOrderMarkBeforeTheHeaderIsNoPartOfIt()
    {
        const std::string log = makeLog("bom");
        test::writeBytes(log + "/frames.csv",
                         std::string("\xEF\xBB\xBF") + kHeader + "0,1000,5,1,15.5,10.0,1.0,0.0\n");
        const Outcome o = fieldsight({"import", log, "--out", path("from_bom")});
        QVERIFY2(o.status == 0, o.err.c_str());
        QVERIFY2(o.out.find("1 frames") != std::string::npos, o.out.c_str());
    }

    void rowsAndFramesThatCannotMakeAStreamAreNamedNothingWritten()
    {
        const auto refused = [&](const std::string& log, const std::string& out) {
            const Outcome o = fieldsight({"import", log, "--out", path(out)});
            if (o.status != 2 || std::filesystem::exists(path(out)))
                return std::string("exit ") + std::to_string(o.status);
            return o.err;
        };
        // A frame listed twice: the CSV's line, not a hidden folder the copy failed in.
        const std::string twice =
            refused(makeLog("twice", "0,1000,5,1,15.5,10,1,0\n1,1040,5,1,15.5,10,1,0\n"
                                     "0,1080,5,1,15.5,10,1,0\n"),
                    "from_twice");
        QVERIFY2(twice.find("frames.csv: line 4: frame 0 again (line 2 has it already)") !=
                         std::string::npos &&
                     twice.find(".partial") == std::string::npos,
                 twice.c_str());

        // A frame that is a FIFO is no regular file (not "missing"; and nothing waits on it).
        const std::string fifo_log = makeLog("fifo");
        std::filesystem::remove(fifo_log + "/frames_ycbcr/f001.png");
        QCOMPARE(::mkfifo((fifo_log + "/frames_ycbcr/f001.png").c_str(), 0600), 0);
        const std::string fifo = refused(fifo_log, "from_fifo");
        QVERIFY2(fifo.find("line 3: its frame") != std::string::npos &&
                     fifo.find("f001.png is a FIFO, not a regular file") != std::string::npos,
                 fifo.c_str());

        // Each frame decodes, at the first one's size: checked here, not found by `eval` later.
        const std::string small_log = makeLog("small");
        fieldsight::test::imwrite(small_log + "/frames_ycbcr/f002.png", cv::Mat(12, 16, CV_8UC3));
        const std::string small = refused(small_log, "from_small");
        QVERIFY2(small.find("line 4") != std::string::npos &&
                     small.find("f002.png: frame size 16x12 differs from the stream's 32x24") !=
                         std::string::npos,
                 small.c_str());
        const std::string cut_log = makeLog("cut");
        const std::string f1 = cut_log + "/frames_ycbcr/f001.png";
        const std::string bytes = test::readAll(f1);
        test::writeBytes(f1, bytes.substr(0, bytes.size() / 2));
        const std::string cut = refused(cut_log, "from_cut");
        QVERIFY2(cut.find("line 3") != std::string::npos &&
                     cut.find("f001.png") != std::string::npos,
                 cut.c_str());
    }

    void theRealLogKeepsEveryLoggedHorizon()
    {
        const QString log = test::referencePath("bhuman2009_log_coltable");
        if (log.isEmpty() || !QFileInfo(log + "/frames.csv").exists())
            QSKIP("reference_data/bhuman2009_log_coltable is absent");
        const std::string out = path("bhuman");
        const Outcome o = fieldsight({"import", log.toStdString(), "--out", out});
        QVERIFY2(o.status == 0, o.err.c_str());
        const auto rows = test::readBhumanFramesCsv(log + "/frames.csv");
        QVERIFY(rows);
        const Json frames = Json::parse(test::readAll(out + "/stream.json")).at("frames");
        QCOMPARE(frames.size(), rows->size());
        int without = 0;
        for (std::size_t i = 0; i < rows->size(); ++i) {
            const auto& row = (*rows)[i];
            QCOMPARE(frames[i].contains("horizon"), row.valid);
            without += !row.valid;
            if (!row.valid)
                continue;
            const auto h = row.horizon(320);
            QVERIFY(std::abs(frames[i].at("horizon")[0].get<double>() - h[0]) < 2e-3);
            QVERIFY(std::abs(frames[i].at("horizon")[1].get<double>() - h[1]) < 2e-3);
        }
        QCOMPARE(without, 22);
        auto input = openStreamInput(out, "");
        QVERIFY2(input.ok(), input ? "" : input.error().message.c_str());
        QCOMPARE(input.value().info().width, 320);
    }
};

FIELDSIGHT_TEST_SUITE(TestLogImport, None)

#include "test_log_import.moc"
