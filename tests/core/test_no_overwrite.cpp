// Nothing lost, nothing overwritten by a command. Every command the usage text names, with every
// option of its --help that takes a path, is pointed at the files of two streams (a table, the
// annotations, the manifest, a frame, the folders themselves): no file of either stream may change,
// so an output flag added later cannot miss the guard. And `synth --out` replaces only its own
// earlier output, only what nobody changed since, and never a file of the user's.
#include "support/test_suite.h"
#include "support/child_process.h"

#include <QtTest>

#include <QTemporaryDir>

#include <filesystem>
#include <future>
#include <map>
#include <regex>
#include <set>
#include <sstream>

using fieldsight::test::Outcome;
using fieldsight::test::readAll;
using fieldsight::test::writeBytes;
namespace fs = std::filesystem;

namespace {

/// Every file under `dir` with its bytes.
std::map<std::string, std::string> snapshot(const std::string& dir)
{
    std::map<std::string, std::string> files;
    std::error_code ec;
    for (const auto& entry : fs::recursive_directory_iterator(dir, ec))
        if (entry.is_regular_file())
            files[fs::relative(entry.path(), dir).string()] = readAll(entry.path().string());
    return files;
}

/// The command words of the overview's "  fieldsight WORD [WORD] ARG..." lines (not the GUI's,
/// not help).
std::vector<std::vector<std::string>> commandsOf(const std::string& usage)
{
    std::vector<std::vector<std::string>> commands;
    std::istringstream lines(usage);
    for (std::string line; std::getline(lines, line);) {
        std::istringstream words(line);
        std::string word;
        if (!(words >> word) || word != "fieldsight")
            continue;
        std::vector<std::string> command;
        while (words >> word && std::islower(static_cast<unsigned char>(word[0])))
            command.push_back(word);
        // The window writes nothing unasked; its saves have their own guard and tests.
        if (!command.empty() && command.front() != "help" && command.front() != "gui")
            commands.push_back(command);
    }
    return commands;
}

/// The options of a command's --help that take a value which may be a path ("--json <FILE>"):
/// every value name but the numbers, angles, names and settings.
std::vector<std::string> pathOptionsOf(const std::string& help)
{
    static const std::set<std::string> not_paths{"N",    "PX",   "DEG",       "S",
                                                 "NAME", "LIST", "STAGE,...", "STAGE.PARAM=VALUE"};
    std::vector<std::string> options;
    const std::regex option(R"(--([a-z][a-z-]*) <([^>]+)>)");
    for (std::sregex_iterator it(help.begin(), help.end(), option), end; it != end; ++it)
        if (!not_paths.count((*it)[2].str()))
            options.push_back((*it)[1].str());
    return options;
}

/// The places of the arguments --help describes as written ("OUT  The .lut file to write.").
std::vector<std::size_t> writtenArgumentsOf(const std::string& help)
{
    std::vector<std::size_t> written;
    const std::size_t at = help.find("\nArguments:\n");
    if (at == std::string::npos)
        return written;
    std::istringstream lines(help.substr(at + 12));
    std::size_t k = 0;
    for (std::string line; std::getline(lines, line) && !line.empty(); ++k)
        if (line.find("write") != std::string::npos)
            written.push_back(k);
    return written;
}

} // namespace

class TestNoOverwrite : public QObject
{
    Q_OBJECT

    QTemporaryDir m_dir;

    std::string path(const std::string& name) const
    {
        return m_dir.filePath(QString::fromStdString(name)).toStdString();
    }

    Outcome fieldsight(const std::vector<std::string>& args)
    {
        return fieldsight::test::runChild(FIELDSIGHT_EXE, args, m_dir.path().toStdString());
    }

    /// A two-frame generated stream of small frames.
    void synth(const std::string& out, const std::vector<std::string>& more = {})
    {
        std::vector<std::string> args{"synth",    "--frames", "2",     "--width", "64",
                                      "--height", "48",       "--out", out};
        args.insert(args.end(), more.begin(), more.end());
        const Outcome o = fieldsight(args);
        QVERIFY2(o.status == 0, o.err.c_str());
    }

    /// A log folder of two frames `fieldsight import` reads.
    std::string makeLog()
    {
        const std::string log = path("log");
        fs::create_directories(log + "/frames_ycbcr");
        const std::string frame = readAll(path("a/frame_000000.png"));
        writeBytes(log + "/frames_ycbcr/f000.png", frame);
        writeBytes(log + "/frames_ycbcr/f001.png", frame);
        writeBytes(log + "/frames.csv",
                   "frame,timestamp_ms,jpeg_bytes,cam_matrix_valid,horizon_origin_x,"
                   "horizon_origin_y,horizon_dir_x,horizon_dir_y\n"
                   "0,1000,5,1,32,10.0,1.0,0.0\n1,1040,5,1,32,10.0,1.0,0.0\n");
        return log;
    }

    /// The arguments that make `command` succeed writing to new paths, each output named by
    /// fresh(name) so its flag can be pointed elsewhere.
    std::vector<std::string> baseOf(const std::vector<std::string>& command, int run)
    {
        const std::string a = path("a");
        const std::string fresh = path("fresh" + std::to_string(run));
        const std::string key = command.size() > 1 ? command[0] + " " + command[1] : command[0];
        if (key == "run")
            return {"run", a, "--out", fresh + ".json"};
        if (key == "bench")
            return {"bench", a, "--json", fresh + ".json"};
        if (key == "eval")
            return {"eval", a, "--json", fresh + ".json"};
        if (key == "compare")
            return {"compare", a, "--lut-b", a + "/default.lut", "--json", fresh + ".json"};
        if (key == "synth")
            return {"synth", "--frames", "1", "--width", "64", "--height", "48", "--out", fresh};
        if (key == "lut convert")
            return {"lut", "convert", a + "/default.lut", fresh + ".lut"};
        if (key == "lut build")
            return {"lut", "build", a, "--out", fresh + ".lut"};
        if (key == "lut auto")
            return {"lut", "auto", a, "--frames", "2", "--out", fresh + ".lut"};
        if (key == "annotations export")
            return {"annotations", "export", a, "--coco", fresh + ".json"};
        if (key == "annotations import-dnt")
            return {"annotations", "import-dnt",   path("labels.txt"), "--stream", a,
                    "--out",       fresh + ".json"};
        if (key == "import")
            return {"import", m_log, "--out", fresh};
        if (key == "tune")
            return {"tune", a, "--budget", "3", "--out", fresh + ".json"};
        return {};
    }

    std::string m_log;

private slots:
    void initTestCase()
    {
        QVERIFY(m_dir.isValid());
        // Two streams a user has worked on: synth's output with the annotations edited since.
        for (const char* name : {"a", "b"}) {
            synth(path(name));
            const std::string truth = path(name) + "/annotations.json";
            writeBytes(truth, readAll(truth) + "\n");
            writeBytes(path(name) + "/notes.txt", "the user's\n");
        }
        writeBytes(path("labels.txt"), "'frame_000000.png [G<10,40>;U<10,5>]'\n");
        m_log = makeLog();
    }

    void noCommandWritesOverAStreamWhateverPathOptionNamesIt()
    {
        const Outcome usage = fieldsight({"help"});
        QCOMPARE(usage.status, 0);
        const auto commands = commandsOf(usage.out);
        QVERIFY2(commands.size() >= 10, usage.out.c_str());
        const std::string a = path("a"), b = path("b");
        // A document of the stream read, one of its frames, another stream's table.
        const std::vector<std::string> file_targets{a + "/annotations.json",
                                                    a + "/frame_000001.png", b + "/default.lut"};
        const std::vector<std::string> folder_targets{a, b};
        const auto before_a = snapshot(a), before_b = snapshot(b);
        int run = 0;
        std::size_t tried = 0;
        for (const auto& command : commands) {
            std::string name;
            for (const std::string& w : command)
                name += (name.empty() ? "" : " ") + w;
            const std::vector<std::string> base = baseOf(command, ++run);
            QVERIFY2(!base.empty(), ("no base invocation for the command '" + name +
                                     "' the usage names: add it to baseOf()")
                                        .c_str());
            // The base invocation itself works, so a refusal below is the guard's.
            const Outcome ok = fieldsight(base);
            QVERIFY2(ok.status == 0, (name + ": " + ok.err).c_str());

            std::vector<std::string> help_args = command;
            help_args.push_back("--help");
            const Outcome help = fieldsight(help_args);
            QCOMPARE(help.status, 0);
            // Every path option, and each argument --help says is written (lut convert's OUT),
            // found among the base invocation's arguments by its place.
            std::vector<std::pair<std::string, std::size_t>> aims; // option, or "" and index
            for (const std::string& option : pathOptionsOf(help.out))
                aims.push_back({option, 0});
            std::vector<std::size_t> positional;
            for (std::size_t i = command.size(); i < base.size(); ++i)
                if (base[i].rfind("--", 0) != 0 && base[i - 1].rfind("--", 0) != 0)
                    positional.push_back(i);
            for (std::size_t k : writtenArgumentsOf(help.out))
                if (k < positional.size())
                    aims.push_back({"", positional[k]});
            QVERIFY2(!aims.empty(), name.c_str());
            std::vector<std::vector<std::string>> runs;
            for (const auto& [option, index] : aims) {
                const bool folder = help.out.find("--" + option + " <DIR>") != std::string::npos;
                for (const std::string& target : folder ? folder_targets : file_targets) {
                    std::vector<std::string> args = base;
                    if (option.empty()) {
                        args[index] = target;
                    } else {
                        const auto at = std::find(args.begin(), args.end(), "--" + option);
                        if (at != args.end())
                            *(at + 1) = target;
                        else
                            args.insert(args.end(), {"--" + option, target});
                    }
                    runs.push_back(std::move(args));
                }
            }
            // A few at a time (each mostly waits for its libraries to load), each in a working
            // folder of its own; the streams are compared after each few.
            constexpr std::size_t kAtOnce = 4;
            for (std::size_t first = 0; first < runs.size(); first += kAtOnce) {
                std::vector<std::future<Outcome>> running;
                std::string lines;
                for (std::size_t i = first; i < runs.size() && i < first + kAtOnce; ++i) {
                    const std::string cwd = path("w" + std::to_string(i - first));
                    fs::create_directories(cwd);
                    running.push_back(std::async(std::launch::async, [&args = runs[i], cwd] {
                        return fieldsight::test::runChild(FIELDSIGHT_EXE, args, cwd);
                    }));
                    for (const std::string& w : runs[i])
                        lines += w + " ";
                    lines += "| ";
                }
                for (auto& r : running)
                    QVERIFY2(r.get().status != -1, lines.c_str());
                tried += running.size();
                QVERIFY2(snapshot(a) == before_a, ("changed stream a: " + lines).c_str());
                QVERIFY2(snapshot(b) == before_b, ("changed stream b: " + lines).c_str());
            }
        }
        qInfo("%zu commands, %zu runs aimed at the streams' files", commands.size(), tried);
    }

    void aReportReplacesOnlyItsOwnKind()
    {
        const std::string a = path("a");
        const std::string json = path("bench.json");
        QCOMPARE(fieldsight({"bench", a, "--json", json}).status, 0);
        QCOMPARE(fieldsight({"bench", a, "--json", json}).status, 0); // its own earlier output
        const Outcome eval = fieldsight({"eval", a, "--json", json});
        QCOMPARE(eval.status, 2);
        QVERIFY2(eval.err.find("is not fieldsight-eval/1 (it is fieldsight-bench/1)") !=
                     std::string::npos,
                 eval.err.c_str());
        QVERIFY(readAll(json).find("fieldsight-bench/1") != std::string::npos);
    }

    void aRenderGoesOnlyIntoANewFolderOrItsOwnEarlierRender()
    {
        const std::string a = path("a");
        const std::string render = path("render");
        QCOMPARE(fieldsight({"run", a, "--render", render}).status, 0);
        QVERIFY(fs::exists(render + "/frame_000000.png"));
        // Without --out the results go beside the render, not into the working folder.
        QVERIFY(fs::exists(render + "/fieldsight-results.json"));
        QVERIFY(!fs::exists(path("fieldsight-results.json")));
        QCOMPARE(fieldsight({"run", a, "--render", render}).status, 0); // its own render again
        fs::create_directories(path("holiday"));
        writeBytes(path("holiday/frame_000000.png"), "a photo");
        const Outcome o = fieldsight({"run", a, "--render", path("holiday")});
        QCOMPARE(o.status, 2);
        QCOMPARE(readAll(path("holiday/frame_000000.png")), std::string("a photo"));
    }

    void synthKeepsAStreamItDidNotWriteOrThatWasEditedSince()
    {
        // A stream synth wrote before it kept a record, with a file of the user's: refused, and
        // not one file gone.
        const std::string copy = path("copy");
        fs::copy(std::string(FIELDSIGHT_SAMPLE_STREAMS_DIR) + "/lab2", copy,
                 fs::copy_options::recursive);
        fs::remove(copy + "/synth-output.json"); // as synth wrote it before it kept one
        writeBytes(copy + "/notes.txt", "mine\n");
        const auto before = snapshot(copy);
        // Small frames: the rule is tested, not the renderer (slow under the sanitizers).
        const Outcome o = fieldsight(
            {"synth", "--frames", "2", "--width", "64", "--height", "48", "--out", copy});
        QVERIFY2(o.status == 2, o.err.c_str());
        QVERIFY2(o.err.find("nothing was written") != std::string::npos, o.err.c_str());
        QVERIFY(snapshot(copy) == before);

        // Its own output with a record: the annotations edited since are named, nothing touched.
        const std::string own = path("own");
        synth(own);
        QVERIFY(fs::exists(own + "/synth-output.json"));
        writeBytes(own + "/annotations.json", readAll(own + "/annotations.json") + " ");
        const auto edited = snapshot(own);
        const Outcome again =
            fieldsight({"synth", "--frames", "3", "--width", "64", "--height", "48", "--out", own});
        QCOMPARE(again.status, 2);
        QVERIFY2(again.err.find("annotations.json was changed since synth wrote it") !=
                     std::string::npos,
                 again.err.c_str());
        QVERIFY(snapshot(own) == edited);
    }

    void synthReplacesItsOwnUnchangedOutputAndKeepsTheUsersFiles()
    {
        const std::string own = path("own2");
        synth(own, {"--seed", "3"});
        writeBytes(own + "/notes.txt", "mine\n");
        writeBytes(own + "/bookmarks.json", "{}\n");
        synth(own, {"--frames", "1"}); // fewer frames: the stale one goes, the user's stay
        QVERIFY(fs::exists(own + "/frame_000000.png"));
        QVERIFY(!fs::exists(own + "/frame_000001.png"));
        QCOMPARE(readAll(own + "/notes.txt"), std::string("mine\n"));
        QCOMPARE(readAll(own + "/bookmarks.json"), std::string("{}\n"));
        // A file of the user's where the new stream would put one of its own is refused.
        writeBytes(own + "/frame_000002.png", "a photo");
        const Outcome o =
            fieldsight({"synth", "--frames", "3", "--width", "64", "--height", "48", "--out", own});
        QCOMPARE(o.status, 2);
        QVERIFY2(o.err.find("frame_000002.png is not synth's own") != std::string::npos,
                 o.err.c_str());
        QCOMPARE(readAll(own + "/frame_000002.png"), std::string("a photo"));
        // Nothing is left beside the folder.
        for (const auto& entry : fs::directory_iterator(m_dir.path().toStdString()))
            QVERIFY2(entry.path().filename().string().find("partial") == std::string::npos,
                     entry.path().c_str());
    }
};

FIELDSIGHT_TEST_SUITE(TestNoOverwrite, Core)

#include "test_no_overwrite.moc"
