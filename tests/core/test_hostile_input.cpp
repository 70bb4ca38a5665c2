// Hostile files and machines (issue 21): paths that are no file to read (a FIFO, a device, a
// link loop, a name past the system's limit), frame entries that are no frame, damaged PNGs that
// libpng would talk about, JSON past any real file's size, and running out of memory reading one.
// Each is an answer naming the file, at once; nothing waits, aborts or prints on its own.
#include "support/test_suite.h"
#include "support/stderr_capture.h"
#include "support/sanitizer.h"
#include "support/synthetic_frames.h"
#include "support/test_images.h"
#include "visioncore/basics/colour_lut.h"
#include "visioncore/basics/ycbcr.h"
#include "visioncore/framework/controller.h"
#include "visioncore/framework/param_set.h"
#include "visioncore/io/annotations.h"
#include "visioncore/io/stream_reader.h"
#include "visioncore/services/lut_building.h"

#include <opencv2/imgproc.hpp>

#include <QByteArray>
#include <QElapsedTimer>
#include <QTemporaryDir>
#include <QtTest>

#include <chrono>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <functional>
#include <future>
#include <thread>

#include <fcntl.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

using namespace fieldsight;
using namespace std::chrono_literals;
using test::bigEndian32;
using test::pngChunk;
namespace fs = std::filesystem;

namespace {

void writeFile(const std::string& path, const std::string& bytes)
{
    std::ofstream(path, std::ios::binary | std::ios::trunc) << bytes;
}

/// openStream(`spec`), given 5 s: an open that waits on the FIFO `fifo` is released (a writer
/// opens and closes it) and reported as "(waited)", so the test fails instead of hanging.
std::string openErrorWithin5s(const std::string& spec, const std::string& fifo)
{
    auto opening = std::async(std::launch::async, [spec] {
        auto opened = openStream(spec);
        return opened ? std::string("(opened)") : opened.error().message;
    });
    if (opening.wait_for(5s) == std::future_status::ready)
        return opening.get();
    const int writer = ::open(fifo.c_str(), O_WRONLY | O_NONBLOCK);
    if (writer >= 0)
        ::close(writer);
    opening.wait();
    return "(waited)";
}

/// A PNG with IHDR data `ihdr`, the chunks `before_idat`, and `zlib` as its image data.
std::string pngOf(const std::string& ihdr, const std::string& before_idat, const std::string& zlib)
{
    return std::string("\x89PNG\r\n\x1a\n", 8) + pngChunk("IHDR", ihdr) + before_idat +
           pngChunk("IDAT", zlib) + pngChunk("IEND", "");
}

/// `rows` (each a filter byte and its pixels) compressed as PNG image data.
std::string compressed(const QByteArray& rows)
{
    return qCompress(rows).mid(4).toStdString(); // qCompress puts the length first
}

std::string png(const std::string& ihdr, const std::string& before_idat, const QByteArray& rows)
{
    return pngOf(ihdr, before_idat, compressed(rows));
}

std::string rgbHeader(char depth = 8)
{
    return bigEndian32(16) + bigEndian32(8) + std::string{depth, 2, 0, 0, 0};
}

QByteArray rgbRows(char filter = 0, int rows = 8)
{
    QByteArray out;
    for (int y = 0; y < rows; ++y)
        out += filter + QByteArray(16 * 3, char(40 + y));
    return out;
}

/// The error reading the one-frame folder whose frame is `bytes`, and what was printed meanwhile.
std::pair<std::string, std::string> readPng(const std::string& bytes)
{
    QTemporaryDir dir;
    writeFile(dir.filePath("f.png").toStdString(), bytes);
    std::string message;
    const std::string printed = test::stderrOf([&] {
        auto opened = openStream(dir.path().toStdString());
        message = opened ? "(read)" : opened.error().message;
    });
    const std::string path = dir.filePath("f.png").toStdString();
    if (const auto at = message.find(path); at != std::string::npos)
        message.replace(at, path.size(), "f.png");
    return {message, printed};
}

/// A file of `bytes` bytes that takes no disk (all zeros).
void sparseFile(const std::string& path, std::uintmax_t bytes)
{
    writeFile(path, "");
    fs::resize_file(path, bytes);
}

} // namespace

class TestHostileInput : public QObject
{
    Q_OBJECT

    QTemporaryDir m_dir;
    std::string at(const std::string& name) const
    {
        return m_dir.filePath(name.c_str()).toStdString();
    }

    /// A folder `name` of `frames` small PNG frames.
    std::string stream(const std::string& name, int frames = 2)
    {
        fs::create_directories(at(name));
        for (int i = 0; i < frames; ++i)
            fieldsight::test::imwrite(at(name + "/frame_" + std::to_string(i) + ".png"),
                                      cv::Mat(24, 32, CV_8UC3, cv::Scalar(40, 160 + i, 60)));
        return at(name);
    }

private slots:
    void aStrmOrVideoThatIsAFifoIsRefusedNotWaitedOn()
    {
        // Opening a FIFO waits for a writer: every command used to block for good on one.
        for (const char* name : {"recording.strm", "match.avi", "folder/image.strm"}) {
            fs::create_directories(fs::path(at(name)).parent_path());
            QCOMPARE(::mkfifo(at(name).c_str(), 0644), 0);
        }
        for (const char* name : {"recording.strm", "match.avi"})
            QCOMPARE(
                QString::fromStdString(openErrorWithin5s(at(name), at(name))),
                QString::fromStdString("cannot read " + at(name) + ": a FIFO, not a regular file"));
        // A folder holding only an image.strm FIFO, and a device.
        const std::string folder = openErrorWithin5s(at("folder"), at("folder/image.strm"));
        QVERIFY2(folder != "(waited)", folder.c_str());
        QCOMPARE(openErrorWithin5s("/dev/zero", "/nonexistent"),
                 std::string("cannot read /dev/zero: a character device, not a regular file"));
    }

    void aLinkLoopOrAnOverlongPathSaysWhy()
    {
        // Both used to be "no such file or folder".
        fs::create_symlink(at("loop_b"), at("loop_a"));
        fs::create_symlink(at("loop_a"), at("loop_b"));
        QCOMPARE(QString::fromStdString(openErrorWithin5s(at("loop_a"), "/nonexistent")),
                 QString::fromStdString("cannot open " + at("loop_a") +
                                        ": Too many levels of symbolic links"));
        const std::string long_name = at(std::string(300, 'n'));
        QCOMPARE(QString::fromStdString(openErrorWithin5s(long_name, "/nonexistent")),
                 QString::fromStdString("cannot open " + long_name + ": File name too long"));
        const std::string long_path = "/" + std::string(5000, 'p');
        QVERIFY(openErrorWithin5s(long_path, "/nonexistent").ends_with(": File name too long"));
        // A missing stream is still said plainly.
        QCOMPARE(openErrorWithin5s(at("nothing"), "/nonexistent"),
                 at("nothing") + ": no such file or folder");
    }

    void aFolderWithoutPermissionSaysSo()
    {
        if (::geteuid() == 0)
            QSKIP("permission bits do not bind root");
        stream("locked/inner");
        fs::permissions(at("locked"), fs::perms::none);
        const std::string error = openErrorWithin5s(at("locked/inner"), "/nonexistent");
        fs::permissions(at("locked"), fs::perms::owner_all);
        QCOMPARE(
            QString::fromStdString(error),
            QString::fromStdString("cannot open " + at("locked/inner") + ": Permission denied"));
    }

    void brokenFrameEntriesAreSkippedAndReported()
    {
        // They used to be skipped without a word.
        const std::string s = stream("broken");
        fs::create_symlink(s + "/nowhere.png", s + "/frame_5.png");
        fs::create_symlink(s + "/frame_6.png", s + "/frame_6.png");
        QCOMPARE(::mkfifo((s + "/frame_7.png").c_str(), 0644), 0);
        fs::create_directories(s + "/frame_8.png");
        fs::create_symlink(s + "/nowhere.txt", s + "/notes.txt"); // not named as a frame
        auto opened = openStream(s);
        QVERIFY(opened);
        const StreamInfo& info = opened.value()->info();
        QCOMPARE(info.frame_count, std::size_t(2));
        const std::vector<std::string> expected{
            s + "/frame_5.png: skipped, a link to a file that does not exist",
            s + "/frame_6.png: skipped, a link loop (Too many levels of symbolic links)",
            s + "/frame_7.png: skipped, a FIFO, not a frame file",
            s + "/frame_8.png: skipped, a folder, not a frame file"};
        QCOMPARE(info.warnings, expected);
    }

    void manyBrokenEntriesAreOneShortList()
    {
        const std::string s = stream("many_broken");
        for (int i = 10; i < 40; ++i)
            fs::create_symlink(s + "/nowhere.png", s + "/frame_" + std::to_string(i) + ".png");
        auto opened = openStream(s);
        QVERIFY(opened);
        const std::vector<std::string>& warnings = opened.value()->info().warnings;
        QCOMPARE(warnings.size(), std::size_t(10));
        QCOMPARE(warnings.front(),
                 s + "/frame_10.png: skipped, a link to a file that does not exist");
        QCOMPARE(warnings.back(), std::string("and 21 more entries skipped"));
    }

    void damagedPngsLibpngWouldTalkAboutAreOneLine()
    {
        // Damage only a decoder finds (every checksum is right): libpng printed its own
        // "libpng error" and "libpng warning" lines before Fieldsight's.
        QByteArray few = rgbRows();
        few.chop(100);
        const std::vector<std::pair<std::string, std::string>> refused = {
            {png(rgbHeader(3), "", rgbRows()),
             "cannot read f.png: damaged PNG (Invalid IHDR data)"},
            {png(rgbHeader(), pngChunk("XYZW", "abc"), rgbRows()),
             "cannot read f.png: damaged PNG (XYZW: unhandled critical chunk)"},
            {png(rgbHeader(), "", rgbRows(9)),
             "cannot read f.png: damaged PNG (bad adaptive filter value)"},
            {png(rgbHeader(), "", few), "cannot read f.png: damaged PNG (Not enough image data)"},
            {png(bigEndian32(16) + bigEndian32(8) + std::string{8, 3, 0, 0, 0}, "", rgbRows()),
             "cannot read f.png: damaged PNG (IDAT: Missing PLTE before IDAT)"},
        };
        for (const auto& [bytes, message] : refused) {
            const auto [error, printed] = readPng(bytes);
            QCOMPARE(QString::fromStdString(error), QString::fromStdString(message));
            QVERIFY2(printed.empty(), printed.c_str());
        }
        // Compressed data whose header is damaged.
        std::string zlib = compressed(rgbRows());
        zlib[0] = 0;
        zlib[1] = 1;
        QCOMPARE(readPng(pngOf(rgbHeader(), "", zlib)),
                 std::make_pair(std::string("cannot read f.png: damaged PNG (IDAT: incorrect "
                                            "header check)"),
                                std::string()));
        // What libpng only warns about leaves the pixels whole: read, and nothing printed.
        for (const std::string& chunk :
             {pngChunk("gAMA", bigEndian32(0)), pngChunk("sRGB", "\x09"),
              pngChunk("tIME", std::string("\x07\xe0\x0d\x20\x00\x00\x00", 7)),
              pngChunk("bKGD", "\x00")}) {
            const auto [error, printed] = readPng(png(rgbHeader(), chunk, rgbRows()));
            QCOMPARE(error, std::string("(read)"));
            QVERIFY2(printed.empty(), printed.c_str());
        }
    }

    void pngsOfEveryKindDecodeAsOpenCvDecodesThem()
    {
        // libpng now decodes PNG frames itself: the pixels are exactly cv::imread's.
        cv::Mat colour(24, 32, CV_8UC3);
        cv::randu(colour, 0, 255);
        cv::Mat grey, colour16, grey16, bgra;
        cv::cvtColor(colour, grey, cv::COLOR_BGR2GRAY);
        colour.convertTo(colour16, CV_16UC3, 257.0);
        grey.convertTo(grey16, CV_16UC1, 251.0);
        cv::cvtColor(colour, bgra, cv::COLOR_BGR2BGRA);
        const std::vector<std::pair<cv::Mat, std::vector<int>>> kinds = {
            {colour, {}}, {grey, {}}, {colour16, {}},
            {grey16, {}}, {bgra, {}}, {grey, {cv::IMWRITE_PNG_BILEVEL, 1}}};
        for (const auto& [image, flags] : kinds) {
            QTemporaryDir dir;
            const std::string file = dir.filePath("f.png").toStdString();
            QVERIFY(fieldsight::test::imwrite(file, image, flags));
            auto reader = openStream(dir.path().toStdString());
            QVERIFY(reader);
            auto frame = reader.value()->read(0);
            QVERIFY(frame);
            const cv::Mat expected = bgrToYcbcr(fieldsight::test::imread(file, cv::IMREAD_COLOR));
            QCOMPARE(frame.value().ycbcr.size(), expected.size());
            QVERIFY2(cv::norm(frame.value().ycbcr, expected, cv::NORM_INF) == 0,
                     qPrintable(QString("image type %1").arg(image.type())));
        }
    }

    void jsonPastWhatARealFileNeedsIsRefusedUnread()
    {
        // Parsed, JSON takes 15 to 25 times its size: a 60 MB stream.json took gigabytes. Each
        // reader now refuses a file past its cap before reading it (the files take no disk).
        const std::string s = stream("huge_manifest");
        sparseFile(s + "/stream.json", 60 << 20);
        sparseFile(at("annotations.json"), 40 << 20);
        sparseFile(at("lut_samples.json"), 40 << 20);
        sparseFile(at("params.json"), 2 << 20);
        struct rusage before
        {
        }, after{};
        ::getrusage(RUSAGE_SELF, &before);
        QElapsedTimer clock;
        clock.start();
        auto manifest = openStream(s);
        QVERIFY(!manifest);
        QCOMPARE(QString::fromStdString(manifest.error().message),
                 QString::fromStdString("cannot read " + s +
                                        "/stream.json: too large (62914560 bytes; at most "
                                        "1050624 bytes for a stream.json of 2 frames)"));
        const auto annotations =
            Annotations::load(at("annotations.json"), Pipeline::standard().perceptKinds(), 2);
        QVERIFY(!annotations);
        QCOMPARE(QString::fromStdString(annotations.error().message),
                 QString::fromStdString("cannot read " + at("annotations.json") +
                                        ": too large (41943040 bytes; at most 16785408 bytes "
                                        "for annotations of 2 frames)"));
        const auto samples = loadLutSamples(at("lut_samples.json"), 2);
        QVERIFY(!samples);
        QCOMPARE(QString::fromStdString(samples.error().message),
                 QString::fromStdString("cannot read " + at("lut_samples.json") +
                                        ": too large (41943040 bytes; at most 16785408 bytes "
                                        "for LUT samples of 2 frames)"));
        const auto params = ParamSet::load(at("params.json"));
        QVERIFY(!params);
        QVERIFY2(params.error().message.find("at most 1048576 bytes for a parameters file") !=
                     std::string::npos,
                 params.error().message.c_str());
        const qint64 ms = clock.elapsed();
        ::getrusage(RUSAGE_SELF, &after);
        qInfo("four files past their caps refused in %lld ms, peak memory grew %ld kB", ms,
              after.ru_maxrss - before.ru_maxrss);
        QVERIFY2(after.ru_maxrss - before.ru_maxrss < 20 * 1024, "a refused file was read");
        // A real stream's files are far below their caps.
        const std::string lab1 = test::sampleStreamsDir() + "/lab1";
        QVERIFY(fs::file_size(lab1 + "/stream.json") < (std::uintmax_t(1) << 20) / 50);
        QVERIFY(fs::file_size(lab1 + "/annotations.json") < maxAnnotationsBytes(30) / 50);
    }

    void runningOutOfMemoryReadingAFileIsAnErrorNamingIt()
    {
        if (test::kUnderSanitizer)
            QSKIP("an address-space cap cannot be tested under AddressSanitizer (its allocator "
                  "ends the process instead of throwing std::bad_alloc)");
        // Within its cap a file can still need more memory than is left: the reader says so,
        // naming the file (it used to end the process with an uncaught std::bad_alloc). Run in
        // a child whose address space is capped 64 MB above what it already uses: reading the
        // 48 MB file (of a stream long enough for that) fits, taking its string apart does not. (A
        // string, not a list: the JSON library needs memory again to free a list it had begun, and
        // ends the process when there is none; the size caps keep a list from getting that far.
        // Plain strings: moc's lexer stumbles on raw strings with unbalanced brackets.)
        const std::string notes(48u << 20, 'x');
        constexpr std::size_t kFrames = 16384; // caps of 80 MiB
        writeFile(at("oom_annotations.json"),
                  "{\"format\": \"fieldsight-annotations/1\", \"notes\": \"" + notes + "\"}");
        writeFile(at("oom_samples.json"),
                  "{\"format\": \"fieldsight-lut-samples/1\", \"notes\": \"" + notes + "\"}");
        const auto inChild = [this](const std::function<std::string()>& read) {
            const std::string out = at("child_message");
            const pid_t pid = ::fork();
            if (pid == 0) {
                std::signal(SIGABRT, SIG_DFL); // not the test runner's handler, which waits on gdb
                long pages = 0;
                std::ifstream("/proc/self/statm") >> pages;
                const rlim_t cap = rlim_t(pages) * rlim_t(::sysconf(_SC_PAGESIZE)) + (64u << 20);
                const rlimit limit{cap, cap};
                ::setrlimit(RLIMIT_AS, &limit);
                const std::string message = read();
                std::ofstream(out, std::ios::trunc) << message;
                ::_exit(0);
            }
            int status = 0;
            const auto start = std::chrono::steady_clock::now();
            while (::waitpid(pid, &status, WNOHANG) == 0) {
                if (std::chrono::steady_clock::now() - start > 30s) {
                    ::kill(pid, SIGKILL);
                    ::waitpid(pid, &status, 0);
                    return std::string("(the child hung)");
                }
                std::this_thread::sleep_for(10ms);
            }
            if (!WIFEXITED(status))
                return std::string("(the child died of signal ") +
                       std::to_string(WTERMSIG(status)) + ")";
            std::ifstream in(out);
            return std::string(std::istreambuf_iterator<char>(in), {});
        };
        const std::string annotations = inChild([this] {
            auto loaded = Annotations::load(at("oom_annotations.json"),
                                            Pipeline::standard().perceptKinds(), kFrames);
            return loaded ? std::string("(read)") : loaded.error().message;
        });
        QCOMPARE(QString::fromStdString(annotations),
                 QString::fromStdString("cannot read " + at("oom_annotations.json") +
                                        ": not enough memory to read it"));
        const std::string samples = inChild([this] {
            auto loaded = loadLutSamples(at("oom_samples.json"), kFrames);
            return loaded ? std::string("(read)") : loaded.error().message;
        });
        QCOMPARE(QString::fromStdString(samples),
                 QString::fromStdString("cannot read " + at("oom_samples.json") +
                                        ": not enough memory to read it"));
    }
};

FIELDSIGHT_TEST_SUITE(TestHostileInput, None)

#include "test_hostile_input.moc"
