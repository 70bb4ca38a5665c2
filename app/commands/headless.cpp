// The command overview and the dispatch from a command word to its command.
#include "commands/commands.h"

#include <new>

namespace fieldsight::cli {

std::string usageText(const Pipeline& pipeline)
{
    return "usage: fieldsight [COMMAND] [ARGS]\n"
           "\n"
           "  fieldsight [gui [STREAM] [--lut FILE]]   open the GUI\n"
           "  fieldsight run   STREAM [--lut FILE] [--out FILE|-] [--skip STAGE,...] [--threads "
           "N]\n"
           "                          [--limit N] [--render DIR [--layers LIST] [--scale N]]\n"
           "  fieldsight bench STREAM... [--lut FILE] [--repeat N] [--threads N] [--json FILE]\n"
           "                          [--limit N]   (several streams: a table as the paper's "
           "Table 1)\n"
           "  fieldsight eval  STREAM [--lut FILE] [--truth FILE] [--json FILE] [--threads N]\n"
           "  fieldsight compare STREAM [--lut A] --lut-b B [--params A] [--params-b B]\n"
           "                          [--truth FILE] [--json FILE|-] [--threads N]\n"
           "                          (frames fixed and broken by table or parameters B)\n"
           "  (run, bench, eval and compare also take --set STAGE.PARAM=VALUE, e.g. "
           "transitions.goal_colour=9,\n"
           "   --params FILE with fieldsight-params/1, and --orientation DEG: 0, 90, 180 or 270\n"
           "   degrees clockwise to turn the stored pictures upright, overriding stream.json's)\n"
           "  fieldsight synth --out DIR [--scenario NAME] [--frames N] [--seed S] [--strm] "
           "[--no-png]\n"
           "  fieldsight lut convert IN OUT\n"
           "  fieldsight lut build STREAM --out FILE [--samples FILE] [--smoothing N] [--soft]\n"
           "                          [--goal-colour NAME] [--truth FILE] [--save-samples FILE]\n"
           "                          [--orientation DEG]\n"
           "  fieldsight annotations export STREAM --coco FILE [--annotations FILE] "
           "[--orientation DEG]\n"
           "  fieldsight annotations import-dnt LABELS --stream STREAM [--out FILE] "
           "[--post-width PX]\n"
           "  fieldsight import LOG --out DIR [--set STAGE.PARAM=VALUE]...   (a B-Human log "
           "folder\n"
           "                          made a stream: frames, kinematic horizons, colour table)\n"
           "  fieldsight help\n"
           "\n"
           "STREAM is a folder of images, a .strm file, a video file or camera:N.\n"
           "Stage ids: " +
           pipeline.idList() +
           ".\n"
           "Exit status: 0 success, 1 failure while running, 2 bad usage or bad input.\n"
           "'fieldsight COMMAND --help' describes one command.\n";
}

namespace {

int runCommandWord(const QString& command, const QStringList& args, const Context& ctx)
{
    if (command == "run")
        return runCommand(args, ctx);
    if (command == "bench")
        return benchCommand(args, ctx);
    if (command == "eval")
        return evalCommand(args, ctx);
    if (command == "compare")
        return compareCommand(args, ctx);
    if (command == "annotations")
        return annotationsCommand(args, ctx);
    if (command == "synth")
        return synthCommand(args, ctx);
    if (command == "import")
        return importCommand(args, ctx);
    if (command == "lut")
        return lutCommand(args, ctx);
    if (command == "help" || command == "--help" || command == "-h") {
        ctx.out << usageText(ctx.pipeline);
        return kExitOk;
    }
    return badInput(ctx, "unknown command '" + command + "'; try 'fieldsight help'");
}

} // namespace

int runHeadless(const QString& command, const QStringList& args, const Context& ctx)
{
    // The readers turn running out of memory into an error naming their file; what is left
    // (the pipeline, a results list) ends the command with one line, not an abort.
    try {
        return runCommandWord(command, args, ctx);
    } catch (const std::bad_alloc&) {
        printError(ctx.err, "out of memory while running '" + command.toStdString() + "'");
        return kExitFailure;
    }
}

} // namespace fieldsight::cli
