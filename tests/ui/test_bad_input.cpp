// The bad-input catalogue (issue 10): each kind of broken input or environment a user at a venue
// can meet, run through the real executable in a child process. The command line must exit 2 for
// bad input (1 for an output failure) with exactly one line naming the file and the problem,
// within seconds and bounded memory; the same inputs opened in the window give a message there,
// and the window goes on working.
#include "support/test_suite.h"
#include "support/child_process.h"
#include "support/synthetic_frames.h"
#include "support/window_waits.h"
#include "support/test_images.h"
#include "ui/adapters/local_path.h"
#include "ui/document/lut_document.h"
#include "ui/actions/session_files.h"
#include "ui/main_window.h"
#include "ui/settings/window_settings.h"
#include "visioncore/basics/colour_lut.h"
#include "visioncore/io/stream_reader.h"

#include <QSignalSpy>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QtTest>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sys/stat.h>

using namespace fieldsight;
using namespace fieldsight::test;
namespace fs = std::filesystem;

namespace {

struct Case
{
    std::string name;
    std::vector<std::string> args; ///< after the program name; run in the catalogue's folder
    int status = 2;
    std::vector<std::string> needles; ///< each appears in the one line (the file, the problem)
    /// The window's part: the stream (and LUT) to open there, and the frame whose reading fails
    /// (0: opening fails). Empty: a command-line case only.
    std::string gui_stream;
    std::string gui_lut;
    std::size_t gui_frame = 0;
    rlim_t file_size_limit = RLIM_INFINITY; ///< bytes a write may reach (ulimit -f)
    /// Permission bits do not bind root: as root the command, and the window's part, run as
    /// nobody (permissionBitsBindTheCommand, theWindowMeetsPermissionBits).
    bool needs_permissions = false;
};

/// Runs fieldsight (or `program`) with `args` in `cwd` (tests/support/child_process.h), killing
/// it after `seconds`; `env` adds to its environment ("NAME=value").
Outcome runFieldsight(const std::vector<std::string>& args, const std::string& cwd,
                      rlim_t file_size_limit, bool as_nobody = false,
                      const std::string& program = FIELDSIGHT_EXE, int seconds = 30,
                      std::vector<std::string> env = {})
{
    return runChild(program, args, cwd, file_size_limit, as_nobody, seconds, std::move(env));
}

/// A .strm record (version 1) of a width x height frame.
std::string strmRecord(std::int32_t version, std::int32_t width, std::int32_t height, double t)
{
    std::string r = "IMAG";
    r.append(reinterpret_cast<const char*>(&version), 4);
    r.append(reinterpret_cast<const char*>(&width), 4);
    r.append(reinterpret_cast<const char*>(&height), 4);
    r.append(reinterpret_cast<const char*>(&t), 8);
    if (version >= 1)
        r += '\0';
    for (std::size_t i = 0; i < std::size_t(width) * std::size_t(height); ++i)
        r += std::string{char(90), char(100), char(60), char(120)}; // Y Cb Y Cr-ish bytes
    return r;
}

} // namespace

class TestBadInput : public QObject
{
    Q_OBJECT

    QTemporaryDir m_tmp;
    std::string m_dir; ///< the catalogue's folder (the children's working folder)
    std::string m_good;
    std::vector<Case> m_cases;

    std::string at(const std::string& name) const { return m_dir + "/" + name; }

    /// A 3-frame copy of the sample stream lab1 as `name`.
    void goodStream(const std::string& name)
    {
        const std::string from = sampleStreamsDir() + "/lab1";
        fs::create_directories(at(name));
        // (Plain strings: moc's lexer stumbles on raw strings with unbalanced brackets.)
        std::string manifest = "{\"format\": \"fieldsight-stream/1\", \"frames\": [";
        for (int i = 0; i < 3; ++i) {
            const std::string frame = "frame_00000" + std::to_string(i) + ".png";
            fs::copy_file(from + "/" + frame, at(name + "/" + frame));
            manifest += std::string(i ? ", " : "") + "{\"file\": \"" + frame + "\"}";
        }
        writeBytes(at(name + "/stream.json"), manifest + "]}");
        fs::copy_file(from + "/default.lut", at(name + "/default.lut"));
    }

    /// A 3-frame copy of lab1 as `name`, its frames re-encoded as `ext` (".jpg", ".bmp").
    void encodedStream(const std::string& name, const std::string& ext)
    {
        const std::string from = sampleStreamsDir() + "/lab1";
        fs::create_directories(at(name));
        for (int i = 0; i < 3; ++i) {
            const std::string frame = "frame_00000" + std::to_string(i);
            QVERIFY(
                fieldsight::test::imwrite(at(name + "/" + frame + ext),
                                          fieldsight::test::imread(from + "/" + frame + ".png")));
        }
        fs::copy_file(from + "/default.lut", at(name + "/default.lut"));
    }

    Case& add(std::string name, std::vector<std::string> args, int status,
              std::vector<std::string> needles, std::string gui_stream = {},
              std::string gui_lut = {}, std::size_t gui_frame = 0)
    {
        Case c;
        c.name = std::move(name);
        c.args = std::move(args);
        c.status = status;
        c.needles = std::move(needles);
        c.gui_stream = std::move(gui_stream);
        c.gui_lut = std::move(gui_lut);
        c.gui_frame = gui_frame;
        return m_cases.emplace_back(std::move(c));
    }

    /// Prints the outcome of case `c` and adds what is wrong with it to `failures`.
    static void check(const Case& c, const Outcome& o, QStringList& failures)
    {
        std::string line = o.err;
        if (!line.empty() && line.back() == '\n')
            line.pop_back();
        qInfo("%-50s %6d %8.2f %8.1f  %s", c.name.c_str(), o.status, o.seconds,
              double(o.peak_kb) / 1024, line.c_str());
        QStringList problems;
        if (o.status != c.status)
            problems << QString("exit %1, expected %2").arg(o.status).arg(c.status);
        if (line.find('\n') != std::string::npos || !line.starts_with("fieldsight: "))
            problems << "not exactly one line from fieldsight";
        for (const std::string& needle : c.needles)
            if (line.find(needle) == std::string::npos)
                problems << QString("no \"%1\"").arg(ui::fromLocalPath(needle));
        if (o.seconds > 10)
            problems << QString("took %1 s").arg(o.seconds);
        if (o.peak_kb > 1536 * 1024)
            problems << QString("peak memory %1 MB").arg(o.peak_kb / 1024);
        if (!problems.isEmpty())
            failures << QString::fromStdString(c.name) + ": " + problems.join("; ");
    }

    /// Opens case `c` in the window, adds what is wrong to `failures`, then checks the window
    /// goes on with the good stream; true when the case was shown.
    bool windowCase(ui::MainWindow& w, const Case& c, QStringList& failures)
    {
        const QString name = QString::fromStdString(c.name);
        const QString stream =
            ui::fromLocalPath(c.gui_stream.starts_with("/") ? c.gui_stream : at(c.gui_stream));
        QString message;
        if (c.gui_frame == 0) {
            QSignalSpy opened(&w.files(), &ui::SessionFiles::streamOpened);
            if (!c.gui_lut.empty())
                w.files().openLut(ui::fromLocalPath(c.gui_lut));
            else
                w.files().openStream(stream);
            if (c.gui_lut.empty() && !opened.wait(10000)) {
                failures << name + ": no answer";
                return false;
            }
            message = w.lastMessage();
        } else {
            if (!openAndWait(w, stream)) {
                failures << name + ": did not open";
                return false;
            }
            w.session().stream().setCurrentIndex(c.gui_frame);
            if (!waitForFrame(w, c.gui_frame)) {
                failures << name + ": frame not shown";
                return false;
            }
            message = w.session().stream().current()->error;
            (void)w.view().grab(); // the error is painted, not a crash
        }
        for (const std::string& needle : c.needles)
            if (!message.contains(ui::fromLocalPath(needle)))
                failures << name + ": the window said \"" + message + "\", without \"" +
                                ui::fromLocalPath(needle) + "\"";
        // And the window goes on: the good stream opens and steps.
        if (!openAndWait(w, QString::fromStdString(m_good))) {
            failures << name + ": the good stream no longer opens";
            return true;
        }
        w.session().stream().setCurrentIndex(2);
        if (!waitForFrame(w, 2))
            failures << name + ": cannot step afterwards";
        return true;
    }

private slots:
    void initTestCase()
    {
        QStandardPaths::setTestModeEnabled(true); // the window's settings stay out of the user's
        QVERIFY(m_tmp.isValid());
        m_dir = m_tmp.path().toStdString();
        // Open to others, so that the permission cases can run as nobody when the test is root.
        fs::permissions(m_dir, fs::perms::owner_all | fs::perms::group_read |
                                   fs::perms::group_exec | fs::perms::others_read |
                                   fs::perms::others_exec);
        goodStream("good");
        m_good = at("good");
        const std::string lab1 = sampleStreamsDir() + "/lab1";
        const std::string png1 = readAll(lab1 + "/frame_000001.png");

        // Streams.
        add("missing stream", {"run", "nope"}, 2, {"nope", "no such file or folder"}, "nope");
        fs::create_directories(at("empty"));
        add("empty folder", {"run", "empty"}, 2, {"empty", "no images"}, "empty");
        goodStream("m_trunc");
        writeBytes(at("m_trunc/stream.json"), readAll(at("good/stream.json")).substr(0, 40));
        add("truncated manifest", {"run", "m_trunc"}, 2,
            {"m_trunc/stream.json", "not valid JSON at line 1, column 41"}, "m_trunc");
        goodStream("m_format");
        writeBytes(at("m_format/stream.json"), R"({"format": "fieldsight-stream/7"})");
        add("manifest of an unknown format version", {"run", "m_format"}, 2,
            {"m_format/stream.json", "unsupported format \"fieldsight-stream/7\""}, "m_format");
        goodStream("m_binary");
        writeBytes(at("m_binary/stream.json"), std::string("\x89\x00\xff\xfe binary", 12));
        add("manifest that is binary garbage", {"run", "m_binary"}, 2,
            {"m_binary/stream.json", "not valid JSON"}, "m_binary");
        goodStream("m_fifo");
        fs::remove(at("m_fifo/stream.json"));
        QCOMPARE(::mkfifo(at("m_fifo/stream.json").c_str(), 0644), 0);
        add("manifest that is a FIFO", {"run", "m_fifo"}, 2,
            {"m_fifo/stream.json", "a FIFO, not a regular file"}, "m_fifo");
        goodStream("m_missing");
        fs::remove(at("m_missing/frame_000001.png"));
        add("manifest listing a missing frame", {"run", "m_missing"}, 2,
            {"m_missing/stream.json", "frame_000001.png"}, "m_missing");
        goodStream("m_twice");
        writeBytes(at("m_twice/stream.json"),
                   R"({"frames": [{"file": "frame_000000.png"}, {"file": "frame_000000.png"}]})");
        add("manifest listing a frame twice", {"run", "m_twice"}, 2,
            {"m_twice/stream.json", "listed twice"}, "m_twice");
        goodStream("m_horizon");
        writeBytes(at("m_horizon/stream.json"),
                   R"({"frames": [{"file": "frame_000000.png", "horizon": [4, 6.9e65]}]})");
        add("manifest with a horizon beyond any row", {"run", "m_horizon"}, 2,
            {"m_horizon/stream.json", "frames[0].horizon must be two image rows"}, "m_horizon");
        goodStream("f_trunc");
        writeBytes(at("f_trunc/frame_000001.png"), png1.substr(0, 200));
        add("truncated frame", {"run", "f_trunc"}, 2, {"f_trunc/frame_000001.png", "truncated PNG"},
            "f_trunc", "", 1);
        goodStream("f_empty");
        writeBytes(at("f_empty/frame_000001.png"), "");
        add("empty frame file", {"run", "f_empty"}, 2, {"f_empty/frame_000001.png", "empty file"},
            "f_empty", "", 1);
        goodStream("f_huge");
        writeBytes(at("f_huge/frame_000001.png"), pngHeaderClaiming(30000, 30000));
        add("frame whose header claims 30000x30000", {"run", "f_huge"}, 2,
            {"f_huge/frame_000001.png", "claims 30000x30000"}, "f_huge", "", 1);
        goodStream("f_magic");
        writeBytes(at("f_magic/frame_000001.png"), "GIF89a not really a frame");
        add("frame with the wrong magic", {"run", "f_magic"}, 2,
            {"f_magic/frame_000001.png", "no PNG, JPEG or BMP signature"}, "f_magic", "", 1);
        goodStream("f_crc");
        {
            std::string bad = png1;
            bad[bad.size() / 2] = char(bad[bad.size() / 2] ^ 0x55);
            writeBytes(at("f_crc/frame_000001.png"), bad);
        }
        add("frame with a damaged byte", {"run", "f_crc"}, 2,
            {"f_crc/frame_000001.png", "checksum mismatch"}, "f_crc", "", 1);
        encodedStream("f_jpeg", ".jpg");
        {
            // Two bytes before the scan: libjpeg's warning, which it would print itself.
            std::string bad = readAll(at("f_jpeg/frame_000001.jpg"));
            bad.insert(bad.find("\xFF\xDA"), "\x12\x34");
            writeBytes(at("f_jpeg/frame_000001.jpg"), bad);
        }
        add("JPEG frame with bytes out of place", {"run", "f_jpeg"}, 2,
            {"f_jpeg/frame_000001.jpg", "damaged JPEG (Corrupt JPEG data: 2 extraneous bytes"},
            "f_jpeg", "", 1);
        encodedStream("f_bmp", ".bmp");
        writeBytes(at("f_bmp/frame_000001.bmp"),
                   readAll(at("f_bmp/frame_000001.bmp")).substr(0, 5000));
        add("truncated BMP frame", {"run", "f_bmp"}, 2,
            {"f_bmp/frame_000001.bmp", "truncated BMP", "the file has 5000"}, "f_bmp", "", 1);

        // .strm files.
        const std::string two = strmRecord(1, 32, 24, 0) + strmRecord(1, 32, 24, 33.3);
        writeBytes(at("s_empty.strm"), "");
        add("empty .strm", {"run", "s_empty.strm"}, 2, {"s_empty.strm", "empty stream"},
            "s_empty.strm");
        writeBytes(at("s_header.strm"), two.substr(0, 10));
        add("truncated .strm header", {"run", "s_header.strm"}, 2,
            {"s_header.strm", "truncated header"}, "s_header.strm");
        writeBytes(at("s_pixels.strm"), two.substr(0, two.size() - 100));
        add("truncated .strm record", {"run", "s_pixels.strm"}, 2,
            {"s_pixels.strm", "record 1", "truncated record"}, "s_pixels.strm");
        writeBytes(at("s_magic.strm"), "XXXX" + two.substr(4));
        add(".strm with the wrong magic", {"run", "s_magic.strm"}, 2,
            {"s_magic.strm", "bad magic \"XXXX\""}, "s_magic.strm");
        writeBytes(at("s_version.strm"), strmRecord(7, 32, 24, 0));
        add(".strm of an unknown version", {"run", "s_version.strm"}, 2,
            {"s_version.strm", "unsupported version 7"}, "s_version.strm");
        writeBytes(at("s_nan.strm"), strmRecord(1, 32, 24, std::nan("")));
        add(".strm with a NaN timestamp", {"run", "s_nan.strm"}, 2,
            {"s_nan.strm", "timestamp is not a finite number"}, "s_nan.strm");
        {
            std::string huge = strmRecord(1, 32, 24, 0);
            const std::int32_t width = 2147483647;
            huge.replace(8, 4, reinterpret_cast<const char*>(&width), 4);
            writeBytes(at("s_size.strm"), huge);
        }
        add(".strm claiming a 2147483647 px wide frame", {"run", "s_size.strm"}, 2,
            {"s_size.strm", "absurd frame size 2147483647x24"}, "s_size.strm");
        // Paths that are no file to read, or that the system refuses (issue 21).
        QCOMPARE(::mkfifo(at("fifo.strm").c_str(), 0644), 0);
        add(".strm that is a FIFO", {"run", "fifo.strm"}, 2,
            {"fifo.strm", "a FIFO, not a regular file"}, "fifo.strm");
        QCOMPARE(::mkfifo(at("fifo.avi").c_str(), 0644), 0);
        add("video that is a FIFO", {"run", "fifo.avi"}, 2,
            {"fifo.avi", "a FIFO, not a regular file"}, "fifo.avi");
        add("stream that is a device (/dev/zero)", {"run", "/dev/zero"}, 2,
            {"/dev/zero", "a character device, not a regular file"}, "/dev/zero");
        fs::create_symlink("loop_b", at("loop_a"));
        fs::create_symlink("loop_a", at("loop_b"));
        add("stream path that is a link loop", {"run", "loop_a"}, 2,
            {"loop_a", "Too many levels of symbolic links"}, "loop_a");
        const std::string long_name(300, 'n');
        add("stream name longer than the system allows", {"run", long_name}, 2,
            {long_name, "File name too long"}, long_name);
        goodStream("e_broken");
        fs::create_symlink("nowhere.png", at("e_broken/frame_000009.png"));
        add("frame entry that is a dangling link (a warning)",
            {"run", "e_broken", "--out", "e.json"}, 0,
            {"e_broken/frame_000009.png", "skipped", "does not exist"}, "e_broken");
        // JSON past what a real file needs: refused unread, not parsed into gigabytes.
        std::string list = "0,"; // doubled up to 50 MiB of "0,0,...": a copy at a time
        while (list.size() < (50u << 20))
            list += list;
        list.resize(50u << 20);
        const auto writeHuge = [&list](const std::string& file, const std::string& head,
                                       const std::string& tail) {
            std::ofstream out(file, std::ios::binary);
            out << head << '[' << list << "0]" << tail;
            QVERIFY(out.flush());
        };
        goodStream("m_huge");
        writeHuge(at("m_huge/stream.json"),
                  R"({"format": "fieldsight-stream/1", "camera": {"notes": )", "}}");
        add("stream.json of 50 MB", {"run", "m_huge"}, 2,
            {"m_huge/stream.json", "too large", "for a stream.json of 3 frames"}, "m_huge");
        writeHuge(at("truth_50mb.json"), R"({"format": "fieldsight-annotations/1", "notes": )",
                  "}");
        add("annotations of 50 MB", {"eval", "good", "--truth", "truth_50mb.json"}, 2,
            {"truth_50mb.json", "too large"});
        writeHuge(at("samples_50mb.json"), R"({"format": "fieldsight-lut-samples/1", "notes": )",
                  "}");
        add("LUT samples of 50 MB",
            {"lut", "build", "good", "--samples", "samples_50mb.json", "--out", "built.lut"}, 2,
            {"samples_50mb.json", "too large"});
        writeBytes(at("garbage.avi"), std::string(4096, '\x5a'));
        add("video file of garbage", {"run", "garbage.avi"}, 2, {"garbage.avi", "not a stream"},
            "garbage.avi");

        // Colour tables.
        writeBytes(at("short.lut"), std::string(100, '\0'));
        add("LUT of the wrong size", {"run", "good", "--lut", "short.lut", "--out", "o.json"}, 2,
            {"short.lut", "wrong size: 100 bytes"}, m_good, at("short.lut"));
        {
            std::string lut(ColourLut::kCells, '\0');
            lut[5000] = char(0xff);
            writeBytes(at("badclass.lut"), lut);
        }
        add("LUT with a colour id out of range",
            {"run", "good", "--lut", "badclass.lut", "--out", "o.json"}, 2,
            {"badclass.lut", "invalid colour id 255 at offset 5000"}, m_good, at("badclass.lut"));
        fs::create_directories(at("folder.lut"));
        add("LUT that is a folder", {"run", "good", "--lut", "folder.lut", "--out", "o.json"}, 2,
            {"folder.lut", "a folder, not a regular file"}, m_good, at("folder.lut"));
        QCOMPARE(::mkfifo(at("fifo.lut").c_str(), 0644), 0);
        add("LUT that is a FIFO", {"run", "good", "--lut", "fifo.lut", "--out", "o.json"}, 2,
            {"fifo.lut", "a FIFO, not a regular file"}, m_good, at("fifo.lut"));
        add("LUT that is a device (/dev/zero)",
            {"run", "good", "--lut", "/dev/zero", "--out", "o.json"}, 2,
            {"/dev/zero", "a character device, not a regular file"}, m_good, "/dev/zero");
        fs::copy_file(at("good/default.lut"), at("locked.lut"));
        fs::permissions(at("locked.lut"), fs::perms::none);
        add("LUT without read permission",
            {"run", "good", "--lut", "locked.lut", "--out", "o.json"}, 2,
            {"locked.lut", "Permission denied"}, m_good, at("locked.lut"))
            .needs_permissions = true;
        writeBytes(at("cut.c64"), std::string("\x00\x10\x00\x00\x01\x00\x10", 7));
        add("B-Human table cut short", {"lut", "convert", "cut.c64", "out.lut"}, 2,
            {"cut.c64", "truncated at byte offset 5"}, m_good, at("cut.c64"));
        writeBytes(at("bad.nnmc.bz2"), "BZh9 not really bzip2");
        add("rUNSWift table that is not bzip2", {"lut", "convert", "bad.nnmc.bz2", "out.lut"}, 2,
            {"bad.nnmc.bz2", "bzip2"}, m_good, at("bad.nnmc.bz2"));
        writeBytes(at("table.xyz"), "?");
        add("table of an unknown format", {"lut", "convert", "table.xyz", "out.lut"}, 2,
            {"table.xyz", "unknown colour table format"});

        // Annotations, parameters, options.
        writeBytes(at("truth_cut.json"), readAll(lab1 + "/annotations.json").substr(0, 300));
        add("truncated annotations", {"eval", "good", "--truth", "truth_cut.json"}, 2,
            {"truth_cut.json", "not valid JSON at line"});
        writeBytes(at("truth_big.json"),
                   R"({"format": "fieldsight-annotations/1", "frames": {"frame_000000.png": )"
                   R"({"done": true, "balls": [{"x": 2147483647, "y": 1, "radius": 3}]}}})");
        add("annotation coordinate near 2^31", {"eval", "good", "--truth", "truth_big.json"}, 2,
            {"truth_big.json", "balls[0].x must be within"});
        writeBytes(at("truth_neg.json"),
                   R"({"format": "fieldsight-annotations/1", "frames": {"frame_000000.png": )"
                   R"({"done": true, "balls": [{"x": 20, "y": 1, "radius": -3}]}}})");
        add("annotation with a negative radius", {"eval", "good", "--truth", "truth_neg.json"}, 2,
            {"truth_neg.json", "radius must not be negative"});
        writeBytes(at("truth_huge.json"), R"({"format": "fieldsight-annotations/1", "x": 4e4444})");
        add("annotations with a number past double's range",
            {"eval", "good", "--truth", "truth_huge.json"}, 2,
            {"truth_huge.json", "not valid JSON", "number overflow"});
        writeBytes(at("truth_none.json"),
                   R"({"format": "fieldsight-annotations/1", "frames": {}})");
        add("annotations with no frame done", {"eval", "good", "--truth", "truth_none.json"}, 2,
            {"truth_none.json", "nothing to score"});
        goodStream("a_bad");
        writeBytes(at("a_bad/annotations.json"), "{\"format\": ");
        add("corrupt annotations.json beside the stream", {"eval", "a_bad"}, 2,
            {"a_bad/annotations.json", "not valid JSON"}, "a_bad");
        writeBytes(at("p_stage.json"),
                   R"({"format": "fieldsight-params/1", "stages": {"nope": {}}})");
        add("parameters naming an unknown stage",
            {"run", "good", "--params", "p_stage.json", "--out", "o.json"}, 2,
            {"p_stage.json", "unknown stage 'nope'"});
        writeBytes(at("p_range.json"),
                   R"({"format": "fieldsight-params/1", "stages": {"ball": {"min_radius": 1e9}}})");
        add("parameter out of range",
            {"run", "good", "--params", "p_range.json", "--out", "o.json"}, 2,
            {"p_range.json", "ball.min_radius", "outside"});
        add("gui --params naming an unknown stage", {"gui", "--params", "p_stage.json"}, 2,
            {"--params p_stage.json", "unknown stage 'nope'"});
        add("gui --set out of range", {"gui", "--set", "ball.min_radius=1e9"}, 2,
            {"--set", "ball.min_radius", "outside"});
        add("whole-number option past 2^32", {"synth", "--width", "4294967312", "--out", "x"}, 2,
            {"--width", "4294967312"});

        // Outputs and the machine.
        add("full disk (--out /dev/full)", {"run", "good", "--out", "/dev/full"}, 1,
            {"/dev/full", "No space left on device"});
        add("output into a missing folder", {"run", "good", "--out", "nowhere/o.json"}, 1,
            {"nowhere/o.json", "No such file or directory"});
        fs::create_directories(at("readonly"));
        fs::permissions(at("readonly"), fs::perms::owner_read | fs::perms::owner_exec |
                                            fs::perms::others_read | fs::perms::others_exec);
        add("output into a read-only folder", {"run", "good", "--out", "readonly/o.json"}, 1,
            {"readonly/o.json", "Permission denied"})
            .needs_permissions = true;
        // An earlier table (of a table's size, so the save may replace it), kept whole.
        std::string old_table(std::size_t(1) << 21, '\0');
        old_table.replace(0, 13, "the old table");
        std::filesystem::create_directories(at("tables"));
        writeBytes(at("tables/kept.lut"), old_table);
        add("a save past the file-size limit (ulimit -f 1 MiB)",
            {"lut", "convert", "good/default.lut", "tables/kept.lut"}, 1,
            {"kept.lut", "File too large"})
            .file_size_limit = 1 << 20;
        const std::string latin1 = "caf\xe9";
        add("folder name that is not UTF-8, missing", {"run", latin1 + "_missing"}, 2,
            {latin1 + "_missing", "no such file or folder"});
    }

    void cleanupTestCase()
    {
        // QDir cannot name the folder that is not UTF-8, and the locked files need their bits.
        for (const char* name : {"locked.lut", "readonly"})
            fs::permissions(at(name), fs::perms::owner_all, fs::perm_options::add);
        std::error_code ignored;
        fs::remove_all(m_dir, ignored);
    }

    void eachBadInputIsOneLineNamingTheFile()
    {
        QStringList failures;
        qInfo("%-50s %6s %8s %8s  %s", "input", "exit", "seconds", "peak MB", "message");
        long worst_kb = 0;
        std::string worst;
        for (const Case& c : m_cases) {
            if (c.needs_permissions)
                continue; // permissionBitsBindTheCommand
            const Outcome o = runFieldsight(c.args, m_dir, c.file_size_limit);
            if (o.peak_kb > worst_kb)
                worst_kb = o.peak_kb, worst = c.name;
            check(c, o, failures);
        }
        qInfo("worst peak memory: %.1f MB (%s)", double(worst_kb) / 1024, worst.c_str());
        QVERIFY2(m_cases.size() >= 30, "the catalogue has at least 30 kinds");
        QVERIFY2(failures.isEmpty(), qPrintable(failures.join("\n")));
        // The save that failed left the old file as it was.
        QCOMPARE(readAll(at("tables/kept.lut")).substr(0, 13), std::string("the old table"));
        QCOMPARE(readAll(at("tables/kept.lut")).size(), std::size_t(1) << 21);
    }

    /// The cases that need permission bits to bind: as root the command runs as nobody, and a
    /// machine where root cannot become nobody skips them, saying so.
    void permissionBitsBindTheCommand()
    {
        QStringList failures;
        int run = 0;
        for (const Case& c : m_cases) {
            if (!c.needs_permissions)
                continue;
            const Outcome o = runFieldsight(c.args, m_dir, c.file_size_limit, true);
            if (amRoot() && (o.status == kCannotBeNobody || o.status == 127))
                QSKIP(qPrintable(QString("root here cannot run the command as nobody (exit %1), "
                                         "so permission bits cannot be tested")
                                     .arg(o.status)));
            check(c, o, failures);
            ++run;
        }
        QCOMPARE(run, 2);
        QVERIFY2(failures.isEmpty(), qPrintable(failures.join("\n")));
    }

    void aPathThatIsNotUtf8ReachesTheCommandUnchanged()
    {
        const std::string folder = "caf\xe9";
        goodStream(folder);
        const std::string out = folder + "/r\xe9sultats.json";
        const Outcome o = runFieldsight({"run", folder, "--out", out}, m_dir, RLIM_INFINITY);
        QCOMPARE(o.status, 0);
        QVERIFY2(o.err.empty(), o.err.c_str());
        QVERIFY(fs::is_regular_file(at(out))); // exactly these bytes, not a U+FFFD spelling
        QVERIFY(readAll(at(out)).find("\"frames\"") != std::string::npos);
    }

    void theWindowShowsEachBadInputAndGoesOn()
    {
        ui::MainWindow w;
        w.show();
        QVERIFY(QTest::qWaitForWindowActive(&w));
        QVERIFY(openAndWait(w, QString::fromStdString(m_good)));
        QStringList failures;
        int shown = 0;
        for (const Case& c : m_cases)
            if (!c.gui_stream.empty() && !c.needs_permissions) // theWindowMeetsPermissionBits
                shown += windowCase(w, c, failures);
        qInfo("%d bad inputs opened in the window", shown);
        QVERIFY(shown >= 25);
        QVERIFY2(failures.isEmpty(), qPrintable(failures.join("\n")));
    }

    /// The permission cases in the window. Permission bits do not bind root, so as root this
    /// test runs itself again as nobody (this function alone, in a child process), and a machine
    /// where root cannot become nobody skips it, saying so.
    void theWindowMeetsPermissionBits()
    {
        if (amRoot()) {
            const std::string home = at("nobody_home");
            fs::create_directories(home);
            fs::permissions(home, fs::perms::owner_all);
            QCOMPARE(::chown(home.c_str(), kNobody, kNobody), 0);
            const Outcome o = runFieldsight(
                {fieldsight::test::currentSuite(), "theWindowMeetsPermissionBits"}, m_dir,
                RLIM_INFINITY, true, QCoreApplication::applicationFilePath().toStdString(), 120,
                {"HOME=" + home, "XDG_RUNTIME_DIR=" + home});
            if (o.status == kCannotBeNobody || o.status == 127)
                QSKIP(qPrintable(QString("root here cannot run this test as nobody (exit %1), "
                                         "so permission bits cannot be tested in the window")
                                     .arg(o.status)));
            if (const auto skip = o.out.find("SKIP   : "); skip != std::string::npos)
                QSKIP(qPrintable("as nobody: " + QString::fromStdString(o.out.substr(
                                                     skip, o.out.find('\n', skip) - skip))));
            QVERIFY2(o.status == 0 &&
                         o.out.find("PASS   : TestBadInput::theWindowMeetsPermissionBits") !=
                             std::string::npos,
                     (o.out + o.err).c_str());
            return;
        }
        ui::MainWindow w;
        w.show();
        QVERIFY(QTest::qWaitForWindowActive(&w));
        QVERIFY(openAndWait(w, QString::fromStdString(m_good)));
        QStringList failures;
        int shown = 0;
        for (const Case& c : m_cases)
            if (!c.gui_stream.empty() && c.needs_permissions)
                shown += windowCase(w, c, failures);
        QCOMPARE(shown, 1);
        QVERIFY2(failures.isEmpty(), qPrintable(failures.join("\n")));
    }

    void aStreamThatShrinksWhileOpenIsAMessageInTheWindow()
    {
        // Eight records: the last is beyond the frames the window reads ahead of the one shown
        // (those were read before the file was cut, and are shown as they were).
        const std::string path = at("shrinks.strm");
        std::string records;
        for (int i = 0; i < 8; ++i)
            records += strmRecord(1, 32, 24, 33 * i);
        writeBytes(path, records);
        ui::MainWindow w;
        w.show();
        QVERIFY(openAndWait(w, QString::fromStdString(path)));
        fs::resize_file(path, 32 * 24 * 4 + 100); // another program cuts it to a record and a bit
        w.session().stream().setCurrentIndex(7);
        QVERIFY(waitForFrame(w, 7));
        const QString error = w.session().stream().current()->error;
        QVERIFY2(error.contains("shrinks.strm") && error.contains("record 7"), qPrintable(error));
        w.session().stream().setCurrentIndex(0);
        QVERIFY(waitForFrame(w, 0));
        QVERIFY(w.session().stream().current()->error.isEmpty());
    }

    void aFullDiskKeepsTheEditsAndSaysSo()
    {
        ui::MainWindow w;
        w.show();
        QVERIFY(openAndWait(w, QString::fromStdString(m_good)));
        ui::LutDocument& lut = w.session().lut();
        QVERIFY(lut.edit("paint", {{12345, lut.version()->cell(12345), Colour::Orange}}));
        QVERIFY(lut.modified());
        // venue.lut is a link to /dev/full: the save reaches a disk with no space left.
        fs::create_symlink("/dev/full", at("venue.lut"));
        QVERIFY(!w.files().saveLutAs(QString::fromStdString(at("venue.lut"))));
        QVERIFY2(w.lastMessage().contains("the edits are kept") &&
                     w.lastMessage().contains("No space left on device"),
                 qPrintable(w.lastMessage()));
        QVERIFY(lut.modified());
        QCOMPARE(lut.version()->cell(12345), Colour::Orange);
        QVERIFY(fs::is_symlink(at("venue.lut"))); // the link is still a link
    }
};

FIELDSIGHT_TEST_SUITE(TestBadInput, Widgets)

#include "test_bad_input.moc"
