// What the headless commands share: exit codes (SPEC §5), one-line errors, writing outputs,
// parsing a command's own arguments, and the options several commands take.
#pragma once

#include "visioncore/basics/output_guard.h"
#include "visioncore/framework/controller.h"
#include "visioncore/basics/result.h"
#include "visioncore/services/stream_runner.h"

#include "ui/adapters/local_path.h"

#include <QCommandLineOption>
#include <QCommandLineParser>
#include <QString>
#include <QStringList>

#include <cmath>
#include <exception>
#include <limits>
#include <optional>
#include <ostream>
#include <string>
#include <string_view>

namespace fieldsight::cli {

/// Paths from the command line are bytes, kept exactly (ui/adapters/local_path.h).
using ui::toLocalPath;

/// Exit statuses of the commands (SPEC §5).
inline constexpr int kExitOk = 0;
inline constexpr int kExitFailure = 1;  ///< failure while running
inline constexpr int kExitBadInput = 2; ///< bad usage or bad input

/// Where a command runs: the pipeline it drives and where it prints.
struct Context
{
    const Pipeline& pipeline;
    std::ostream& out;
    std::ostream& err;
};

/// Rounds to `decimals` places so JSON shows 0.1234 rather than 0.12340000000000001.
double rounded(double value, int decimals);

/// Prints "fieldsight: <message>" as exactly one line.
void printError(std::ostream& err, std::string_view message);
/// The end of a command an exception stopped: one line (running out of memory said in words,
/// not as "std::bad_alloc"), and the exit status of a failure while running.
int failure(const Context& ctx, std::string_view command, const std::exception& e);
/// Prints what a stream's reader skipped, "fieldsight: warning: <what>" a line each.
void printWarnings(std::ostream& err, const StreamInfo& info);
/// printError, then the exit status for bad input.
int badInput(const Context& ctx, std::string_view message);
int badInput(const Context& ctx, const QString& message);
inline int badInput(const Context& ctx, const char* message)
{
    return badInput(ctx, std::string_view(message));
}

/// What the commands write, for checkOutputFile: an existing file is replaced only when it is an
/// earlier output of the same kind (reports also inside a stream folder, documents never there).
inline const OutputFileKind kResultsFile{"fieldsight-results/1", {}, false, true};
inline const OutputFileKind kBenchFile{"fieldsight-bench/1", {}, false, true};
inline const OutputFileKind kEvalFile{"fieldsight-eval/1", {}, false, true};
inline const OutputFileKind kCompareFile{"fieldsight-compare/1", {}, false, true};
inline const OutputFileKind kCocoFile{{}, "categories", false, true};
inline const OutputFileKind kTableFile{{}, {}, true, false};
inline const OutputFileKind kAnnotationsFile{"fieldsight-annotations/1", {}, false, false};
inline const OutputFileKind kSamplesFile{"fieldsight-lut-samples/1", {}, false, false};
inline const OutputFileKind kParamsFile{"fieldsight-params/1", {}, false, false};

/// Writes `text` to `path` atomically, or to `out` when `path` is "-".
Status writeOutput(const std::string& path, const std::string& text, std::ostream& out);

/// The end of a reporting command: prints `table` to `out`, then writes `json` to `json_path`
/// when one was given. Returns the command's exit code.
int finishReport(const Context& ctx, const std::string& table, const std::string& json_path,
                 const std::string& json);

/// Parses the arguments after the command word (args[0] is the program name). Returns an exit
/// status when parsing ends the command (help shown, or a usage error), nothing when it runs.
std::optional<int> parseCommand(QCommandLineParser& parser, const QString& command,
                                const QStringList& args, int positional_min, int positional_max,
                                const Context& ctx);

/// Reads a whole-number option from `min` to `max` (a value out of range, such as a width that
/// would wrap in an int, is an error, never truncated).
std::optional<long long> intOption(const QCommandLineParser& parser, const QString& name,
                                   long long fallback, long long min, QString& error,
                                   long long max = std::numeric_limits<int>::max());

QCommandLineOption lutOption();
QCommandLineOption setOption();
QCommandLineOption paramsOption();
QCommandLineOption threadsOption(const QString& fallback);
QCommandLineOption orientationOption();
/// --adapt: the table follows the light (StreamInput::adapt); openInput reads it.
QCommandLineOption adaptOption();

/// --orientation DEG as stream options (none set: the stream's own orientation). A value other
/// than 0, 90, 180 or 270 is an Error naming the option and the value.
Result<StreamOptions> streamOptionsFrom(const QCommandLineParser& parser);

/// The parameter values of --params FILE and then every --set (which win), checked against
/// `pipeline`; an error names where the value came from (the file, or --set).
Result<ParamSet> paramsFrom(const QCommandLineParser& parser, const Pipeline& pipeline);

/// Opens the stream (turned by --orientation) and LUT and applies --params and --set, all
/// checked against the pipeline; with --adapt (where the command has it) the table follows the
/// light.
Result<StreamInput> openInput(const QCommandLineParser& parser, const std::string& stream,
                              const Context& ctx);

} // namespace fieldsight::cli
