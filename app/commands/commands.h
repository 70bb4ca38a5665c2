// The headless commands of SPEC §5. Each parses its own arguments (args[0] is the program name,
// then the command's arguments), prints its results to ctx.out and at most one line,
// "fieldsight: <problem>", to ctx.err, and returns the exit status.
#pragma once

#include "commands/cli.h"

#include <string>
#include <string_view>
#include <vector>

namespace fieldsight::cli {

int runCommand(const QStringList& args, const Context& ctx);
int benchCommand(const QStringList& args, const Context& ctx);
int evalCommand(const QStringList& args, const Context& ctx);
int compareCommand(const QStringList& args, const Context& ctx);
/// `annotations export` (COCO JSON) and `annotations import-dnt` (the Dutch Nao Team's labels).
int annotationsCommand(const QStringList& args, const Context& ctx);
int synthCommand(const QStringList& args, const Context& ctx);
/// `import LOG --out DIR`: a robot's log folder (a B-Human log) made into a stream folder.
int importCommand(const QStringList& args, const Context& ctx);
int lutCommand(const QStringList& args, const Context& ctx);
/// `tune STREAM --out PARAMS`: the stages' parameters fitted to the stream's annotations.
int tuneCommand(const QStringList& args, const Context& ctx);

/// One command's line in the overview: its words ("lut build"), every argument and option, and
/// what it is for (may be empty).
struct Synopsis
{
    const char* command;
    const char* synopsis;
    const char* what;
};
/// Every command's synopsis: the one source of `fieldsight help` and of `fieldsight lut --help`
/// and `fieldsight annotations --help`.
const std::vector<Synopsis>& synopses();
/// The overview's lines of the commands whose words start with `group` (empty: all), wrapped.
std::string synopsisLines(std::string_view group);

/// The overview `fieldsight help` prints, with the pipeline's stage ids.
std::string usageText(const Pipeline& pipeline);

/// Runs `command` (the word after the program name) with `args`; unknown commands are a usage
/// error.
int runHeadless(const QString& command, const QStringList& args, const Context& ctx);

} // namespace fieldsight::cli
