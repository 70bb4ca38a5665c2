// `fieldsight eval`: the pipeline over the done frames of an annotations file, scored per SPEC
// §5.3.
#include "visioncore/batch.h"

#include "batch/batch_util.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <map>
#include <ostream>

namespace fieldsight {
namespace {

std::string stem(const std::string& name)
{
    return std::filesystem::path(name).stem().string();
}

/// Finds the stream index of every done frame of `truth`: by name, else by name without extension
/// (a .strm names its frames frame_000000 where the PNG folder beside it has frame_000000.png).
Result<std::map<std::string, std::size_t>>
doneFrameIndices(const BatchInput& input, const Annotations& truth, const std::string& truth_path)
{
    std::map<std::string, std::size_t> by_name;
    std::map<std::string, std::size_t> by_stem;
    for (std::size_t i = 0; i < input.info().frame_count; ++i) {
        const std::string name = input.reader->frameName(i);
        by_name.emplace(name, i);
        by_stem.emplace(stem(name), i);
    }
    std::map<std::string, std::size_t> indices;
    for (const auto& [name, annotation] : truth.frames) {
        if (!annotation.done)
            continue;
        if (auto it = by_name.find(name); it != by_name.end()) {
            indices.emplace(name, it->second);
        } else if (auto st = by_stem.find(stem(name)); st != by_stem.end()) {
            indices.emplace(name, st->second);
        } else {
            return Error{truth_path + ": frame '" + name + "' is marked done but " + input.stream +
                         " has no such frame"};
        }
    }
    return indices;
}

constexpr const char* kPrecisionNote = "precision = 1 when TP+FP = 0; recall = 1 when TP+FN = 0";

} // namespace

std::string defaultTruthPath(const std::string& stream)
{
    namespace fs = std::filesystem;
    std::error_code ec;
    const fs::path path(stream);
    const fs::path folder = fs::is_directory(path, ec) ? path : path.parent_path();
    return (folder / "annotations.json").string();
}

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
                    {"precision", batch::rounded(c.precision(), 6)},
                    {"recall", batch::rounded(c.recall(), 6)}};
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
        boundary["mean_error_px"] = batch::rounded(s.boundaryMeanError(), 4);
    else
        boundary["mean_error_px"] = nullptr;
    boundary["frames"] = s.boundary_frames;
    j["field_boundary"] = std::move(boundary);
    j["note"] = kPrecisionNote;
    return j.dump(2) + "\n";
}

int evalCommand(const EvalOptions& options, std::ostream& out, std::ostream& err)
{
    try {
        auto input = openBatchInput(options.stream, options.lut, options.set);
        if (!input) {
            batch::printError(err, input.error().message);
            return kExitBadInput;
        }
        const std::string truth_path =
            options.truth.empty() ? defaultTruthPath(options.stream) : options.truth;
        auto truth = Annotations::load(truth_path);
        if (!truth) {
            batch::printError(err, truth.error().message);
            return kExitBadInput;
        }
        auto names = doneFrameIndices(input.value(), truth.value(), truth_path);
        if (!names) {
            batch::printError(err, names.error().message);
            return kExitBadInput;
        }
        std::vector<std::size_t> indices;
        for (const auto& [name, index] : names.value())
            indices.push_back(index);
        std::sort(indices.begin(), indices.end());
        indices.erase(std::unique(indices.begin(), indices.end()), indices.end());

        auto frames = processFrames(input.value(), indices, {}, options.threads);
        if (!frames) {
            batch::printError(err, frames.error().message);
            return kExitBadInput;
        }
        std::map<std::size_t, const FrameResult*> by_index;
        for (const FrameResult& f : frames.value())
            by_index.emplace(f.index, &f);
        std::map<std::string, FrameDetections> detected;
        for (const auto& [name, index] : names.value())
            detected.emplace(name, by_index.at(index)->detections());

        EvalReport report;
        report.stream = options.stream;
        report.lut_path = input.value().lut_path;
        report.truth_path = truth_path;
        report.scores = evaluate(detected, truth.value(), input.value().info().width,
                                 input.value().info().height);
        return batch::finishReport(out, err, evalTable(report), options.json, evalJson(report));
    } catch (const std::exception& e) {
        batch::printError(err, e.what());
        return kExitFailure;
    }
}

} // namespace fieldsight
