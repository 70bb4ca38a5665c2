// The command overview and the dispatch from a command word to its command.
#include "commands/commands.h"

#include <new>

namespace fieldsight::cli {

const std::vector<Synopsis>& synopses()
{
    // Every option of every command, as its --help lists them (test_cli checks both ways).
    static const std::vector<Synopsis> all{
        {"gui", "[STREAM] [--lut FILE] [--set STAGE.PARAM=VALUE] [--params FILE]", "open the GUI"},
        {"run",
         "STREAM [--lut FILE] [--out FILE|-] [--skip STAGE,...] [--threads N] [--limit N] "
         "[--render DIR [--layers LIST] [--scale N]] [--overlays DIR] [--set STAGE.PARAM=VALUE] "
         "[--params FILE] [--orientation DEG] [--adapt]",
         ""},
        {"bench",
         "STREAM... [--lut FILE] [--repeat N] [--threads N] [--json FILE] [--limit N] "
         "[--set STAGE.PARAM=VALUE] [--params FILE] [--orientation DEG] [--adapt]",
         "several streams: a table as the paper's Table 1"},
        {"eval",
         "STREAM [--lut FILE] [--truth FILE] [--json FILE] [--threads N] "
         "[--set STAGE.PARAM=VALUE] [--params FILE] [--orientation DEG] [--adapt]",
         ""},
        {"compare",
         "STREAM [--lut A] --lut-b B [--params A] [--params-b B] [--truth FILE] [--json FILE|-] "
         "[--threads N] [--set STAGE.PARAM=VALUE] [--orientation DEG] [--adapt]",
         "frames fixed and broken by table or parameters B"},
        {"synth",
         "--out DIR [--scenario NAME] [--frames N|paper] [--seed S] [--width PX] [--height PX] "
         "[--camera-height M] [--strm] [--no-png] [--drift F [--table-light P]]",
         "a generated stream with exact ground truth"},
        {"lut convert", "IN OUT", "another team's table as a .lut"},
        {"lut build",
         "STREAM --out FILE [--samples FILE] [--truth FILE] [--save-samples FILE] "
         "[--smoothing N] [--soft] [--goal-colour NAME] [--orientation DEG]",
         "a table from samples or the annotations"},
        {"lut auto",
         "STREAM --out FILE [--frames N] [--annotations] [--truth FILE] [--params-out FILE] "
         "[--orientation DEG]",
         "a first table from the frames alone"},
        {"annotations export", "STREAM --coco FILE [--annotations FILE] [--orientation DEG]",
         "the annotations as COCO JSON"},
        {"annotations import-dnt",
         "LABELS --stream STREAM [--out FILE] [--post-width PX] [--orientation DEG]",
         "the Dutch Nao Team's goal-post labels"},
        {"tune",
         "STREAM... --out PARAMS [--annotations FILE] [--stages STAGE,...] [--budget N] [--seed "
         "S] [--holdout SHARE] [--folds K] [--validate STREAM] [--agree N] [--allow-costly] "
         "[--weight TERM=W] [--json FILE] [--lut FILE] [--set STAGE.PARAM=VALUE] "
         "[--params FILE] [--orientation DEG] [--threads N]",
         "parameters fitted to the annotations"},
        {"import", "LOG --out DIR [--params FILE] [--set STAGE.PARAM=VALUE]",
         "a B-Human log folder made a stream: frames, kinematic horizons, colour table"},
    };
    return all;
}

std::string synopsisLines(std::string_view group)
{
    constexpr std::size_t kWidth = 100;
    std::string text;
    for (const Synopsis& s : synopses()) {
        const std::string command = s.command;
        if (!group.empty() && command != group && command.rfind(std::string(group) + " ", 0) != 0)
            continue;
        const std::string head = "  fieldsight " + command + " ";
        std::string line = head;
        const std::string indent(head.size() + 2, ' ');
        std::string words = std::string(s.synopsis) +
                            (*s.what ? std::string("   (") + s.what + ")" : std::string());
        // Wraps between bracketed groups, never inside one.
        std::size_t depth = 0, start = 0;
        for (std::size_t i = 0; i <= words.size(); ++i) {
            if (i < words.size()) {
                depth += words[i] == '[' || words[i] == '(';
                depth -= (words[i] == ']' || words[i] == ')') && depth > 0;
                if (words[i] != ' ' || depth > 0)
                    continue;
            }
            const std::string word = words.substr(start, i - start);
            start = i + 1;
            if (word.empty())
                continue;
            if (line.size() + word.size() + 1 > kWidth && line.size() > indent.size()) {
                text += line + "\n";
                line = indent;
            } else if (line.back() != ' ') {
                line += ' ';
            }
            line += word;
        }
        text += line + "\n";
    }
    return text;
}

std::string usageText(const Pipeline& pipeline)
{
    return "usage: fieldsight [COMMAND] [ARGS]\n"
           "\n" +
           synopsisLines({}) +
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
    if (command == "tune")
        return tuneCommand(args, ctx);
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
