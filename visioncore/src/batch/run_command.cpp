// `fieldsight run`: the pipeline over a stream, written as fieldsight-results/1 (SPEC §5.1).
#include "visioncore/batch.h"

#include "batch/batch_util.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <optional>
#include <ostream>

namespace fieldsight {
namespace {

using Json = nlohmann::ordered_json; // keeps the field order of SPEC §5.1

constexpr int kMsDecimals = 4; ///< 0.1 microsecond
constexpr int kPxDecimals = 3;

double px(double v)
{
    return batch::rounded(v, kPxDecimals);
}
double ms(double v)
{
    return batch::rounded(v, kMsDecimals);
}

Json frameJson(const FrameResult& f)
{
    Json j;
    j["index"] = f.index;
    j["name"] = f.name;
    Json& time = j["time_ms"];
    time["total"] = ms(f.report.total_ms);
    for (const StageTiming& t : f.report.stages)
        if (t.ran)
            time[t.stage] = ms(t.ms);

    if (f.stageRan("green_horizon")) {
        Json& hull = j["green_horizon"] = Json::array();
        for (const PointF& p : f.green_horizon)
            hull.push_back({px(p.x), px(p.y)});
    }
    if (f.stageRan("ball")) {
        Json& list = j["balls"] = Json::array();
        for (const Ball& b : f.balls)
            list.push_back({{"x", px(b.x)}, {"y", px(b.y)}, {"radius", px(b.radius)}});
    }
    if (f.stageRan("goalposts")) {
        Json& list = j["goalposts"] = Json::array();
        for (const Goalpost& g : f.goalposts)
            list.push_back({{"left", g.left},
                            {"right", g.right},
                            {"top", g.top},
                            {"bottom", g.bottom},
                            {"base_x", px(g.base_x)},
                            {"base_y", px(g.base_y)}});
    }
    if (f.stageRan("obstacles")) {
        Json& list = j["obstacles"] = Json::array();
        for (const Obstacle& o : f.obstacles)
            list.push_back(
                {{"left", o.left}, {"right", o.right}, {"top", o.top}, {"bottom", o.bottom}});
    }
    if (f.stageRan("field_lines")) {
        Json& list = j["field_lines"] = Json::array();
        for (const FieldLine& l : f.field_lines)
            list.push_back(
                {{"x1", px(l.x1)}, {"y1", px(l.y1)}, {"x2", px(l.x2)}, {"y2", px(l.y2)}});
    }
    if (!f.diagnostics.empty()) {
        Json& list = j["diagnostics"] = Json::array();
        for (const Diagnostic& d : f.diagnostics)
            list.push_back({{"stage", d.stage}, {"message", d.message}});
    }
    return j;
}

Json summaryJson(const std::vector<FrameResult>& frames)
{
    std::vector<double> totals;
    totals.reserve(frames.size());
    for (const FrameResult& f : frames)
        totals.push_back(f.report.total_ms);
    const TimingStats total = TimingStats::of(totals);

    Json summary;
    summary["frames"] = frames.size();
    summary["mean_ms"] = ms(total.mean_ms);
    summary["std_ms"] = ms(total.std_ms);
    Json& stages = summary["stage_mean_ms"] = Json::object();
    for (const std::string& id : pipelineStageIds()) {
        double sum = 0;
        std::size_t runs = 0;
        for (const FrameResult& f : frames) {
            for (const StageTiming& t : f.report.stages) {
                if (t.stage == id && t.ran) {
                    sum += t.ms;
                    ++runs;
                }
            }
        }
        if (runs > 0)
            stages[id] = ms(sum / double(runs));
    }
    return summary;
}

} // namespace

std::string resultsJson(const BatchInput& input, const std::vector<FrameResult>& frames,
                        const std::vector<std::string>& skip)
{
    Json head;
    head["format"] = "fieldsight-results/1";
    head["stream"] = input.stream;
    head["lut"] = input.lut_path;
    head["width"] = input.info().width;
    head["height"] = input.info().height;
    if (!skip.empty())
        head["skipped_stages"] = skip;

    // One frame per line: readable, diffable, and no document-sized tree in memory.
    std::string text = head.dump();
    text.pop_back(); // reopen the object to append the frames
    text += ",\"frames\":[";
    for (std::size_t i = 0; i < frames.size(); ++i) {
        text += i == 0 ? "\n" : ",\n";
        text += frameJson(frames[i]).dump();
    }
    text += "],\n\"summary\":";
    text += summaryJson(frames).dump();
    text += "}\n";
    return text;
}

int runCommand(const RunOptions& options, std::ostream& out, std::ostream& err)
{
    try {
        if (Status s = checkStageIds(options.skip); !s) {
            batch::printError(err, s.error().message);
            return kExitBadInput;
        }
        auto input = openBatchInput(options.stream, options.lut, options.set);
        if (!input) {
            batch::printError(err, input.error().message);
            return kExitBadInput;
        }
        std::size_t count = input.value().info().frame_count;
        if (options.limit > 0)
            count = std::min(count, options.limit);
        std::vector<std::size_t> indices(count);
        for (std::size_t i = 0; i < count; ++i)
            indices[i] = i;

        auto frames = processFrames(input.value(), indices, options.skip, options.threads);
        if (!frames) {
            batch::printError(err, frames.error().message);
            return kExitBadInput;
        }
        if (!options.overlays.empty()) {
            // The stream's annotations, if any, are drawn as the truth beside the detections.
            const auto folder = std::filesystem::path(options.stream);
            const auto truth_path = folder / "annotations.json";
            std::optional<Annotations> truth;
            if (std::filesystem::is_regular_file(truth_path))
                if (auto t = Annotations::load(truth_path.string()))
                    truth = std::move(t.value());
            if (Status s = writeOverlays(input.value(), frames.value(), options.overlays,
                                         truth ? &*truth : nullptr);
                !s) {
                batch::printError(err, s.error().message);
                return kExitFailure;
            }
        }
        const std::string text = resultsJson(input.value(), frames.value(), options.skip);
        if (Status s = batch::writeOutput(options.out, text, out); !s) {
            batch::printError(err, s.error().message);
            return kExitFailure;
        }
        if (options.out != "-") {
            std::vector<double> totals;
            for (const FrameResult& f : frames.value())
                totals.push_back(f.report.total_ms);
            const TimingStats stats = TimingStats::of(totals);
            char line[256];
            std::snprintf(line, sizeof line, "%zu frames, %.3f ms per frame (std %.3f) -> ",
                          frames.value().size(), stats.mean_ms, stats.std_ms);
            out << line << options.out << '\n';
        }
        return kExitOk;
    } catch (const std::exception& e) {
        batch::printError(err, e.what());
        return kExitFailure;
    }
}

} // namespace fieldsight
