// The pieces every headless command shares.
#include "commands/cli.h"

#include "visioncore/basics/atomic_file.h"

#include <filesystem>
#include <new>

namespace fieldsight::cli {

double rounded(double value, int decimals)
{
    static constexpr double kScales[] = {1, 1e1, 1e2, 1e3, 1e4, 1e5, 1e6, 1e7, 1e8};
    if (!std::isfinite(value) || decimals < 0 || decimals > 8)
        return value;
    const double scale = kScales[decimals];
    return std::round(value * scale) / scale;
}

void printError(std::ostream& err, std::string_view message)
{
    std::string line = "fieldsight: ";
    for (char c : message)
        line += (c == '\n' || c == '\r') ? ' ' : c;
    err << line << '\n' << std::flush;
}

int failure(const Context& ctx, std::string_view command, const std::exception& e)
{
    if (dynamic_cast<const std::bad_alloc*>(&e))
        printError(ctx.err, std::string(command) + ": out of memory");
    else
        printError(ctx.err, e.what());
    return kExitFailure;
}

void printWarnings(std::ostream& err, const StreamInfo& info)
{
    for (const std::string& warning : info.warnings)
        printError(err, "warning: " + warning);
}

int badInput(const Context& ctx, std::string_view message)
{
    printError(ctx.err, message);
    return kExitBadInput;
}

int badInput(const Context& ctx, const QString& message)
{
    return badInput(ctx, message.toStdString());
}

Status writeOutput(const std::string& path, const std::string& text, std::ostream& out)
{
    if (path == "-") {
        out << text << std::flush;
        if (!out)
            return Error{"standard output: write failed"};
        return {};
    }
    return writeFileAtomically(path, text);
}

int finishReport(const Context& ctx, const std::string& table, const std::string& json_path,
                 const std::string& json)
{
    ctx.out << table << std::flush;
    if (!json_path.empty()) {
        if (Status s = writeOutput(json_path, json, ctx.out); !s) {
            printError(ctx.err, s.error().message);
            return kExitFailure;
        }
    }
    return kExitOk;
}

std::optional<int> parseCommand(QCommandLineParser& parser, const QString& command,
                                const QStringList& args, int positional_min, int positional_max,
                                const Context& ctx)
{
    parser.setSingleDashWordOptionMode(QCommandLineParser::ParseAsLongOptions);
    const QCommandLineOption help({"h", "help"}, "Show this help.");
    parser.addOption(help);
    if (!parser.parse(args))
        return badInput(ctx, (command + ": " + parser.errorText()).toStdString());
    if (parser.isSet(help)) {
        // "Usage: fieldsight lut convert [options] IN OUT", not the program's path alone.
        QString text = parser.helpText();
        const qsizetype options = text.indexOf(" [options]");
        if (text.startsWith("Usage: ") && options > 0)
            text.replace(7, options - 7, "fieldsight " + command);
        ctx.out << text.toStdString();
        return kExitOk;
    }
    const qsizetype count = parser.positionalArguments().size();
    if (count < positional_min)
        return badInput(ctx,
                        (command + ": missing argument; try 'fieldsight " + command + " --help'")
                            .toStdString());
    if (count > positional_max)
        return badInput(ctx, (command + ": unexpected argument '" +
                              parser.positionalArguments().value(positional_max) + "'")
                                 .toStdString());
    return std::nullopt;
}

std::optional<long long> intOption(const QCommandLineParser& parser, const QString& name,
                                   long long fallback, long long min, QString& error, long long max)
{
    if (!parser.isSet(name))
        return fallback;
    bool ok = false;
    const long long value = parser.value(name).toLongLong(&ok);
    if (!ok || value < min || value > max) {
        error = "--" + name + ": expected a whole number from " + QString::number(min) + " to " +
                QString::number(max) + ", got '" + parser.value(name) + "'";
        return std::nullopt;
    }
    return value;
}

QCommandLineOption lutOption()
{
    return {"lut",
            "Colour lookup table (default: the one stream.json names, else the stream's "
            "default.lut).",
            "FILE"};
}

QCommandLineOption setOption()
{
    return {"set", "Set a stage parameter, e.g. transitions.goal_colour=9 (repeatable).",
            "STAGE.PARAM=VALUE"};
}

QCommandLineOption paramsOption()
{
    return {"params", "Stage parameters from a fieldsight-params/1 file (--set wins).", "FILE"};
}

QCommandLineOption threadsOption(const QString& fallback)
{
    return {"threads",
            "Worker threads, each with its own vision core (0: one per core; default " + fallback +
                "; at most one per core).",
            "N"};
}

QCommandLineOption adaptOption()
{
    return {"adapt",
            "Follow the light: from the stream's table, the table follows slow changes of the "
            "light's colour and level over the frames (frame 0 on), and not one frame's outlier."};
}

QCommandLineOption orientationOption()
{
    return {"orientation",
            "Degrees clockwise to turn the stored pictures upright: 0, 90, 180 or 270 (default: "
            "the stream's own, its stream.json \"orientation\"). Results are in the turned frame.",
            "DEG"};
}

Result<StreamOptions> streamOptionsFrom(const QCommandLineParser& parser)
{
    StreamOptions options;
    if (!parser.isSet("orientation"))
        return options;
    const QString text = parser.value("orientation");
    bool ok = false;
    const long long value = text.toLongLong(&ok);
    options.orientation = ok ? orientationFromDegrees(value) : std::nullopt;
    if (!options.orientation)
        return Error{"--orientation: expected 0, 90, 180 or 270 (degrees clockwise), got '" +
                     text.toStdString() + "'"};
    return options;
}

Result<ParamSet> paramsFrom(const QCommandLineParser& parser, const Pipeline& pipeline)
{
    ParamSet params;
    const std::string file = toLocalPath(parser.value("params"));
    if (parser.isSet("params")) {
        auto loaded = ParamSet::load(file);
        if (!loaded)
            return loaded.error();
        params = std::move(loaded).value();
    }
    const ParamSet from_file = params;
    for (const QString& setting : parser.values("set"))
        if (Status s = params.parseSetting(setting.toStdString()); !s)
            return Error{"--set " + s.error().message};
    if (Status s = params.check(pipeline); !s) {
        // A value --set gave wins over the file's, so the file is named only when its own
        // values are wrong.
        if (Status f = from_file.check(pipeline); !f && parser.isSet("params"))
            return Error{"--params " + file + ": " + f.error().message};
        return Error{"--set: " + s.error().message};
    }
    return params;
}

Result<StreamInput> openInput(const QCommandLineParser& parser, const std::string& stream,
                              const Context& ctx)
{
    auto params = paramsFrom(parser, ctx.pipeline);
    if (!params)
        return params.error();
    auto options = streamOptionsFrom(parser);
    if (!options)
        return options.error();
    auto input =
        openStreamInput(stream, toLocalPath(parser.value("lut")), ctx.pipeline, options.value());
    if (!input)
        return input.error();
    printWarnings(ctx.err, input.value().info());
    // The stream's own parameters, then --params and --set over them.
    input.value().params.merge(params.value());
    if (parser.optionNames().contains("adapt"))
        input.value().adapt = LightTrackingOptions{};
    return input;
}

} // namespace fieldsight::cli
