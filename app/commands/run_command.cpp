// `fieldsight run`: the pipeline over a stream, written as fieldsight-results/1 (SPEC §5.1), and
// optionally every frame rendered with its layers.
#include "commands/commands.h"
#include "commands/render.h"

#include "visioncore/services/evaluation.h"
#include "visioncore/services/results_json.h"

#include <algorithm>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <optional>

namespace fieldsight::cli {

int runCommand(const QStringList& args, const Context& ctx)
{
    QCommandLineParser parser;
    parser.setApplicationDescription("Runs the vision pipeline over a stream and writes "
                                     "fieldsight-results/1 JSON.");
    parser.addPositionalArgument("STREAM", "Image folder, .strm file, video file or camera:N.");
    parser.addOption(lutOption());
    parser.addOption(setOption());
    parser.addOption(paramsOption());
    parser.addOption(orientationOption());
    parser.addOption(adaptOption());
    parser.addOption({"out",
                      "Output file, or - for standard output (default "
                      "fieldsight-results.json, with --render DIR/fieldsight-results.json).",
                      "FILE"});
    parser.addOption({"skip",
                      "Stages to switch off, comma separated (" +
                          QString::fromStdString(ctx.pipeline.idList()) + ").",
                      "STAGE,..."});
    parser.addOption(threadsOption("1"));
    parser.addOption({"limit", "Process only the first N frames.", "N"});
    parser.addOption(
        {"render", "Also write every frame with its layers drawn to DIR/<frame>.png.", "DIR"});
    parser.addOption({"overlays", "The same as --render.", "DIR"});
    parser.addOption({"layers",
                      "Layers to render, comma separated: all, truth, percepts, a stage id or a "
                      "layer id (default: truth,percepts).",
                      "LIST"});
    parser.addOption({"scale", "Screen pixels per image pixel in renders (default 2).", "N"});
    if (auto done = parseCommand(parser, "run", args, 1, 1, ctx))
        return *done;

    try {
        const std::string stream = toLocalPath(parser.positionalArguments().first());
        QString error;
        const auto threads = intOption(parser, "threads", 1, 0, error);
        const auto limit = intOption(parser, "limit", 0, 1, error);
        const auto scale = intOption(parser, "scale", 2, 1, error, 64);
        if (!threads || !limit || !scale)
            return badInput(ctx, ("run: " + error).toStdString());
        if (*scale > 16)
            return badInput(ctx, "run: --scale: at most 16");
        const std::string render_dir =
            toLocalPath(parser.isSet("render") ? parser.value("render") : parser.value("overlays"));
        if (render_dir.empty() && (parser.isSet("layers") || parser.isSet("scale")))
            return badInput(ctx, "run: --layers and --scale need --render DIR");
        // Without --out the results go beside the render, not into whatever folder this is.
        const std::string out_path = parser.isSet("out")  ? toLocalPath(parser.value("out"))
                                     : render_dir.empty() ? std::string("fieldsight-results.json")
                                                          : render_dir + "/fieldsight-results.json";
        // Neither output goes over what the run reads (a render into the stream's own folder
        // would replace its frames), nor over another stream or anything but an earlier render.
        const std::vector<std::string> inputs{stream, toLocalPath(parser.value("lut")),
                                              toLocalPath(parser.value("params")),
                                              defaultTruthPath(stream)};
        if (Status s = checkRenderFolder("run --render", render_dir, inputs);
            !render_dir.empty() && !s)
            return badInput(ctx, s.error().message);
        if (Status s = checkOutputFile("run --out", out_path, inputs, kResultsFile); !s)
            return badInput(ctx, s.error().message);

        std::vector<std::string> skip;
        for (const QString& list : parser.values("skip"))
            for (const QString& id : list.split(',', Qt::SkipEmptyParts))
                skip.push_back(id.trimmed().toStdString());
        // Checked before the stream is opened (opening can decode a frame).
        if (Status s = checkSkip(ctx.pipeline, skip); !s)
            return badInput(ctx, "--skip: " + s.error().message);
        auto input = openInput(parser, stream, ctx);
        if (!input)
            return badInput(ctx, input.error().message);
        input.value().skip = skip;

        RunHooks hooks;
        RenderOptions render;
        std::optional<Annotations> truth;
        if (!render_dir.empty()) {
            auto layers = selectLayers(parser.isSet("layers") ? parser.value("layers").toStdString()
                                                              : "truth,percepts",
                                       ctx.pipeline);
            if (!layers)
                return badInput(ctx, "--layers: " + layers.error().message);
            // The stream's annotations, if any, are the truth layers.
            const std::string truth_path = defaultTruthPath(stream);
            if (std::filesystem::is_regular_file(truth_path)) {
                auto loaded = Annotations::load(truth_path, ctx.pipeline.perceptKinds(),
                                                input.value().info().frame_count);
                if (!loaded)
                    return badInput(ctx, loaded.error().message);
                truth = std::move(loaded).value();
            }
            if (Status s = prepareRenderFolder(render_dir, stream); !s) {
                printError(ctx.err, s.error().message);
                return kExitFailure;
            }
            render.dir = render_dir;
            render.layers = std::move(layers).value();
            render.scale = int(*scale);
            render.pipeline = &ctx.pipeline;
            if (truth)
                render.truth = truth->truthByStem();
            hooks.layers = render.layers;
            hooks.on_frame = [&render](const FrameResult& r, const Frame& f, const DebugCanvas& c) {
                return renderFrame(render, r, f, c);
            };
        }

        std::size_t count = input.value().info().frame_count;
        if (*limit > 0)
            count = std::min(count, std::size_t(*limit));
        auto run = runStream(input.value(), firstFrames(count), int(*threads), hooks);
        if (!run)
            return badInput(ctx, run.error().message);
        const std::vector<FrameResult>& frames = run.value().frames;
        const std::string text =
            resultsJson(resultsHeader(input.value()), frames, ctx.pipeline.ids());
        if (Status s = writeOutput(out_path, text, ctx.out); !s) {
            printError(ctx.err, s.error().message);
            return kExitFailure;
        }
        if (out_path != "-") {
            std::vector<double> totals;
            for (const FrameResult& f : frames)
                totals.push_back(f.report.total_ms);
            const TimingStats stats = TimingStats::of(totals);
            char line[256];
            std::snprintf(line, sizeof line, "%zu frames, %.3f ms per frame (std %.3f) -> ",
                          frames.size(), stats.mean_ms, stats.std_ms);
            ctx.out << line << out_path << '\n';
        }
        return kExitOk;
    } catch (const std::exception& e) {
        return failure(ctx, "run", e);
    }
}

} // namespace fieldsight::cli
