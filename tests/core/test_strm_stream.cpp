// Original NUbots image streams (.strm): writer/reader round trip, flips, and damaged files.
#include "support/child_process.h"
#include "support/test_suite.h"
#include "visioncore/datawrappers/stream_data_wrapper.h"
#include "visioncore/io/stream_reader.h"

#include "support/synthetic_frames.h"
#include "support/test_images.h"

#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>

#include <QtTest>

#include <cstring>
#include <filesystem>
#include <limits>
#include <fstream>

using namespace fieldsight;

namespace {

Frame randomFrame(int width, int height, double timestamp_ms, int seed)
{
    Frame frame;
    frame.ycbcr.create(height, width, CV_8UC3);
    cv::RNG rng{std::uint64_t(seed)};
    rng.fill(frame.ycbcr, cv::RNG::UNIFORM, 0, 256);
    frame.timestamp_ms = timestamp_ms;
    return frame;
}

bool sameImage(const cv::Mat& a, const cv::Mat& b)
{
    return a.size() == b.size() && a.type() == b.type() && cv::norm(a, b, cv::NORM_INF) == 0;
}

std::string strmFileBytes(const std::string& path)
{
    return test::readAll(path);
}

template <class T> void put(std::string& out, T value)
{
    char raw[sizeof(T)];
    std::memcpy(raw, &value, sizeof(T));
    out.append(raw, sizeof(T));
}

/// A record header as the original writer laid it out (version >= 1 adds the flipped byte).
std::string header(std::int32_t version, std::int32_t width, std::int32_t height, double ts,
                   bool flipped)
{
    std::string out = "IMAG";
    put(out, version);
    put(out, width);
    put(out, height);
    put(out, ts);
    if (version >= 1)
        out.push_back(flipped ? 1 : 0);
    return out;
}

void writeStrm(const std::string& path, const std::vector<Frame>& frames, bool flipped = false)
{
    auto writer = StrmWriter::create(path);
    QVERIFY(writer.ok());
    for (const Frame& f : frames)
        QVERIFY(writer.value().append(f, flipped).ok());
    QVERIFY(writer.value().close().ok());
}

constexpr std::size_t recordSize(int w, int h)
{
    return 25 + std::size_t(w) * std::size_t(h) * 4;
}

} // namespace

class TestStrmStream : public QObject
{
    Q_OBJECT

private slots:
    void roundTripPreservesPixelsAndTimestamps()
    {
        QTemporaryDir dir;
        const std::string path = dir.filePath("image.strm").toStdString();
        // 7x5 = 35 pixels: not a multiple of 4, so the conversion's tail is exercised too.
        const std::vector<Frame> frames = {randomFrame(7, 5, 0.0, 1), randomFrame(7, 5, 33.25, 2),
                                           randomFrame(7, 5, 1e9 + 0.5, 3)};
        writeStrm(path, frames);
        QCOMPARE(strmFileBytes(path).size(), 3 * recordSize(7, 5));

        auto opened = openStream(path);
        QVERIFY2(opened.ok(), opened.ok() ? "" : opened.error().message.c_str());
        StreamReader& reader = *opened.value();
        QCOMPARE(reader.info().kind, StreamKind::Strm);
        QCOMPARE(reader.info().width, 7);
        QCOMPARE(reader.info().height, 5);
        QCOMPARE(reader.info().frame_count, std::size_t(3));
        QCOMPARE(reader.info().path, path);
        for (std::size_t i : {2u, 0u, 1u, 2u}) { // random access, any order, repeated
            auto frame = reader.read(i);
            QVERIFY(frame.ok());
            QVERIFY(sameImage(frame.value().ycbcr, frames[i].ycbcr));
            QCOMPARE(frame.value().timestamp_ms, frames[i].timestamp_ms);
            QCOMPARE(frame.value().name, reader.frameName(i));
            QVERIFY(!frame.value().horizon.has_value());
        }
        QCOMPARE(reader.frameName(0), std::string("frame_000000"));
        QCOMPARE(reader.frameName(12), std::string("frame_000012"));
        QVERIFY(!reader.read(3).ok());
    }

    void writerLaysOutVersionOneRecordsWithYInBothLumaBytes()
    {
        QTemporaryDir dir;
        const std::string path = dir.filePath("one.strm").toStdString();
        Frame frame;
        frame.ycbcr = cv::Mat(1, 2, CV_8UC3);
        frame.ycbcr.at<cv::Vec3b>(0, 0) = {10, 20, 30};
        frame.ycbcr.at<cv::Vec3b>(0, 1) = {40, 50, 60};
        frame.timestamp_ms = 12.5;
        writeStrm(path, {frame});
        const std::string expected =
            header(1, 2, 1, 12.5, false) + std::string("\x0a\x14\x0a\x1e\x28\x32\x28\x3c", 8);
        QCOMPARE(strmFileBytes(path), expected);
    }

    void flippedRecordIsStoredRotatedAndReadBackUpright()
    {
        QTemporaryDir dir;
        const std::string path = dir.filePath("flipped.strm").toStdString();
        const Frame frame = randomFrame(9, 4, 5.0, 7);
        writeStrm(path, {frame}, true);

        const std::string bytes = strmFileBytes(path);
        QCOMPARE(bytes[24], '\x01'); // the flipped flag
        // The first stored pixel is the frame's bottom-right pixel.
        const cv::Vec3b last = frame.ycbcr.at<cv::Vec3b>(3, 8);
        QCOMPARE(std::uint8_t(bytes[25 + 1]), last[1]);
        QCOMPARE(std::uint8_t(bytes[25 + 2]), last[0]);
        QCOMPARE(std::uint8_t(bytes[25 + 3]), last[2]);

        auto opened = openStream(path);
        QVERIFY(opened.ok());
        auto back = opened.value()->read(0);
        QVERIFY(back.ok());
        QVERIFY(sameImage(back.value().ycbcr, frame.ycbcr));
    }

    void flippedFlagRotatesTheStoredRaster()
    {
        // A hand-made record: raster 3x2 with flipped set reads as that raster rotated 180 degrees.
        QTemporaryDir dir;
        const std::string path = dir.filePath("hand.strm").toStdString();
        std::string bytes = header(1, 3, 2, 0.0, true);
        cv::Mat raster(2, 3, CV_8UC3);
        for (int i = 0; i < 6; ++i) {
            const auto v = std::uint8_t(10 * (i + 1));
            raster.at<cv::Vec3b>(i / 3, i % 3) = {v, std::uint8_t(v + 1), std::uint8_t(v + 2)};
            bytes += char(0);     // Y0, ignored
            bytes += char(v + 1); // Cb
            bytes += char(v);     // Y
            bytes += char(v + 2); // Cr
        }
        test::writeBytes(path, bytes);
        auto opened = openStream(path);
        QVERIFY(opened.ok());
        auto frame = opened.value()->read(0);
        QVERIFY(frame.ok());
        cv::Mat rotated;
        cv::rotate(raster, rotated, cv::ROTATE_180);
        QVERIFY(sameImage(frame.value().ycbcr, rotated));
        QCOMPARE(frame.value().ycbcr.at<cv::Vec3b>(0, 0), (cv::Vec3b{60, 61, 62}));
    }

    void readsVersionZeroRecordsWithoutFlippedByte()
    {
        QTemporaryDir dir;
        const std::string path = dir.filePath("v0.strm").toStdString();
        std::string bytes;
        for (int r = 0; r < 2; ++r) {
            bytes += header(0, 2, 1, 100.0 * r, false);
            bytes += std::string("\x00\x05\x07\x09\x00\x06\x08\x0a", 8);
        }
        test::writeBytes(path, bytes);
        auto opened = openStream(path);
        QVERIFY2(opened.ok(), opened.ok() ? "" : opened.error().message.c_str());
        QCOMPARE(opened.value()->info().frame_count, std::size_t(2));
        auto frame = opened.value()->read(1);
        QVERIFY(frame.ok());
        QCOMPARE(frame.value().timestamp_ms, 100.0);
        QCOMPARE(frame.value().ycbcr.at<cv::Vec3b>(0, 0), (cv::Vec3b{7, 5, 9}));
        QCOMPARE(frame.value().ycbcr.at<cv::Vec3b>(0, 1), (cv::Vec3b{8, 6, 10}));
    }

    void rejectsTruncatedStrmNamingFileRecordAndOffset()
    {
        QTemporaryDir dir;
        const std::string path = dir.filePath("cut.strm").toStdString();
        writeStrm(path,
                  {randomFrame(8, 6, 0, 1), randomFrame(8, 6, 33, 2), randomFrame(8, 6, 66, 3)});
        std::filesystem::resize_file(path, 3 * recordSize(8, 6) - 10);
        auto opened = openStream(path);
        QVERIFY(!opened.ok());
        const std::string& message = opened.error().message;
        QVERIFY2(message.rfind(path + ": record 2 at byte offset " +
                                   std::to_string(2 * recordSize(8, 6)) + ": truncated record",
                               0) == 0,
                 message.c_str());

        // Cut inside the header as well.
        std::filesystem::resize_file(path, recordSize(8, 6) + 10);
        auto opened_again = openStream(path);
        QVERIFY(!opened_again.ok());
        QVERIFY2(opened_again.error().message.find("record 1 at byte offset " +
                                                   std::to_string(recordSize(8, 6)) +
                                                   ": truncated header") != std::string::npos,
                 opened_again.error().message.c_str());
    }

    void rejectsBadMagicNamingRecordAndOffset()
    {
        QTemporaryDir dir;
        const std::string path = dir.filePath("magic.strm").toStdString();
        writeStrm(path, {randomFrame(4, 4, 0, 1), randomFrame(4, 4, 33, 2)});
        std::string bytes = strmFileBytes(path);
        bytes.replace(recordSize(4, 4), 4, "JUNK");
        test::writeBytes(path, bytes);
        auto opened = openStream(path);
        QVERIFY(!opened.ok());
        QCOMPARE(opened.error().message, path + ": record 1 at byte offset " +
                                             std::to_string(recordSize(4, 4)) +
                                             ": bad magic \"JUNK\" (expected \"IMAG\")");
    }

    void rejectsAbsurdFrameSize()
    {
        QTemporaryDir dir;
        const std::string path = dir.filePath("huge.strm").toStdString();
        test::writeBytes(path, header(1, 100000, 240, 0, false) + std::string(64, '\0'));
        auto opened = openStream(path);
        QVERIFY(!opened.ok());
        QCOMPARE(opened.error().message,
                 path + ": record 0 at byte offset 0: absurd frame size 100000x240");
    }

    void rejectsEmptyAndMissingFiles()
    {
        QTemporaryDir dir;
        const std::string path = dir.filePath("empty.strm").toStdString();
        test::writeBytes(path, "");
        auto opened = openStream(path);
        QVERIFY(!opened.ok());
        QCOMPARE(opened.error().message, path + ": empty stream (no records)");

        const std::string missing = dir.filePath("missing.strm").toStdString();
        auto none = openStream(missing);
        QVERIFY(!none.ok());
        QCOMPARE(none.error().message, missing + ": no such file or folder");
    }

    void defaultLutBesideTheStreamIsReported()
    {
        QTemporaryDir dir;
        const std::string path = dir.filePath("image.strm").toStdString();
        writeStrm(path, {randomFrame(4, 4, 0, 1)});
        QVERIFY(openStream(path).value()->info().default_lut.empty());
        QVERIFY(ColourLut().save(dir.filePath("default.lut").toStdString()).ok());
        QCOMPARE(openStream(path).value()->info().default_lut,
                 dir.filePath("default.lut").toStdString());
    }

    void logFolderWithImageStrmOpensTheStream()
    {
        QTemporaryDir dir;
        writeStrm(dir.filePath("3_image.strm").toStdString(), {randomFrame(4, 2, 0, 1)});
        auto opened = openStream(dir.path().toStdString());
        QVERIFY2(opened.ok(), opened.ok() ? "" : opened.error().message.c_str());
        QCOMPARE(opened.value()->info().kind, StreamKind::Strm);
        QCOMPARE(opened.value()->info().width, 4);
    }

    void sensorStrmSuppliesTheHorizon()
    {
        QTemporaryDir dir;
        const std::string path = dir.filePath("image.strm").toStdString();
        // Three NUSensorsData records (design note §4.2), trimmed to a few sensors.
        // Horizon A*x + B*y = C: record 0 is y = 20 - 0.5x, record 1 is invalid.
        // Record 2 is nearly vertical (B = 1e-8): y = 20 / 1e-8 is no row a camera sees.
        const std::string record0 =
            "[0 HeadPitch , 1 Horizon , 2 Orientation ]\n[0 HeadPitch , 1 Horizon ]\n"
            "[[0], [1], [2]]\n[0, 1, 2]\n3 HeadPitch 10 1 0 0 0 0.25 Horizon 10 0 1 0 0 "
            "[0.5, 1, 20] Orientation 10 0 1 0 0 [0, 0, 0] \n";
        const std::string record1 =
            "[0 HeadPitch , 1 Horizon , 2 Orientation ]\n[0 HeadPitch , 1 Horizon ]\n"
            "[[0], [1], [2]]\n[0, 1, 2]\n3 HeadPitch 43 1 0 0 0 0.25 Horizon 43 0 0 0 0 "
            "[] Orientation 43 0 1 0 0 [0, 0, 0] \n";
        std::string record2 = record0;
        record2.replace(record2.find("[0.5, 1, 20]"), 12, "[0.5, 1e-8, 20]");
        writeStrm(path,
                  {randomFrame(11, 4, 0, 1), randomFrame(11, 4, 33, 2), randomFrame(11, 4, 66, 3)});
        test::writeBytes(dir.filePath("sensor.strm").toStdString(), record0 + record1 + record2);

        auto opened = openStream(path);
        QVERIFY(opened.ok());
        auto first = opened.value()->read(0);
        QVERIFY(first.ok());
        QVERIFY(first.value().horizon.has_value());
        QCOMPARE(first.value().horizon->y_left, 20.0);
        QCOMPARE(first.value().horizon->y_right, 15.0); // x = 10
        auto second = opened.value()->read(1);
        QVERIFY(second.ok());
        QVERIFY(!second.value().horizon.has_value());
        auto third = opened.value()->read(2);
        QVERIFY(third.ok());
        QVERIFY(!third.value().horizon.has_value());
    }

    void rawReferencePixelsConvertLikeTheReferencePng()
    {
        const std::string ref = test::referenceDataDir();
        if (ref.empty())
            QSKIP("reference data absent");
        const std::string base = ref + "/bhuman2009_log_coltable/";
        const std::string raw = strmFileBytes(base + "frames_raw_pixel/f000_320x240_Y0CbY1Cr.yuv");
        QCOMPARE(raw.size(), std::size_t(320 * 240 * 4));
        QTemporaryDir dir;
        const std::string path = dir.filePath("bhuman.strm").toStdString();
        test::writeBytes(path, header(1, 320, 240, 486749, false) + raw);

        auto opened = openStream(path);
        QVERIFY(opened.ok());
        auto frame = opened.value()->read(0);
        QVERIFY(frame.ok());
        // The PNG's R, G, B are Y, Cb, Cr; imread returns B, G, R.
        cv::Mat png = fieldsight::test::imread(base + "frames_ycbcr/f000.png", cv::IMREAD_COLOR);
        QVERIFY(!png.empty());
        cv::Mat expected;
        cv::cvtColor(png, expected, cv::COLOR_BGR2RGB);
        QVERIFY(sameImage(frame.value().ycbcr, expected));
        QCOMPARE(frame.value().timestamp_ms, 486749.0);
    }

    void dataWrapperServesFramesAndTheirHorizon()
    {
        QTemporaryDir dir;
        const std::string path = dir.filePath("image.strm").toStdString();
        const std::vector<Frame> frames = {randomFrame(6, 3, 0, 1), randomFrame(6, 3, 33, 2)};
        writeStrm(path, frames);
        auto opened = openStream(path);
        QVERIFY(opened.ok());
        StreamDataWrapper wrapper(std::move(opened).value(), test::testLut());
        QVERIFY(wrapper.seek(1).ok());
        QCOMPARE(wrapper.frameIndex(), std::size_t(1));
        QVERIFY(sameImage(wrapper.image(), frames[1].ycbcr));
        QCOMPARE(wrapper.kinematicHorizon(), (Horizon{0, 0})); // none in the stream: top row
        QCOMPARE(wrapper.lut().classify(230, 128, 128), Colour::White);

        const Status bad = wrapper.seek(2);
        QVERIFY(!bad.ok());
        QCOMPARE(bad.error().message, path + ": frame 2 out of range (2 frames)");
        QCOMPARE(wrapper.frameIndex(), std::size_t(1)); // the previous frame stays current
        QVERIFY(sameImage(wrapper.image(), frames[1].ycbcr));
    }

    void rejectsUnknownVersionsAndNonFiniteTimestamps()
    {
        QTemporaryDir dir;
        const std::string path = dir.filePath("odd.strm").toStdString();
        const std::string pixels(8, '\0');
        test::writeBytes(path, header(7, 2, 1, 0, false) + pixels);
        auto opened = openStream(path);
        QVERIFY(!opened.ok());
        QCOMPARE(opened.error().message,
                 path + ": record 0 at byte offset 0: unsupported version 7 (this reader knows "
                        "versions 0 and 1)");
        const std::size_t record = header(1, 2, 1, 0, false).size() + pixels.size();
        test::writeBytes(
            path, header(1, 2, 1, 0, false) + pixels +
                      header(1, 2, 1, std::numeric_limits<double>::quiet_NaN(), false) + pixels);
        opened = openStream(path);
        QVERIFY(!opened.ok());
        QCOMPARE(opened.error().message, path + ": record 1 at byte offset " +
                                             std::to_string(record) +
                                             ": timestamp is not a finite number");
    }
};

FIELDSIGHT_TEST_SUITE(TestStrmStream, None)

#include "test_strm_stream.moc"
