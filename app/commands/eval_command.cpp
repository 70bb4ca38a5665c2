// `fieldsight eval`: the pipeline over the scored frames of an annotations file (done, or with
// reviewed kinds), scored per SPEC §5.3 and docs/formats.md, printed as a table and written as
// fieldsight-eval/1.
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
    if (s.frames_reviewed == 0)
        std::snprintf(line, sizeof line,
                      "%zu done frames scored (%zu annotated frames not done, ignored)\n", s.frames,
                      s.frames_not_done);
    else
        std::snprintf(line, sizeof line,
                      "%zu done frames scored, and %zu not done for their reviewed kinds only (%zu "
                      "annotated frames not done)\n",
                      s.frames, s.frames_reviewed, s.frames_not_done);
    text += line;
    std::snprintf(line, sizeof line, "%-10s %7s %7s %7s %10s %8s\n", "class", "TP", "FP", "FN",
                  "precision", "recall");
    text += line;
    auto row = [&](const char* name, const ClassScore& c) {
        std::snprintf(line, sizeof line, "%-10s %7d %7d %7d %10.3f %8.3f\n", name, c.tp, c.fp, c.fn,
                      c.precision(), c.recall());
        text += line;
    };
    for (const auto& [kind, c] : s.classes())
        row(scoredClassText(*kind).c_str(), c);
    for (const auto& [kind, c] : s.classes())
        if (c.concealed_found + c.concealed_missed > 0) {
            std::snprintf(line, sizeof line,
                          "concealed %s: %d found, %d missed (in neither TP nor FN)\n",
                          scoredClassText(*kind).c_str(), c.concealed_found, c.concealed_missed);
            text += line;
        }
    if (s.boundary_frames > 0)
        std::snprintf(line, sizeof line, "field boundary: mean error %.2f px over %zu frames\n",
                      s.boundaryMeanError(), s.boundary_frames);
    else
        std::snprintf(line, sizeof line,
                      "field boundary: no frame with both a detected and a true boundary\n");
    text += line;
    text += "("; // in steps: GCC 12 misreads a + of these as out of bounds
    text += kPrecisionNote;
    text += ")\n";
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
                    {"recall", rounded(c.recall(), 6)},
                    {"concealed_found", c.concealed_found},
                    {"concealed_missed", c.concealed_missed}};
    };
    Json j;
    j["format"] = "fieldsight-eval/1";
    j["stream"] = report.stream;
    j["lut"] = report.lut_path;
    j["truth"] = report.truth_path;
    j["frames"] = s.frames;
    j["frames_not_done"] = s.frames_not_done;
    j["frames_reviewed"] = s.frames_reviewed;
    Json classes = Json::object();
    for (const auto& [kind, c] : s.classes())
        classes[scoredClassName(*kind)] = score(c);
    j["classes"] = std::move(classes);
    Json boundary;
    if (s.boundary_frames > 0)
        boundary["mean_error_px"] = rounded(s.boundaryMeanError(), 4);
    else
        boundary["mean_error_px"] = nullptr;
    boundary["frames"] = s.boundary_frames;
    j["field_boundary"] = std::move(boundary);
    Json disagreements = Json::array();
    for (const FrameDisagreement& d : report.disagreements) {
        Json frame;
        frame["frame"] = d.frame;
        if (const auto it = report.frame_index.find(d.frame); it != report.frame_index.end())
            frame["index"] = it->second;
        frame["class"] = scoredClassName(*d.kind);
        frame["false_detections"] = d.false_detections;
        frame["missed"] = d.missed;
        disagreements.push_back(std::move(frame));
    }
    j["disagreements"] = std::move(disagreements);
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
    parser.addOption(adaptOption());
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
        if (Status s = checkOutputFile("eval --json", toLocalPath(parser.value("json")),
                                       {stream, truth_path, toLocalPath(parser.value("lut")),
                                        toLocalPath(parser.value("params"))},
                                       kEvalFile);
            !s)
            return badInput(ctx, s.error().message);
        auto truth = Annotations::load(truth_path, ctx.pipeline.perceptKinds(),
                                       input.value().info().frame_count);
        if (!truth)
            return badInput(ctx, truth.error().message);
        // Precision and recall of nothing would print as a perfect 1.000.
        const std::vector<const PerceptKind*> kinds = scoredKinds(ctx.pipeline.perceptKinds());
        if (std::none_of(truth.value().frames.begin(), truth.value().frames.end(),
                         [&kinds](const auto& f) { return isScored(f.second, kinds); }))
            return badInput(ctx, truth_path + ": nothing to score (no frame is marked \"done\": "
                                              "true or has a \"reviewed\" kind)");
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
