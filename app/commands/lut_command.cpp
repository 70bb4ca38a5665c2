// `fieldsight lut`: `convert` turns another team's colour table into a Fieldsight .lut; `build`
// votes one from samples of a stream (a fieldsight-lut-samples/1 file, or its annotations).
#include "commands/commands.h"

#include "visioncore/basics/colour_lut.h"
#include "visioncore/io/lut_import.h"
#include "visioncore/services/evaluation.h"
#include "visioncore/services/lut_auto.h"
#include "visioncore/services/lut_building.h"
#include "visioncore/services/lut_editing.h"

#include <chrono>
#include <cstdio>
#include <exception>
#include <iostream>

#include <unistd.h>

namespace fieldsight::cli {
namespace {

constexpr const char* kLutUsage =
    "try 'lut convert IN OUT', 'lut build STREAM --out FILE' or 'lut auto STREAM --out FILE'";

int convertCommand(const QStringList& args, const Context& ctx)
{
    QCommandLineParser parser;
    parser.setApplicationDescription(
        "Converts another team's colour table (.c64, .nnmc.bz2, .raw, .lut) to a Fieldsight "
        ".lut.");
    parser.addPositionalArgument("IN", "The table to import.");
    parser.addPositionalArgument("OUT", "The .lut file to write.");
    if (auto done = parseCommand(parser, "lut convert", args, 3, 3, ctx))
        return *done;
    const QStringList positional = parser.positionalArguments();
    const std::string in = toLocalPath(positional[1]);
    const std::string out = toLocalPath(positional[2]);
    if (fieldsight::Status s = checkOutputFile("lut convert", out, {in}, kTableFile); !s)
        return badInput(ctx, s.error().message);
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

/// "green 1234, white 56, ..." for the classes that have cells.
std::string cellsSummary(const ColourLut& lut)
{
    const std::vector<std::size_t> counts = cellsPerClass(lut);
    std::string text;
    for (int c = 1; c < kColourCount; ++c) {
        if (counts[std::size_t(c)] == 0)
            continue;
        text += (text.empty() ? "" : ", ") + std::string(colourName(Colour(c))) + " " +
                std::to_string(counts[std::size_t(c)]);
    }
    return text.empty() ? "none" : text;
}

int buildCommand(const QStringList& args, const Context& ctx)
{
    QCommandLineParser parser;
    parser.setApplicationDescription(
        "Builds a colour LUT from samples of a stream: every pixel of a sample votes for its "
        "class in its YCbCr cell, votes spread into neighbouring cells (--smoothing), and each "
        "cell takes the class with the most weight. The samples are a fieldsight-lut-samples/1 "
        "file, or without --samples the stream's annotations (SPEC 5.2, done frames): the field "
        "below the boundary green, field lines white, goalposts the goal colour, balls orange; "
        "above the boundary and obstacles unclassified. Prints one line: samples, frames, "
        "pixels and cells per class.");
    parser.addPositionalArgument("STREAM", "Image folder or .strm file the samples are from.");
    parser.addOption({"out", "The .lut file to write (required).", "FILE"});
    parser.addOption(
        {"samples", "A fieldsight-lut-samples/1 file (default: the annotations).", "FILE"});
    parser.addOption(
        {"truth", "Annotations (default: annotations.json in the stream folder).", "FILE"});
    parser.addOption({"save-samples",
                      "Also write the samples used as fieldsight-lut-samples/1 (e.g. "
                      "lut_samples.json beside the stream, to rebuild after the light changes).",
                      "FILE"});
    parser.addOption({"smoothing",
                      "Cells each vote spreads into, in Y, Cb and Cr (default: the samples "
                      "file's, else 1; 0 to 8).",
                      "N"});
    parser.addOption({"soft", "Soft classes pink_orange and yellow_orange where orange and "
                              "pink or yellow samples meet."});
    parser.addOption({"goal-colour", "Class of the annotated goalposts (default yellow).", "NAME"});
    parser.addOption(orientationOption());
    if (auto done = parseCommand(parser, "lut build", args, 2, 2, ctx))
        return *done;

    try {
        const auto started = std::chrono::steady_clock::now();
        const std::string stream = toLocalPath(parser.positionalArguments()[1]);
        if (!parser.isSet("out"))
            return badInput(ctx, "lut build: --out FILE is required");
        const std::string out = toLocalPath(parser.value("out"));
        const std::vector<std::string> inputs{stream, toLocalPath(parser.value("samples")),
                                              toLocalPath(parser.value("truth"))};
        if (Status s = checkOutputFile("lut build --out", out, inputs, kTableFile); !s)
            return badInput(ctx, s.error().message);
        if (Status s =
                checkOutputFile("lut build --save-samples",
                                toLocalPath(parser.value("save-samples")), inputs, kSamplesFile);
            !s)
            return badInput(ctx, s.error().message);
        QString error;
        const auto smoothing = intOption(parser, "smoothing", -1, 0, error);
        if (!smoothing || *smoothing > 8)
            return badInput(ctx, "lut build: " + (error.isEmpty()
                                                      ? "--smoothing: expected 0 to 8, got '" +
                                                            parser.value("smoothing") + "'"
                                                      : error));
        AnnotationSampleRules rules;
        if (parser.isSet("goal-colour")) {
            const auto colour = colourFromName(parser.value("goal-colour").toStdString());
            if (!colour || *colour == Colour::Unclassified)
                return badInput(ctx, "lut build: --goal-colour: unknown colour class '" +
                                         parser.value("goal-colour") + "'");
            rules.goal_colour = *colour;
        }

        // Samples and annotations are in the frame the stream is shown in, turned upright.
        const auto stream_options = streamOptionsFrom(parser);
        if (!stream_options)
            return badInput(ctx, "lut build: " + stream_options.error().message);
        auto reader = openStream(stream, stream_options.value());
        if (!reader)
            return badInput(ctx, reader.error().message);
        const StreamInfo& info = reader.value()->info();
        printWarnings(ctx.err, info);

        LutSamples samples;
        if (parser.isSet("samples")) {
            auto loaded = loadLutSamples(toLocalPath(parser.value("samples")), info.frame_count);
            if (!loaded)
                return badInput(ctx, loaded.error().message);
            samples = std::move(loaded).value();
        } else {
            const std::string truth_path = parser.isSet("truth")
                                               ? toLocalPath(parser.value("truth"))
                                               : defaultTruthPath(stream);
            auto truth =
                Annotations::load(truth_path, ctx.pipeline.perceptKinds(), info.frame_count);
            if (!truth)
                return badInput(ctx, truth.error().message);
            samples.samples =
                samplesFromAnnotations(truth.value(), {info.width, info.height}, rules);
            if (samples.samples.empty())
                return badInput(ctx, truth_path + ": no done frame to take samples from");
        }
        LutBuildOptions options;
        options.smoothing = *smoothing >= 0 ? int(*smoothing) : samples.smoothing;
        options.soft = parser.isSet("soft");
        samples.smoothing = options.smoothing;

        auto run = collectLutVotes(*reader.value(), samples.samples);
        if (!run)
            return badInput(ctx, run.error().message);
        const ColourLut lut = run.value().votes.build(options);
        if (Status s = lut.save(out); !s) {
            printError(ctx.err, s.error().message);
            return kExitFailure;
        }
        if (parser.isSet("save-samples")) {
            if (Status s = saveLutSamples(toLocalPath(parser.value("save-samples")), samples); !s) {
                printError(ctx.err, s.error().message);
                return kExitFailure;
            }
        }
        const double seconds =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
        char time[32];
        std::snprintf(time, sizeof time, "%.2f s", seconds);
        ctx.out << "lut build: " << samples.samples.size() << " samples over " << run.value().frames
                << " frames, " << run.value().votes.pixels() << " pixels, smoothing "
                << options.smoothing << " -> " << out << " (cells: " << cellsSummary(lut) << "; "
                << time << ")\n";
        return kExitOk;
    } catch (const std::exception& e) {
        return failure(ctx, "lut build", e);
    }
}

int autoCommand(const QStringList& args, const Context& ctx)
{
    QCommandLineParser parser;
    parser.setApplicationDescription(
        "Makes a first colour table from the stream's frames alone: the carpet as the dominant "
        "colour low in the frames, white in thin runs bordered by carpet, a round blob on the "
        "carpet as the ball (orange), bars standing at the field's edge as the goal (yellow or "
        "blue); colours two classes contest stay unclassified. Prints per class the cells taken "
        "and the share of the sampled pixels, and the goal colour the stream shows.");
    parser.addPositionalArgument("STREAM", "Image folder or .strm file.");
    parser.addOption({"out", "The .lut file to write (required).", "FILE"});
    parser.addOption(
        {"frames",
         QString("Frames sampled, spread over the stream (default %1; 0: every frame).")
             .arg(AutoLutOptions{}.frames),
         "N"});
    parser.addOption({"annotations", "Also let the stream's annotations vote (their done "
                                     "frames' regions, as lut build takes them)."});
    parser.addOption({"truth",
                      "With --annotations: the annotations file (default: "
                      "annotations.json in the stream folder).",
                      "FILE"});
    parser.addOption({"params-out",
                      "Also write the goal colour found as a fieldsight-params/1 file, for "
                      "--params.",
                      "FILE"});
    parser.addOption(orientationOption());
    if (auto done = parseCommand(parser, "lut auto", args, 2, 2, ctx))
        return *done;
    try {
        const auto started = std::chrono::steady_clock::now();
        const std::string stream = toLocalPath(parser.positionalArguments()[1]);
        if (!parser.isSet("out"))
            return badInput(ctx, "lut auto: --out FILE is required");
        const std::string out = toLocalPath(parser.value("out"));
        const std::string params_out = toLocalPath(parser.value("params-out"));
        const std::string truth_path =
            parser.isSet("truth") ? toLocalPath(parser.value("truth")) : defaultTruthPath(stream);
        if (Status s = checkOutputFile("lut auto --out", out, {stream, truth_path}, kTableFile); !s)
            return badInput(ctx, s.error().message);
        if (Status s =
                checkOutputFile("lut auto --params-out", params_out, {stream, out}, kParamsFile);
            !s)
            return badInput(ctx, s.error().message);
        QString error;
        const auto frames = intOption(parser, "frames", int(AutoLutOptions{}.frames), 0, error);
        if (!frames)
            return badInput(ctx, "lut auto: " + error);
        const auto stream_options = streamOptionsFrom(parser);
        if (!stream_options)
            return badInput(ctx, "lut auto: " + stream_options.error().message);
        auto reader = openStream(stream, stream_options.value());
        if (!reader)
            return badInput(ctx, reader.error().message);
        printWarnings(ctx.err, reader.value()->info());

        AutoLutOptions options;
        options.frames = std::size_t(*frames);
        std::optional<Annotations> truth;
        if (parser.isSet("annotations")) {
            auto loaded = Annotations::load(truth_path, ctx.pipeline.perceptKinds(),
                                            reader.value()->info().frame_count);
            if (!loaded)
                return badInput(ctx, loaded.error().message);
            truth = std::move(loaded).value();
            options.annotations = &*truth;
        } else if (parser.isSet("truth")) {
            return badInput(ctx, "lut auto: --truth needs --annotations");
        }
        // Progress on a terminal only, on one line.
        const bool terminal = &ctx.err == &std::cerr && isatty(STDERR_FILENO);
        auto made = buildAutoLut(*reader.value(), options, [&](std::size_t done, std::size_t n) {
            if (terminal)
                ctx.err << "\rlut auto: frame " << done << " of " << n << std::flush;
            return true;
        });
        if (terminal)
            ctx.err << "\r\033[K" << std::flush;
        if (!made)
            return badInput(ctx, made.error().message);
        const AutoLut& result = made.value();
        if (Status s = result.lut.save(out); !s) {
            printError(ctx.err, s.error().message);
            return kExitFailure;
        }
        const std::optional<GoalColourParam> goal = goalColourParam(ctx.pipeline);
        if (!params_out.empty() && goal && result.goal_colour) {
            ParamSet params;
            params.set(goal->stage, goal->name, double(int(*result.goal_colour)));
            if (Status s = params.save(params_out); !s) {
                printError(ctx.err, s.error().message);
                return kExitFailure;
            }
        }
        const double seconds =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
        char line[160];
        std::snprintf(line, sizeof line, "lut auto: %zu frames sampled -> %s (%.2f s)\n",
                      result.frames, out.c_str(), seconds);
        ctx.out << line;
        for (const AutoLutClass& c : result.classes) {
            std::snprintf(line, sizeof line, "  %-14s %8zu cells %6.1f %% of the sampled pixels\n",
                          std::string(colourName(c.colour)).c_str(), c.cells, 100 * c.pixel_share);
            ctx.out << line;
        }
        if (result.goal_colour) {
            ctx.out << "  goal colour: " << colourName(*result.goal_colour);
            if (goal)
                ctx.out << " (--set " << goal->stage << "." << goal->name << "="
                        << int(*result.goal_colour)
                        << (params_out.empty() ? "" : ", written to " + params_out) << ")";
            ctx.out << "\n";
        }
        for (const std::string& note : result.notes)
            ctx.out << "  note: " << note << "\n";
        return kExitOk;
    } catch (const std::exception& e) {
        return failure(ctx, "lut auto", e);
    }
}

} // namespace

int lutCommand(const QStringList& args, const Context& ctx)
{
    const QString command = args.value(1);
    if (command == "convert")
        return convertCommand(args, ctx);
    if (command == "build")
        return buildCommand(args, ctx);
    if (command == "auto")
        return autoCommand(args, ctx);
    if (command == "--help" || command == "-h" || command == "help") {
        ctx.out << "usage:\n"
                << synopsisLines("lut")
                << "'fieldsight lut convert --help', 'fieldsight lut build --help' and "
                   "'fieldsight lut auto --help' describe them.\n";
        return kExitOk;
    }
    if (command.isEmpty()) {
        std::string text = "lut: missing command; "; // in steps: GCC 12 misreads a + here
        text += kLutUsage;
        return badInput(ctx, text);
    }
    return badInput(ctx, "lut: unknown lut command '" + command + "'; " + kLutUsage);
}

} // namespace fieldsight::cli
