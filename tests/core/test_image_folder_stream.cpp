// Image-folder streams (SPEC §4): pixel formats, manifest, natural order and bad input.
#include "support/test_suite.h"
#include "support/stderr_capture.h"
#include "support/synthetic_frames.h"
#include "support/test_images.h"
#include "visioncore/datawrappers/stream_data_wrapper.h"
#include "visioncore/io/stream_reader.h"
#include "visioncore/basics/ycbcr.h"

#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>

#include <QtTest>

#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>

#include <sys/resource.h>
#include <unistd.h>

using namespace fieldsight;
using fieldsight::test::stderrOf;

namespace {

void writeText(const QTemporaryDir& dir, const char* name, const std::string& text)
{
    std::ofstream out(dir.filePath(name).toStdString(), std::ios::binary);
    out << text;
}

/// Writes a PNG whose pixels are given as R, G, B (the file's own channel order).
void writePngRgb(const QTemporaryDir& dir, const char* name, int width, int height,
                 const std::vector<cv::Vec3b>& rgb_pixels)
{
    cv::Mat bgr(height, width, CV_8UC3);
    for (int i = 0; i < width * height; ++i) {
        const cv::Vec3b p = rgb_pixels[std::size_t(i) % rgb_pixels.size()];
        bgr.at<cv::Vec3b>(i / width, i % width) = {p[2], p[1], p[0]};
    }
    QVERIFY(fieldsight::test::imwrite(dir.filePath(name).toStdString(), bgr));
}

std::unique_ptr<StreamReader> openOk(const QTemporaryDir& dir)
{
    auto opened = openStream(dir.path().toStdString());
    if (!opened.ok())
        qWarning("%s", opened.error().message.c_str());
    return opened.ok() ? std::move(opened).value() : nullptr;
}

std::string openError(const QTemporaryDir& dir)
{
    auto opened = openStream(dir.path().toStdString());
    return opened.ok() ? std::string("(opened)") : opened.error().message;
}

/// The encoding of a 32x24 frame (green, an orange disc) in `ext`'s format.
std::string encodedFrame(const char* ext)
{
    cv::Mat bgr(24, 32, CV_8UC3, cv::Scalar(40, 160, 60));
    cv::circle(bgr, {16, 12}, 5, cv::Scalar(0, 128, 255), -1);
    std::vector<unsigned char> bytes;
    fieldsight::test::imencode(ext, bgr, bytes);
    return std::string(bytes.begin(), bytes.end());
}

/// The error reading frame 1 (`bytes`, named `name`) after a good frame 0 of the same format,
/// with what was printed on stderr meanwhile.
std::pair<std::string, std::string> secondFrameError(const char* name, const std::string& bytes)
{
    QTemporaryDir dir;
    const std::string ext = std::filesystem::path(name).extension().string();
    writeText(dir, ("f0" + ext).c_str(), encodedFrame(ext.c_str()));
    writeText(dir, name, bytes);
    std::string message = "(opened)";
    const std::string printed = stderrOf([&] {
        auto opened = openStream(dir.path().toStdString());
        if (!opened.ok()) {
            message = opened.error().message;
            return;
        }
        auto frame = opened.value()->read(1);
        message = frame.ok() ? "(read)" : frame.error().message;
    });
    const std::string path = dir.filePath(name).toStdString();
    if (message.find(path) != std::string::npos)
        message.replace(message.find(path), path.size(), name);
    return {message, printed};
}

} // namespace

class TestImageFolderStream : public QObject
{
    Q_OBJECT

private slots:
    void rgbFramesBecomeBt601FullRangeYCbCr()
    {
        QTemporaryDir dir;
        // R, G, B of red, green, blue, white, black, mid grey
        writePngRgb(
            dir, "a.png", 6, 1,
            {{255, 0, 0}, {0, 255, 0}, {0, 0, 255}, {255, 255, 255}, {0, 0, 0}, {128, 128, 128}});
        auto reader = openOk(dir);
        QVERIFY(reader);
        QCOMPARE(reader->info().kind, StreamKind::ImageFolder);
        auto frame = reader->read(0);
        QVERIFY(frame.ok());
        const cv::Mat& m = frame.value().ycbcr;
        QCOMPARE(m.type(), CV_8UC3);
        // Y = .299R + .587G + .114B, Cb = 128 + .564(B - Y), Cr = 128 + .713(R - Y), stored Y, Cb,
        // Cr, rounded as OpenCV's fixed-point COLOR_BGR2YCrCb does (green's Cb 43.58 gives 43).
        QCOMPARE(m.at<cv::Vec3b>(0, 0), (cv::Vec3b{76, 85, 255}));
        QCOMPARE(m.at<cv::Vec3b>(0, 1), (cv::Vec3b{150, 43, 21}));
        QCOMPARE(m.at<cv::Vec3b>(0, 2), (cv::Vec3b{29, 255, 107}));
        QCOMPARE(m.at<cv::Vec3b>(0, 3), (cv::Vec3b{255, 128, 128}));
        QCOMPARE(m.at<cv::Vec3b>(0, 4), (cv::Vec3b{0, 128, 128}));
        QCOMPARE(m.at<cv::Vec3b>(0, 5), (cv::Vec3b{128, 128, 128}));
    }

    void ycbcrFramesKeepTheirChannels()
    {
        QTemporaryDir dir;
        writePngRgb(dir, "a.png", 2, 1, {{10, 20, 30}, {200, 100, 50}});
        writeText(dir, "stream.json",
                  R"({"format": "fieldsight-stream/1", "pixel_format": "ycbcr"})");
        auto reader = openOk(dir);
        QVERIFY(reader);
        auto frame = reader->read(0);
        QVERIFY(frame.ok());
        QCOMPARE(frame.value().ycbcr.at<cv::Vec3b>(0, 0), (cv::Vec3b{10, 20, 30}));
        QCOMPARE(frame.value().ycbcr.at<cv::Vec3b>(0, 1), (cv::Vec3b{200, 100, 50}));
    }

    void manifestSuppliesHorizonTimestampLutAndFieldOfView()
    {
        QTemporaryDir dir;
        writePngRgb(dir, "frame_000000.png", 4, 3, {{0, 0, 0}});
        writePngRgb(dir, "frame_000001.png", 4, 3, {{0, 0, 0}});
        writeText(dir, "stream.json", R"({"format": "fieldsight-stream/1",
            "lut": "tables/my.lut", "camera": {"fov_deg": [62.8, 48.8]},
            "frames": [{"file": "frame_000001.png", "timestamp_ms": 33.5, "horizon": [29.9, 31.2]},
                       {"file": "frame_000000.png", "timestamp_ms": 0}]})");
        auto reader = openOk(dir);
        QVERIFY(reader);
        const StreamInfo& info = reader->info();
        QCOMPARE(info.width, 4);
        QCOMPARE(info.height, 3);
        QCOMPARE(info.frame_count, std::size_t(2));
        QCOMPARE(info.default_lut, dir.filePath("tables/my.lut").toStdString());
        QVERIFY(info.fov_deg.has_value());
        QCOMPARE((*info.fov_deg)[0], 62.8);
        QCOMPARE((*info.fov_deg)[1], 48.8);

        auto first = reader->read(0);
        QVERIFY(first.ok());
        QCOMPARE(first.value().name, std::string("frame_000000.png"));
        QVERIFY(!first.value().horizon.has_value());
        auto second = reader->read(1);
        QVERIFY(second.ok());
        QCOMPARE(second.value().timestamp_ms, 33.5);
        QVERIFY(second.value().horizon.has_value());
        QCOMPARE(*second.value().horizon, (Horizon{29.9, 31.2}));

        StreamDataWrapper wrapper(std::move(reader), ColourLut());
        QVERIFY(wrapper.seek(1).ok());
        QCOMPARE(wrapper.kinematicHorizon(), (Horizon{29.9, 31.2}));
        QVERIFY(wrapper.seek(0).ok());
        QCOMPARE(wrapper.kinematicHorizon(), (Horizon{0, 0}));
    }

    void defaultLutInTheFolderIsFoundWithoutManifest()
    {
        QTemporaryDir dir;
        writePngRgb(dir, "a.png", 2, 2, {{0, 0, 0}});
        QVERIFY(openOk(dir)->info().default_lut.empty());
        QVERIFY(ColourLut().save(dir.filePath("default.lut").toStdString()).ok());
        QCOMPARE(openOk(dir)->info().default_lut, dir.filePath("default.lut").toStdString());
    }

    void framesAreInNaturalFileNameOrder()
    {
        QTemporaryDir dir;
        for (const char* name :
             {"frame_10.png", "frame_2.png", "frame_1.bmp", "frame_02b.jpg", "Frame_3.JPEG"})
            writePngRgb(dir, name, 2, 2, {{0, 0, 0}});
        writeText(dir, "notes.txt", "not a frame");
        auto reader = openOk(dir);
        QVERIFY(reader);
        QCOMPARE(reader->info().frame_count, std::size_t(5));
        QStringList names;
        for (std::size_t i = 0; i < reader->info().frame_count; ++i)
            names << QString::fromStdString(reader->frameName(i));
        QCOMPARE(names, (QStringList{"Frame_3.JPEG", "frame_1.bmp", "frame_2.png", "frame_02b.jpg",
                                     "frame_10.png"}));
    }

    void emptyFolderIsAnError()
    {
        QTemporaryDir dir;
        writeText(dir, "readme.txt", "nothing here");
        QCOMPARE(openError(dir),
                 dir.path().toStdString() + ": no images in the folder (.png, .jpg, .jpeg, .bmp)");
    }

    void undecodableImageIsAnErrorNamingTheFile()
    {
        QTemporaryDir dir;
        writePngRgb(dir, "f1.png", 2, 2, {{0, 0, 0}});
        writeText(dir, "f2.png", "this is not a PNG");
        auto reader = openOk(dir);
        QVERIFY(reader);
        QVERIFY(reader->read(0).ok());
        auto bad = reader->read(1);
        QVERIFY(!bad.ok());
        QCOMPARE(bad.error().message,
                 "cannot read " + dir.filePath("f2.png").toStdString() +
                     ": not a decodable image (no PNG, JPEG or BMP signature)");

        // When the first frame is bad, opening already fails.
        QTemporaryDir dir2;
        writeText(dir2, "f0.png", "garbage");
        writePngRgb(dir2, "f1.png", 2, 2, {{0, 0, 0}});
        QCOMPARE(openError(dir2), "cannot read " + dir2.filePath("f0.png").toStdString() +
                                      ": not a decodable image (no PNG, JPEG or BMP signature)");
    }

    void frameOfAnotherSizeIsAnError()
    {
        QTemporaryDir dir;
        writePngRgb(dir, "f1.png", 4, 4, {{0, 0, 0}});
        writePngRgb(dir, "f2.png", 5, 4, {{0, 0, 0}});
        auto reader = openOk(dir);
        QVERIFY(reader);
        auto bad = reader->read(1);
        QVERIFY(!bad.ok());
        QCOMPARE(bad.error().message, dir.filePath("f2.png").toStdString() +
                                          ": frame size 5x4 differs from the stream's 4x4");
    }

    void aFrameClaimingAnotherSizeIsNotDecoded()
    {
        // A 32x24 JPEG whose frame header is changed to claim 8000x6000: libjpeg would decode
        // the missing data as grey, 144 MB. Once the stream's size is known, the header is
        // compared first and nothing is decoded (issue 10: limits before allocating).
        QTemporaryDir dir;
        std::vector<unsigned char> jpeg;
        QVERIFY(fieldsight::test::imencode(
            ".jpg", cv::Mat(24, 32, CV_8UC3, cv::Scalar(40, 160, 60)), jpeg));
        writeText(dir, "f1.jpg", std::string(jpeg.begin(), jpeg.end()));
        std::size_t sof = 2;
        while (sof + 9 < jpeg.size() && jpeg[sof + 1] != 0xC0)
            sof += 2 + (std::size_t(jpeg[sof + 2]) << 8 | jpeg[sof + 3]);
        QVERIFY(sof + 9 < jpeg.size());
        const unsigned char claim[4] = {6000 >> 8, 6000 & 255, 8000 >> 8, 8000 & 255};
        std::memcpy(&jpeg[sof + 5], claim, 4); // height, width
        writeText(dir, "f2.jpg", std::string(jpeg.begin(), jpeg.end()));
        auto reader = openOk(dir);
        QVERIFY(reader);
        struct rusage before
        {
        }, after{};
        ::getrusage(RUSAGE_SELF, &before);
        auto bad = reader->read(1);
        ::getrusage(RUSAGE_SELF, &after);
        QVERIFY(!bad.ok());
        QCOMPARE(bad.error().message, dir.filePath("f2.jpg").toStdString() +
                                          ": frame size 8000x6000 differs from the stream's 32x24");
        QVERIFY2(after.ru_maxrss - before.ru_maxrss < 50 * 1024, "the frame was decoded");
        QVERIFY(reader->read(0).ok());
    }

    void badManifestIsAnErrorNamingStreamJson()
    {
        const std::string json_name = "stream.json";
        struct Case
        {
            const char* text;
            const char* problem;
        };
        const Case cases[] = {
            {"{ \"pixel_format\": ",
             "not valid JSON at line 1, column 19 (syntax error while parsing value - unexpected "
             "end of input; expected '[', '{', or a literal)"},
            {R"({"pixel_format": 3})", "\"pixel_format\" must be \"rgb\" or \"ycbcr\""},
            {R"({"pixel_format": "yuv"})", "\"pixel_format\" must be \"rgb\" or \"ycbcr\""},
            {R"({"format": "fieldsight-stream/9"})",
             "unsupported format \"fieldsight-stream/9\" (expected \"fieldsight-stream/1\")"},
            {R"({"lut": 5})", "\"lut\" must be a string (a file name relative to the folder)"},
            {R"({"params": ["a.json"]})", "\"params\" must be a string (a fieldsight-params/1 file "
                                          "name relative to the folder)"},
            {R"({"camera": {"fov_deg": [60]}})",
             "\"camera.fov_deg\" must be an array of two numbers"},
            {R"({"frames": [{"file": "a.png", "horizon": "high"}]})",
             "frames[0].horizon must be [y at x = 0, y at x = width-1]"},
            // Found by fuzz_stream_manifest: a row beyond int reached the green horizon stage.
            {R"({"frames": [{"file": "a.png", "horizon": [4, 6.9e65]}]})",
             "frames[0].horizon must be two image rows from -1e6 to 1e6"},
            {R"({"frames": [{"file": "a.png", "horizon": [-1000001, 0]}]})",
             "frames[0].horizon must be two image rows from -1e6 to 1e6"},
            {R"({"frames": [{"file": "a.png", "timestamp_ms": "0"}]})",
             "frames[0].timestamp_ms must be a number"},
            {R"({"frames": [{"file": "a.png"}, {"name": "b.png"}]})",
             "frames[1].file must be a string"},
            {R"({"frames": [{"file": "a.png"}, {"file": "a.png", "timestamp_ms": 5}]})",
             "frames[1].file \"a.png\" is listed twice"},
            {R"([1, 2])", "expected a JSON object at the top level"},
        };
        for (const Case& c : cases) {
            QTemporaryDir dir;
            writePngRgb(dir, "a.png", 2, 2, {{0, 0, 0}});
            writeText(dir, "stream.json", c.text);
            QCOMPARE(openError(dir), dir.filePath("stream.json").toStdString() + ": " + c.problem);
        }
    }

    void manifestNamingAMissingFrameIsAnError()
    {
        QTemporaryDir dir;
        writePngRgb(dir, "a.png", 2, 2, {{0, 0, 0}});
        writeText(dir, "stream.json", R"({"frames": [{"file": "b.png"}]})");
        QCOMPARE(openError(dir), dir.filePath("stream.json").toStdString() +
                                     ": frame \"b.png\" is not an image in the folder");
    }

    void missingPathIsAnError()
    {
        auto opened = openStream("/nonexistent/stream");
        QVERIFY(!opened.ok());
        QCOMPARE(opened.error().message,
                 std::string("/nonexistent/stream: no such file or folder"));
        auto camera = openStream("camera:x");
        QVERIFY(!camera.ok());
        QCOMPARE(camera.error().message,
                 std::string("camera:x: expected camera:N with N a camera number (0, 1, ...)"));
    }

    void aHeaderClaimingAHugeImageIsRefusedBeforeDecoding()
    {
        // Small files whose headers claim 30000 x 30000 (PNG), 65535 x 65535 (PNG), 60000 x 9
        // (JPEG) and 9 x 70000 (BMP): each refused by name, quickly, without the allocation.
        const auto png = [](std::uint32_t w, std::uint32_t h) {
            return test::pngHeaderClaiming(w, h) + std::string(64, '\0');
        };
        const std::string jpeg = std::string("\xFF\xD8\xFF\xE0\x00\x04\x00\x00", 8) +
                                 std::string("\xFF\xC0\x00\x11\x08\x00\x09\xEA\x60", 9) +
                                 std::string(64, '\0');
        std::string bmp = "BM" + std::string(24, '\0');
        const std::int32_t bw = 9, bh = 70000;
        std::memcpy(bmp.data() + 18, &bw, 4);
        std::memcpy(bmp.data() + 22, &bh, 4);
        const std::vector<std::pair<std::string, std::string>> cases = {
            {"a.png", png(30000, 30000)},
            {"b.png", png(65535, 65535)},
            {"c.jpg", jpeg},
            {"d.bmp", bmp}};
        QElapsedTimer clock;
        clock.start();
        for (const auto& [name, bytes] : cases) {
            QTemporaryDir dir;
            writeText(dir, name.c_str(), bytes);
            const std::string error = openError(dir);
            QVERIFY2(error.find(dir.filePath(QString::fromStdString(name)).toStdString()) !=
                             std::string::npos &&
                         error.find("header claims") != std::string::npos,
                     error.c_str());
        }
        QVERIFY(clock.elapsed() < 2000);
    }

    void jpegFramesDecodeAsOpenCvDecodesThem()
    {
        // Fieldsight decodes JPEG frames with libjpeg itself (so that libjpeg's own lines are
        // not printed): the pixels must be exactly OpenCV's, for colour and grey frames, and for
        // the real camera frames of the reference data where it is present.
        std::vector<std::string> files;
        QTemporaryDir made;
        cv::Mat colour(48, 64, CV_8UC3);
        cv::randu(colour, 0, 255);
        cv::GaussianBlur(colour, colour, {5, 5}, 2);
        files.push_back(made.filePath("colour.jpg").toStdString());
        QVERIFY(fieldsight::test::imwrite(files.back(), colour));
        files.push_back(made.filePath("grey.jpg").toStdString());
        cv::Mat grey;
        cv::cvtColor(colour, grey, cv::COLOR_BGR2GRAY);
        QVERIFY(fieldsight::test::imwrite(files.back(), grey));
        files.push_back(made.filePath("progressive.jpg").toStdString());
        QVERIFY(fieldsight::test::imwrite(files.back(), colour, {cv::IMWRITE_JPEG_PROGRESSIVE, 1}));
        if (const std::string ref = test::referenceDataDir(); !ref.empty())
            for (const auto& entry :
                 std::filesystem::directory_iterator(ref + "/nubots_nusight_frames"))
                if (entry.path().extension() == ".jpg")
                    files.push_back(entry.path().string());
        QVERIFY(files.size() >= 3);
        for (const std::string& file : files) {
            QTemporaryDir dir;
            std::filesystem::copy_file(file, dir.filePath("frame.jpg").toStdString());
            auto reader = openOk(dir);
            QVERIFY2(reader, file.c_str());
            auto frame = reader->read(0);
            QVERIFY2(frame.ok(), file.c_str());
            const cv::Mat expected = bgrToYcbcr(fieldsight::test::imread(file, cv::IMREAD_COLOR));
            QCOMPARE(frame.value().ycbcr.size(), expected.size());
            QVERIFY2(cv::norm(frame.value().ycbcr, expected, cv::NORM_INF) == 0, file.c_str());
        }
    }

    void aDamagedFrameIsRefusedWithOneLineAndNothingPrinted()
    {
        // Damage that libjpeg reports as a warning (and OpenCV's decoders print on stderr) is
        // Fieldsight's one error line, naming the file; the libraries print nothing.
        const std::string jpeg = encodedFrame(".jpg");
        std::string extraneous = jpeg;
        extraneous.insert(extraneous.find("\xFF\xDA"), "\x12\x34"); // before the scan
        const std::string bmp = encodedFrame(".bmp");
        std::string rle = bmp;
        rle[30] = 1; // BI_RLE8
        // A fill byte before the first marker hides the frame header from a walk of the
        // segments, not from libjpeg: the size is compared with libjpeg's reading too.
        std::string filled = jpeg;
        const std::size_t sof = filled.find("\xFF\xC0");
        filled.replace(sof + 5, 4, "\x17\x70\x1F\x40"); // 6000 high, 8000 wide
        filled.insert(2, "\xFF");
        std::string compressed = bmp;
        compressed[30] = 4; // BI_JPEG
        const std::vector<std::pair<std::string, std::string>> cases = {
            {extraneous, "cannot read f1.jpg: damaged JPEG (Corrupt JPEG data: 2 extraneous "
                         "bytes before marker 0xda)"},
            {jpeg.substr(0, jpeg.size() / 2),
             "cannot read f1.jpg: damaged JPEG (Premature end of JPEG file)"},
            {std::string("\xFF\xD8\xFF\xD9", 4),
             "cannot read f1.jpg: undecodable JPEG (JPEG datastream contains no image)"},
            {filled, "f1.jpg: frame size 8000x6000 differs from the stream's 32x24"},
            {bmp.substr(0, 30),
             "cannot read f1.bmp: truncated BMP (the header needs 54 bytes, the file has 30)"},
            {bmp.substr(0, 1000), "cannot read f1.bmp: truncated BMP (24 rows of 96 bytes from "
                                  "byte 54, the file has 1000)"},
            {compressed, "cannot read f1.bmp: damaged BMP (unknown compression 4)"},
            {rle, "cannot read f1.bmp: run-length-compressed BMP, not a camera frame (save "
                  "frames uncompressed)"},
        };
        {
            // The frame claiming 8000x6000 is refused before decoding, not after (144 MB).
            struct rusage before
            {
            }, after{};
            ::getrusage(RUSAGE_SELF, &before);
            (void)secondFrameError("f1.jpg", filled);
            ::getrusage(RUSAGE_SELF, &after);
            QVERIFY2(after.ru_maxrss - before.ru_maxrss < 50 * 1024, "the frame was decoded");
        }
        for (const auto& [bytes, message] : cases) {
            const bool isJpeg = bytes[0] == char(0xFF);
            const auto [error, printed] = secondFrameError(isJpeg ? "f1.jpg" : "f1.bmp", bytes);
            QCOMPARE(QString::fromStdString(error), QString::fromStdString(message));
            QVERIFY2(printed.empty(), printed.c_str());
        }
        // The good frames themselves still read.
        QCOMPARE(secondFrameError("f1.jpg", jpeg).first, std::string("(read)"));
        QCOMPARE(secondFrameError("f1.bmp", bmp).first, std::string("(read)"));
    }
};

FIELDSIGHT_TEST_SUITE(TestImageFolderStream, None)

#include "test_image_folder_stream.moc"
