// `fieldsight annotations`: `export` writes a stream's annotations as COCO JSON; `import-dnt`
// turns the Dutch Nao Team's hand labels (post feet and tops) into goalpost truth
// (docs/formats.md).
#include "commands/commands.h"

#include "visioncore/basics/atomic_file.h"
#include "visioncore/io/coco_export.h"
#include "visioncore/io/dnt_labels.h"
#include "visioncore/services/evaluation.h"

#include <exception>

namespace fieldsight::cli {
namespace {

constexpr const char* kUsage =
    "try 'annotations export STREAM --coco FILE' or 'annotations import-dnt LABELS --stream "
    "STREAM'";

Result<std::unique_ptr<StreamReader>> openFrames(const QCommandLineParser& parser,
                                                 const std::string& stream, const Context& ctx)
{
    auto options = streamOptionsFrom(parser);
    if (!options)
        return options.error();
    auto reader = openStream(stream, options.value());
    if (reader)
        printWarnings(ctx.err, reader.value()->info());
    return reader;
}

int exportCommand(const QStringList& args, const Context& ctx)
{
    QCommandLineParser parser;
    parser.setApplicationDescription(
        "Writes a stream's annotations as COCO JSON: one image per annotated frame, one category "
        "per drawn kind, boxes as [x, y, w, h]; the field boundary and lines as polylines.");
    parser.addPositionalArgument("STREAM", "Image folder or .strm file.");
    parser.addOption({"coco", "The COCO JSON file to write.", "FILE"});
    parser.addOption({"annotations",
                      "The annotations to export (default: annotations.json in the stream "
                      "folder).",
                      "FILE"});
    parser.addOption(orientationOption());
    if (auto done = parseCommand(parser, "annotations export", args, 2, 2, ctx))
        return *done;
    if (!parser.isSet("coco"))
        return badInput(ctx, "annotations export: missing --coco FILE");
    try {
        const std::string stream = toLocalPath(parser.positionalArguments()[1]);
        const std::string out = toLocalPath(parser.value("coco"));
        const std::string source = parser.isSet("annotations")
                                       ? toLocalPath(parser.value("annotations"))
                                       : defaultTruthPath(stream);
        if (Status s =
                checkOutputFile("annotations export --coco", out, {stream, source}, kCocoFile);
            !s)
            return badInput(ctx, s.error().message);
        auto reader = openFrames(parser, stream, ctx);
        if (!reader)
            return badInput(ctx, reader.error().message);
        auto annotations = Annotations::load(source, ctx.pipeline.perceptKinds(),
                                             reader.value()->info().frame_count);
        if (!annotations)
            return badInput(ctx, annotations.error().message);
        auto json = cocoJson(annotations.value(), CocoStream::of(*reader.value()),
                             ctx.pipeline.perceptKinds(), source);
        if (!json)
            return badInput(ctx, json.error().message);
        if (Status s = writeOutput(out, json.value(), ctx.out); !s) {
            printError(ctx.err, s.error().message);
            return kExitFailure;
        }
        if (out != "-")
            ctx.out << source << " -> " << out << " (" << annotations.value().frames.size()
                    << " frames)\n";
        return kExitOk;
    } catch (const std::exception& e) {
        return failure(ctx, "annotations export", e);
    }
}

int importDntCommand(const QStringList& args, const Context& ctx)
{
    QCommandLineParser parser;
    parser.setApplicationDescription(
        "Turns the Dutch Nao Team's hand labels of their field pictures (one line a picture, "
        "G<x,y> a post foot, U<x,y> a post top) into goalpost annotations of a stream of those "
        "pictures: each labelled frame is marked reviewed for goalposts (not done).");
    parser.addPositionalArgument("LABELS", "The label file (annotations_original.txt).");
    parser.addOption({"stream", "The stream of the labelled pictures.", "STREAM"});
    parser.addOption({"out",
                      "The annotations file to write (default: annotations.json in the stream "
                      "folder; never over an existing file of the stream).",
                      "FILE"});
    parser.addOption(
        {"post-width", "px, the width of a post nothing in its picture sizes (default 10).", "PX"});
    parser.addOption(orientationOption());
    if (auto done = parseCommand(parser, "annotations import-dnt", args, 2, 2, ctx))
        return *done;
    if (!parser.isSet("stream"))
        return badInput(ctx, "annotations import-dnt: missing --stream STREAM");
    try {
        const std::string labels = toLocalPath(parser.positionalArguments()[1]);
        const std::string stream = toLocalPath(parser.value("stream"));
        const std::string out =
            parser.isSet("out") ? toLocalPath(parser.value("out")) : defaultTruthPath(stream);
        QString error;
        DntPostModel model;
        const auto width = intOption(parser, "post-width", model.default_width, 1, error, 1000);
        if (!width)
            return badInput(ctx, ("annotations import-dnt: " + error).toStdString());
        model.default_width = int(*width);
        if (Status s = checkOutputFile("annotations import-dnt --out", out, {stream, labels},
                                       kAnnotationsFile);
            !s)
            return badInput(ctx, s.error().message);
        auto reader = openFrames(parser, stream, ctx);
        if (!reader)
            return badInput(ctx, reader.error().message);
        auto pictures = loadDntLabels(labels);
        if (!pictures)
            return badInput(ctx, pictures.error().message);
        auto imported = importDntGoalposts(pictures.value(), *reader.value(), labels, model);
        if (!imported)
            return badInput(ctx, imported.error().message);
        if (Status s = writeOutput(
                out, imported.value().annotations.toJson(ctx.pipeline.perceptKinds()), ctx.out);
            !s) {
            printError(ctx.err, s.error().message);
            return kExitFailure;
        }
        const DntImport& r = imported.value();
        if (out != "-")
            ctx.out << labels << " -> " << out << ": " << r.posts << " goalposts on " << r.pictures
                    << " frames (reviewed for goalposts)";
        if (!r.not_in_stream.empty() && out != "-")
            ctx.out << "; " << r.not_in_stream.size() << " labelled pictures are not in the stream";
        if (out != "-")
            ctx.out << "\n";
        return kExitOk;
    } catch (const std::exception& e) {
        return failure(ctx, "annotations import-dnt", e);
    }
}

} // namespace

int annotationsCommand(const QStringList& args, const Context& ctx)
{
    const QString command = args.value(1);
    if (command == "export")
        return exportCommand(args, ctx);
    if (command == "import-dnt")
        return importDntCommand(args, ctx);
    if (command == "--help" || command == "-h" || command == "help") {
        ctx.out << "usage:\n"
                << synopsisLines("annotations")
                << "'fieldsight annotations export --help' and 'fieldsight annotations "
                   "import-dnt --help' describe them.\n";
        return kExitOk;
    }
    if (command.isEmpty())
        return badInput(ctx, std::string("annotations: missing command; ") + kUsage);
    return badInput(ctx, "annotations: unknown annotations command '" + command + "'; " + kUsage);
}

} // namespace fieldsight::cli
