// `fieldsight lut convert`: another team's colour table as a Fieldsight .lut.
#include "commands/commands.h"

#include "visioncore/colour_lut.h"
#include "visioncore/io/lut_import.h"

namespace fieldsight::cli {

int lutCommand(const QStringList& args, const Context& ctx)
{
    QCommandLineParser parser;
    parser.setApplicationDescription(
        "Converts another team's colour table (.c64, .nnmc.bz2, .raw, .lut) to a Fieldsight "
        ".lut.");
    parser.addPositionalArgument("convert", "The only lut command.");
    parser.addPositionalArgument("IN", "The table to import.");
    parser.addPositionalArgument("OUT", "The .lut file to write.");
    if (auto done = parseCommand(parser, "lut", args, 3, 3, ctx))
        return *done;
    const QStringList positional = parser.positionalArguments();
    if (positional[0] != "convert")
        return badInput(ctx, "lut: unknown lut command '" + positional[0] +
                                 "'; try 'lut convert "
                                 "IN OUT'");
    const std::string in = positional[1].toStdString();
    const std::string out = positional[2].toStdString();
    auto lut = fieldsight::importLut(in);
    if (!lut) {
        return badInput(ctx, lut.error().message);
    }
    if (fieldsight::Status s = lut.value().save(out); !s) {
        printError(ctx.err, s.error().message);
        return kExitFailure;
    }
    std::size_t classified = 0;
    for (std::size_t i = 0; i < fieldsight::ColourLut::kCells; ++i)
        classified += lut.value().data()[i] != 0;
    ctx.out << in << " -> " << out << " (" << classified << " of " << fieldsight::ColourLut::kCells
            << " cells classified)\n";
    return kExitOk;
}

} // namespace fieldsight::cli
