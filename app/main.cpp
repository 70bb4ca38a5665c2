// The fieldsight executable: parses the command line (SPEC §5), then opens the GUI or runs a
// headless command. The commands themselves live in the Qt-free core (visioncore/batch.h).
#include "synth/synth.h"
#include "visioncore/batch.h"
#include "visioncore/colour_lut.h"
#include "visioncore/lut_import.h"

#include <QCommandLineParser>
#include <QCoreApplication>
#include <QStringList>

#include <iostream>
#include <limits>
#include <optional>

namespace {

using fieldsight::kExitBadInput;
using fieldsight::kExitFailure;
using fieldsight::kExitOk;

constexpr const char* kUsage =
    "usage: fieldsight [COMMAND] [ARGS]\n"
    "\n"
    "  fieldsight [gui [STREAM] [--lut FILE]]   open the GUI\n"
    "  fieldsight run   STREAM [--lut FILE] [--out FILE|-] [--skip STAGE,...] [--threads N]\n"
    "                          [--limit N] [--overlays DIR]\n"
    "  fieldsight bench STREAM... [--lut FILE] [--repeat N] [--threads N] [--json FILE]\n"
    "                          [--limit N]   (several streams: a table as the paper's Table 1)\n"
    "  fieldsight eval  STREAM [--lut FILE] [--truth FILE] [--json FILE]\n"
    "  (run, bench and eval also take --set STAGE.PARAM=VALUE, e.g. transitions.goal_colour=9)\n"
    "  fieldsight synth --out DIR [--scenario NAME] [--frames N] [--seed S] [--strm] [--no-png]\n"
    "  fieldsight lut convert IN OUT\n"
    "  fieldsight help\n"
    "\n"
    "STREAM is a folder of images, a .strm file, a video file or camera:N.\n"
    "Stage ids: green_horizon, scanlines, transitions, goalposts, field_lines, ball, obstacles.\n"
    "Exit status: 0 success, 1 failure while running, 2 bad usage or bad input.\n"
    "'fieldsight COMMAND --help' describes one command.\n";

int usageError(const QString& message)
{
    std::cerr << "fieldsight: " << message.toStdString() << '\n';
    return kExitBadInput;
}

/// Parses the arguments after the command word. Returns an exit status when parsing ends the
/// program (help shown, or a usage error), nothing when the command should run.
std::optional<int> parseCommand(QCommandLineParser& parser, const QString& command,
                                const QStringList& args, int positional_min, int positional_max)
{
    parser.setSingleDashWordOptionMode(QCommandLineParser::ParseAsLongOptions);
    const QCommandLineOption help({"h", "help"}, "Show this help.");
    parser.addOption(help);
    if (!parser.parse(args))
        return usageError(command + ": " + parser.errorText());
    if (parser.isSet(help)) {
        std::cout << parser.helpText().toStdString();
        return kExitOk;
    }
    const qsizetype count = parser.positionalArguments().size();
    if (count < positional_min)
        return usageError(command + ": missing argument; try 'fieldsight " + command + " --help'");
    if (count > positional_max)
        return usageError(command + ": unexpected argument '" +
                          parser.positionalArguments().value(positional_max) + "'");
    return std::nullopt;
}

/// Reads a whole-number option; `min` is the smallest allowed value.
std::optional<long long> intOption(const QCommandLineParser& parser, const QString& name,
                                   long long fallback, long long min, QString& error)
{
    if (!parser.isSet(name))
        return fallback;
    bool ok = false;
    const long long value = parser.value(name).toLongLong(&ok);
    if (!ok || value < min) {
        error = "--" + name + ": expected a whole number >= " + QString::number(min) + ", got '" +
                parser.value(name) + "'";
        return std::nullopt;
    }
    return value;
}

QCommandLineOption lutOption()
{
    return {"lut", "Colour lookup table (default: the stream's default.lut).", "FILE"};
}

QCommandLineOption setOption()
{
    return {"set", "Set a stage parameter, e.g. transitions.goal_colour=9 (repeatable).",
            "STAGE.PARAM=VALUE"};
}

QCommandLineOption threadsOption(const QString& fallback)
{
    return {"threads",
            "Worker threads, each with its own vision core (0: one per core; default " + fallback +
                ").",
            "N"};
}

int runRun(const QStringList& args)
{
    QCommandLineParser parser;
    parser.setApplicationDescription("Runs the vision pipeline over a stream and writes "
                                     "fieldsight-results/1 JSON.");
    parser.addPositionalArgument("STREAM", "Image folder, .strm file, video file or camera:N.");
    parser.addOption(lutOption());
    parser.addOption(setOption());
    parser.addOption({"out",
                      "Output file, or - for standard output (default "
                      "fieldsight-results.json).",
                      "FILE"});
    parser.addOption({"skip", "Stages to switch off, comma separated.", "STAGE,..."});
    parser.addOption(threadsOption("1"));
    parser.addOption({"limit", "Process only the first N frames.", "N"});
    parser.addOption(
        {"overlays", "Also write every frame with its detections drawn to DIR.", "DIR"});
    if (auto done = parseCommand(parser, "run", args, 1, 1))
        return *done;

    fieldsight::RunOptions options;
    options.stream = parser.positionalArguments().first().toStdString();
    options.lut = parser.value("lut").toStdString();
    for (const QString& setting : parser.values("set"))
        options.set.push_back(setting.toStdString());
    if (parser.isSet("out"))
        options.out = parser.value("out").toStdString();
    for (const QString& list : parser.values("skip"))
        for (const QString& id : list.split(',', Qt::SkipEmptyParts))
            options.skip.push_back(id.trimmed().toStdString());
    QString error;
    const auto threads = intOption(parser, "threads", 1, 0, error);
    const auto limit = intOption(parser, "limit", 0, 1, error);
    if (!threads || !limit)
        return usageError("run: " + error);
    options.threads = int(*threads);
    options.limit = std::size_t(*limit);
    options.overlays = parser.value("overlays").toStdString();
    return fieldsight::runCommand(options, std::cout, std::cerr);
}

int runBench(const QStringList& args)
{
    QCommandLineParser parser;
    parser.setApplicationDescription(
        "Times the pipeline per frame (mean and standard deviation, per stage) next to a floor "
        "(only the scan lines' LUT lookups) and a full-frame OpenCV baseline. With several "
        "streams, each is timed on its own and the table has one row per stream and a combined "
        "row over all their frames, as the paper's Table 1, then the stages per stream.");
    parser.addPositionalArgument("STREAM", "Image folder, .strm file or video file; one or more.",
                                 "STREAM...");
    parser.addOption({"lut",
                      "Colour lookup table for every stream (default: each stream's own "
                      "default.lut).",
                      "FILE"});
    parser.addOption(setOption());
    parser.addOption({"repeat", "Passes over each stream (default 1).", "N"});
    parser.addOption(threadsOption("1"));
    parser.addOption({"json", "Also write the numbers as fieldsight-bench/1 JSON.", "FILE"});
    parser.addOption({"limit", "Use only the first N frames of each stream.", "N"});
    if (auto done = parseCommand(parser, "bench", args, 1, std::numeric_limits<int>::max()))
        return *done;

    fieldsight::BenchOptions options;
    for (const QString& stream : parser.positionalArguments())
        options.streams.push_back(stream.toStdString());
    options.lut = parser.value("lut").toStdString();
    for (const QString& setting : parser.values("set"))
        options.set.push_back(setting.toStdString());
    options.json = parser.value("json").toStdString();
    QString error;
    const auto repeat = intOption(parser, "repeat", 1, 1, error);
    const auto threads = intOption(parser, "threads", 1, 0, error);
    const auto limit = intOption(parser, "limit", 0, 1, error);
    if (!repeat || !threads || !limit)
        return usageError("bench: " + error);
    options.repeat = int(*repeat);
    options.threads = int(*threads);
    options.limit = std::size_t(*limit);
    return fieldsight::benchCommand(options, std::cout, std::cerr);
}

int runEval(const QStringList& args)
{
    QCommandLineParser parser;
    parser.setApplicationDescription(
        "Runs the pipeline over the done frames of an annotations file and scores it (SPEC "
        "5.3): TP, FP, FN, precision, recall per class, field boundary error in px.");
    parser.addPositionalArgument("STREAM", "Image folder or .strm file.");
    parser.addOption(lutOption());
    parser.addOption(setOption());
    parser.addOption(
        {"truth", "Annotations (default: annotations.json in the stream folder).", "FILE"});
    parser.addOption({"json", "Also write the scores as fieldsight-eval/1 JSON.", "FILE"});
    if (auto done = parseCommand(parser, "eval", args, 1, 1))
        return *done;

    fieldsight::EvalOptions options;
    options.stream = parser.positionalArguments().first().toStdString();
    options.lut = parser.value("lut").toStdString();
    for (const QString& setting : parser.values("set"))
        options.set.push_back(setting.toStdString());
    options.truth = parser.value("truth").toStdString();
    options.json = parser.value("json").toStdString();
    options.threads = 0; // all cores
    return fieldsight::evalCommand(options, std::cout, std::cerr);
}

int runSynth(const QStringList& args)
{
    namespace synth = fieldsight::synth;
    QCommandLineParser parser;
    parser.setApplicationDescription("Renders a synthetic stream with exact ground truth.");
    QString names;
    for (const std::string& name : synth::scenarioNames())
        names += (names.isEmpty() ? "" : ", ") + QString::fromStdString(name);
    parser.addOption({"scenario", "One of " + names + " (default lab2).", "NAME"});
    parser.addOption({"frames",
                      "Number of frames (default 30), or 'paper' for the paper's length of the "
                      "scenario (5090, 470, 175, 2640, 625).",
                      "N"});
    parser.addOption({"seed", "Random seed (default 1).", "S"});
    parser.addOption({"out", "Stream folder to create.", "DIR"});
    parser.addOption({"width", "Image width in px (default 320).", "PX"});
    parser.addOption({"height", "Image height in px (default 240).", "PX"});
    parser.addOption({"strm", "Also write image.strm."});
    parser.addOption({"no-png", "Do not write PNG frames (needs --strm)."});
    if (auto done = parseCommand(parser, "synth", args, 0, 0))
        return *done;

    synth::SynthOptions options;
    if (!parser.isSet("out"))
        return usageError("synth: --out DIR is required");
    options.out_dir = parser.value("out").toStdString();
    if (parser.isSet("scenario")) {
        auto scenario = synth::scenarioFromName(parser.value("scenario").toStdString());
        if (!scenario)
            return usageError("synth: --scenario: " +
                              QString::fromStdString(scenario.error().message));
        options.scenario = scenario.value();
    }
    QString error;
    if (parser.value("frames") == "paper")
        options.frames = synth::paperFrameCount(options.scenario);
    const auto frames = parser.value("frames") == "paper"
                            ? std::optional<long long>(options.frames)
                            : intOption(parser, "frames", options.frames, 1, error);
    const auto width = intOption(parser, "width", options.width, 16, error);
    const auto height = intOption(parser, "height", options.height, 16, error);
    if (!frames || !width || !height)
        return usageError("synth: " + error);
    options.frames = int(*frames);
    options.width = int(*width);
    options.height = int(*height);
    if (parser.isSet("seed")) {
        bool ok = false;
        options.seed = parser.value("seed").toULongLong(&ok);
        if (!ok)
            return usageError("synth: --seed: expected a whole number >= 0, got '" +
                              parser.value("seed") + "'");
    }
    options.write_strm = parser.isSet("strm");
    options.write_png = !parser.isSet("no-png");
    if (!options.write_png && !options.write_strm)
        return usageError("synth: --no-png without --strm would write no frames");

    if (fieldsight::Status s = synth::generateStream(options); !s) {
        std::cerr << "fieldsight: " << s.error().message << '\n';
        return kExitFailure;
    }
    std::cout << "wrote " << options.frames << " frames of "
              << synth::scenarioName(options.scenario) << " to " << options.out_dir << '\n';
    return kExitOk;
}

int runLut(const QStringList& args)
{
    QCommandLineParser parser;
    parser.setApplicationDescription(
        "Converts another team's colour table (.c64, .nnmc.bz2, .raw, .lut) to a Fieldsight "
        ".lut.");
    parser.addPositionalArgument("convert", "The only lut command.");
    parser.addPositionalArgument("IN", "The table to import.");
    parser.addPositionalArgument("OUT", "The .lut file to write.");
    if (auto done = parseCommand(parser, "lut", args, 3, 3))
        return *done;
    const QStringList positional = parser.positionalArguments();
    if (positional[0] != "convert")
        return usageError("lut: unknown lut command '" + positional[0] +
                          "'; try 'lut convert "
                          "IN OUT'");
    const std::string in = positional[1].toStdString();
    const std::string out = positional[2].toStdString();
    auto lut = fieldsight::importLut(in);
    if (!lut) {
        std::cerr << "fieldsight: " << lut.error().message << '\n';
        return kExitBadInput;
    }
    if (fieldsight::Status s = lut.value().save(out); !s) {
        std::cerr << "fieldsight: " << s.error().message << '\n';
        return kExitFailure;
    }
    std::size_t classified = 0;
    for (std::size_t i = 0; i < fieldsight::ColourLut::kCells; ++i)
        classified += lut.value().data()[i] != 0;
    std::cout << in << " -> " << out << " (" << classified << " of "
              << fieldsight::ColourLut::kCells << " cells classified)\n";
    return kExitOk;
}

// ---------------------------------------------------------------------------------------------
// The GUI entry point (`fieldsight` and `fieldsight gui [STREAM] [--lut FILE]`). It owns the
// application object, since a GUI needs a QApplication rather than a QCoreApplication. To be
// replaced once the GUI exists (FIELDSIGHT_WITH_GUI).
int runGui(int argc, char* argv[])
{
    (void)argc;
    (void)argv;
    std::cerr << "fieldsight: the GUI is not built yet; try 'fieldsight run STREAM'\n";
    return kExitBadInput;
}
// ---------------------------------------------------------------------------------------------

} // namespace

int main(int argc, char* argv[])
{
    const QString command = argc > 1 ? QString::fromLocal8Bit(argv[1]) : QString();
    if (command.isEmpty() || command == "gui")
        return runGui(argc, argv);

    QCoreApplication app(argc, argv);
    QCoreApplication::setApplicationName("fieldsight");
    QCoreApplication::setApplicationVersion(QStringLiteral(FIELDSIGHT_VERSION));
    // The parsers see the program name followed by the command's own arguments.
    QStringList args = QCoreApplication::arguments();
    args.removeAt(1);

    if (command == "run")
        return runRun(args);
    if (command == "bench")
        return runBench(args);
    if (command == "eval")
        return runEval(args);
    if (command == "synth")
        return runSynth(args);
    if (command == "lut")
        return runLut(args);
    if (command == "help" || command == "--help" || command == "-h") {
        std::cout << kUsage;
        return kExitOk;
    }
    if (command == "--version" || command == "-v") {
        std::cout << "fieldsight " << FIELDSIGHT_VERSION << '\n';
        return kExitOk;
    }
    return usageError("unknown command '" + command + "'; try 'fieldsight help'");
}
