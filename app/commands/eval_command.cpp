// `fieldsight eval`: the pipeline over the done frames of an annotations file, scored per SPEC
// §5.3, printed as a table and written as fieldsight-eval/1.
#include "commands/commands.h"

#include "visioncore/basics/json_text.h"
#include "visioncore/services/evaluation.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdio>
#include <exception>

namespace fieldsight::cli {
namespace {

constexpr const char* kPrecisionNote = "precision = 1 when TP+FP = 0; recall = 1 when TP+FN = 0";

std::string evalTable(const EvalReport& report)
{
    const EvaluationScores& s = report.scores;
    std::string text;
    char line[256];
    std::snprintf(line, sizeof line, "fieldsight eval: %s against %s\n", report.stream.c_str(),
                  report.truth_path.c_str());
    text += line;
    std::snprintf(line, sizeof line,
                  "%zu done frames scored (%zu annotated frames not done, ignored)\n", s.frames,
                  s.frames_not_done);
    text += line;
    std::snprintf(line, sizeof line, "%-10s %7s %7s %7s %10s %8s\n", "class", "TP", "FP", "FN",
                  "precision", "recall");
    text += line;
    auto row = [&](const char* name, const ClassScore& c) {
        std::snprintf(line, sizeof line, "%-10s %7d %7d %7d %10.3f %8.3f\n", name, c.tp, c.fp, c.fn,
                      c.precision(), c.recall());
        text += line;
    };
    row("ball", s.balls);
    row("goalpost", s.goalposts);
    row("obstacle", s.obstacles);
    if (s.boundary_frames > 0)
        std::snprintf(line, sizeof line, "field boundary: mean error %.2f px over %zu frames\n",
                      s.boundaryMeanError(), s.boundary_frames);
    else
        std::snprintf(line, sizeof line,
                      "field boundary: no frame with both a detected and a true boundary\n");
    text += line;
    text += std::string("(") + kPrecisionNote + ")\n";
    return text;
}

std::string evalJson(const EvalReport& report)
{
    using Json = nlohmann::ordered_json;
    const EvaluationScores& s = report.scores;
    auto score = [](const ClassScore& c) {
        return Json{{"tp", c.tp},
                    {"fp", c.fp},
                    {"fn", c.fn},
                    {"precision", rounded(c.precision(), 6)},
                    {"recall", rounded(c.recall(), 6)}};
    };
    Json j;
    j["format"] = "fieldsight-eval/1";
    j["stream"] = report.stream;
    j["lut"] = report.lut_path;
    j["truth"] = report.truth_path;
    j["frames"] = s.frames;
    j["frames_not_done"] = s.frames_not_done;
    j["classes"] = {{"ball", score(s.balls)},
                    {"goalpost", score(s.goalposts)},
                    {"obstacle", score(s.obstacles)}};
    Json boundary;
    if (s.boundary_frames > 0)
        boundary["mean_error_px"] = rounded(s.boundaryMeanError(), 4);
    else
        boundary["mean_error_px"] = nullptr;
    boundary["frames"] = s.boundary_frames;
    j["field_boundary"] = std::move(boundary);
    j["note"] = kPrecisionNote;
    return jsonText(j, 2) + "\n";
}

} // namespace

int evalCommand(const QStringList& args, const Context& ctx)
{
    QCommandLineParser parser;
    parser.setApplicationDescription(
        "Runs the pipeline over the done frames of an annotations file and scores it (SPEC "
        "5.3): TP, FP, FN, precision, recall per class, field boundary error in px.");
    parser.addPositionalArgument("STREAM", "Image folder or .strm file.");
    parser.addOption(lutOption());
    parser.addOption(setOption());
    parser.addOption(paramsOption());
    parser.addOption(orientationOption());
    parser.addOption(
        {"truth", "Annotations (default: annotations.json in the stream folder).", "FILE"});
    parser.addOption({"json", "Also write the scores as fieldsight-eval/1 JSON.", "FILE"});
    parser.addOption(threadsOption("0"));
    if (auto done = parseCommand(parser, "eval", args, 1, 1, ctx))
        return *done;

    try {
        const std::string stream = toLocalPath(parser.positionalArguments().first());
        QString error;
        const auto threads = intOption(parser, "threads", 0, 0, error);
        if (!threads)
            return badInput(ctx, ("eval: " + error).toStdString());
        auto input = openInput(parser, stream, ctx);
        if (!input)
            return badInput(ctx, input.error().message);
        const std::string truth_path =
            parser.isSet("truth") ? toLocalPath(parser.value("truth")) : defaultTruthPath(stream);
        if (Status s = checkNotAnInput("eval", toLocalPath(parser.value("json")),
                                       {stream, truth_path, toLocalPath(parser.value("lut")),
                                        toLocalPath(parser.value("params"))});
            !s)
            return badInput(ctx, s.error().message);
        auto truth = Annotations::load(truth_path, ctx.pipeline.perceptKinds(),
                                       input.value().info().frame_count);
        if (!truth)
            return badInput(ctx, truth.error().message);
        // Precision and recall of nothing would print as a perfect 1.000.
        if (std::none_of(truth.value().frames.begin(), truth.value().frames.end(),
                         [](const auto& f) { return f.second.done; }))
            return badInput(ctx,
                            truth_path + ": nothing to score (no frame is marked \"done\": true)");
        auto report = evaluateStream(input.value(), truth.value(), truth_path, int(*threads));
        if (!report)
            return badInput(ctx, report.error().message);
        report.value().stream = stream;
        return finishReport(ctx, evalTable(report.value()), toLocalPath(parser.value("json")),
                            evalJson(report.value()));
    } catch (const std::exception& e) {
        return failure(ctx, "eval", e);
    }
}

} // namespace fieldsight::cli
