// `fieldsight bench`: the flags, the tables (the paper's Table 1) and fieldsight-bench/1 JSON of
// the benchmark in visioncore/services/bench.h, which times the pipeline next to a floor and a
// full-frame baseline.
#include "commands/commands.h"

#include "visioncore/basics/json_text.h"
#include "visioncore/services/bench.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdio>
#include <exception>
#include <limits>
#include <string_view>

namespace fieldsight::cli {
namespace {

double ratio(double a, double b)
{
    return b > 0 ? a / b : 0.0;
}

std::string benchTable(const BenchResults& r)
{
    std::string text;
    char line[256];
    auto row = [&](const char* label, const TimingStats& s, const std::string& note = {}) {
        std::snprintf(line, sizeof line, "%-36s %10.4f %10.4f%s\n", label, s.mean_ms, s.std_ms,
                      note.empty() ? "" : ("   " + note).c_str());
        text += line;
    };
    std::snprintf(
        line, sizeof line,
        "fieldsight bench: %s (%dx%d), %zu frames x %d pass%s = %zu runs, %d thread%s%s\n",
        r.stream.c_str(), r.width, r.height, r.frames, r.repeat, r.repeat == 1 ? "" : "es",
        r.pipeline.samples, r.threads, r.threads == 1 ? "" : "s",
        r.in_memory ? ", frames in memory" : ", frames decoded each pass (not timed)");
    text += line;
    std::snprintf(line, sizeof line, "%-36s %10s %10s\n", "", "mean ms", "std ms");
    text += line;
    row("pipeline (ControlWrapper::runFrame)", r.pipeline);
    for (const auto& [id, stats] : r.stages)
        row(("  " + id).c_str(), stats);
    const double image_pixels = double(r.width) * double(r.height);
    char note[96];
    std::snprintf(note, sizeof note, "%.0f px/frame, %.1f%% of the image", r.floor_pixels_per_frame,
                  image_pixels > 0 ? 100.0 * r.floor_pixels_per_frame / image_pixels : 0.0);
    row("floor: LUT lookups on scan lines", r.floor, note);
    row("baseline: full frame + OpenCV CC", r.baseline);
    std::snprintf(line, sizeof line, "%-36s %10.2fx\n", "pipeline / floor",
                  ratio(r.pipeline.mean_ms, r.floor.mean_ms));
    text += line;
    std::snprintf(line, sizeof line, "%-36s %10.2fx\n", "pipeline / baseline",
                  ratio(r.pipeline.mean_ms, r.baseline.mean_ms));
    text += line;
    text += "(std is the population standard deviation over all runs; the three rows are timed on "
            "the same frames, each after an untimed full-frame LUT pass)\n";
    return text;
}

using Json = nlohmann::ordered_json;

Json statsJson(const TimingStats& s)
{
    return Json{{"mean_ms", rounded(s.mean_ms, 5)},
                {"std_ms", rounded(s.std_ms, 5)},
                {"samples", s.samples}};
}

/// The timing fields of fieldsight-bench/1 (frames onwards), appended to `j`.
void appendTimings(Json& j, const BenchResults& r)
{
    Json pipeline = statsJson(r.pipeline);
    Json& stages = pipeline["stages"] = Json::object();
    for (const auto& [id, s] : r.stages)
        stages[id] = statsJson(s);
    j["pipeline"] = std::move(pipeline);
    Json floor = statsJson(r.floor);
    floor["pixels_per_frame"] = rounded(r.floor_pixels_per_frame, 1);
    j["floor"] = std::move(floor);
    j["baseline"] = statsJson(r.baseline);
    j["ratios"] = {
        {"pipeline_over_floor", rounded(ratio(r.pipeline.mean_ms, r.floor.mean_ms), 4)},
        {"pipeline_over_baseline", rounded(ratio(r.pipeline.mean_ms, r.baseline.mean_ms), 4)}};
}

/// One stream's fields of fieldsight-bench/1, after whatever `j` already holds.
void appendBench(Json& j, const BenchResults& r)
{
    j["stream"] = r.stream;
    j["lut"] = r.lut_path;
    j["width"] = r.width;
    j["height"] = r.height;
    j["frames"] = r.frames;
    j["repeat"] = r.repeat;
    j["threads"] = r.threads;
    j["frames_in_memory"] = r.in_memory;
    appendTimings(j, r);
}

std::string benchJson(const BenchResults& r)
{
    Json j;
    j["format"] = "fieldsight-bench/1";
    appendBench(j, r);
    return jsonText(j, 2) + "\n";
}

/// Mean ms of stage `id` in `r`, if it ran.
const TimingStats* stageStats(const BenchResults& r, const std::string& id)
{
    for (const auto& [stage, stats] : r.stages)
        if (stage == id)
            return &stats;
    return nullptr;
}

std::string multiBenchTable(const MultiBenchResults& m)
{
    const BenchResults& c = m.combined;
    std::string text;
    char line[512];
    int min_threads = c.threads;
    for (const BenchResults& r : m.streams)
        min_threads = std::min(min_threads, r.threads);
    std::snprintf(line, sizeof line,
                  "fieldsight bench: %zu streams, %zu frames x %d pass%s = %zu runs, %s%d "
                  "thread%s%s\n",
                  m.streams.size(), c.frames, c.repeat, c.repeat == 1 ? "" : "es",
                  c.pipeline.samples, min_threads == c.threads ? "" : "up to ", c.threads,
                  c.threads == 1 ? "" : "s", c.in_memory ? ", frames in memory" : "");
    text += line;
    for (std::size_t i = 0; i < m.streams.size(); ++i)
        if (!m.streams[i].in_memory)
            text += "  " + m.names[i] + ": frames decoded each pass (not timed)\n";

    int name_width = int(std::string_view("combined").size());
    for (const std::string& name : m.names)
        name_width = std::max(name_width, int(name.size()));

    // Table 1: one row per stream, then the combined row.
    std::snprintf(line, sizeof line, "\n%-*s %7s %9s %20s %10s %10s %9s %9s\n", name_width, "", "",
                  "", "pipeline ms/frame", "floor", "baseline", "pipeline", "pipeline");
    text += line;
    std::snprintf(line, sizeof line, "%-*s %7s %9s %20s %10s %10s %9s %9s\n", name_width, "stream",
                  "frames", "size", "mean (std)", "mean ms", "mean ms", "/ floor", "/ base");
    text += line;
    auto row = [&](const std::string& name, const BenchResults& r) {
        char size[32] = "mixed";
        if (r.width > 0)
            std::snprintf(size, sizeof size, "%dx%d", r.width, r.height);
        char timing[64];
        std::snprintf(timing, sizeof timing, "%.4f (%.4f)", r.pipeline.mean_ms, r.pipeline.std_ms);
        std::snprintf(line, sizeof line, "%-*s %7zu %9s %20s %10.4f %10.4f %8.2fx %8.2fx\n",
                      name_width, name.c_str(), r.frames, size, timing, r.floor.mean_ms,
                      r.baseline.mean_ms, ratio(r.pipeline.mean_ms, r.floor.mean_ms),
                      ratio(r.pipeline.mean_ms, r.baseline.mean_ms));
        text += line;
    };
    for (std::size_t i = 0; i < m.streams.size(); ++i)
        row(m.names[i], m.streams[i]);
    text += std::string(std::size_t(name_width) + 81, '-') + "\n";
    row("combined", c);

    // Per stage: rows stages, columns streams (mean ms per frame; "-" where it did not run).
    std::vector<int> widths;
    for (const std::string& name : m.names)
        widths.push_back(std::max(10, int(name.size())));
    widths.push_back(10);
    int stage_width = int(std::string_view("pipeline").size());
    for (const auto& [id, stats] : c.stages)
        stage_width = std::max(stage_width, int(id.size()));
    text += "\nmean ms per frame by stage\n";
    std::snprintf(line, sizeof line, "%-*s", stage_width, "stage");
    text += line;
    for (std::size_t i = 0; i <= m.names.size(); ++i) {
        std::snprintf(line, sizeof line, " %*s", widths[i],
                      i < m.names.size() ? m.names[i].c_str() : "combined");
        text += line;
    }
    text += "\n";
    auto cell = [&](std::size_t column, const TimingStats* stats) {
        if (stats)
            std::snprintf(line, sizeof line, " %*.4f", widths[column], stats->mean_ms);
        else
            std::snprintf(line, sizeof line, " %*s", widths[column], "-");
        text += line;
    };
    for (const auto& [id, stats] : c.stages) {
        std::snprintf(line, sizeof line, "%-*s", stage_width, id.c_str());
        text += line;
        for (std::size_t i = 0; i < m.streams.size(); ++i)
            cell(i, stageStats(m.streams[i], id));
        cell(m.streams.size(), &stats);
        text += "\n";
    }
    std::snprintf(line, sizeof line, "%-*s", stage_width, "pipeline");
    text += line;
    for (std::size_t i = 0; i < m.streams.size(); ++i)
        cell(i, &m.streams[i].pipeline);
    cell(m.streams.size(), &c.pipeline);
    text += "\n(std is the population standard deviation; the combined row pools every run of "
            "every stream, it does not average the streams' means)\n";
    return text;
}

std::string multiBenchJson(const MultiBenchResults& m)
{
    Json j;
    j["format"] = "fieldsight-bench/1";
    j["repeat"] = m.combined.repeat;
    Json& streams = j["streams"] = Json::array();
    for (std::size_t i = 0; i < m.streams.size(); ++i) {
        Json s;
        s["name"] = m.names[i];
        appendBench(s, m.streams[i]);
        streams.push_back(std::move(s));
    }
    Json c;
    c["streams"] = m.streams.size();
    if (m.combined.width > 0) {
        c["width"] = m.combined.width;
        c["height"] = m.combined.height;
    }
    c["frames"] = m.combined.frames;
    appendTimings(c, m.combined);
    j["combined"] = std::move(c);
    return jsonText(j, 2) + "\n";
}

/// Opens one stream of a bench and applies the settings. With several streams, an error that
/// does not name the stream (a bad LUT names the LUT) is prefixed with it.
Result<StreamInput> openBenchInput(const QCommandLineParser& parser, const std::string& stream,
                                   std::size_t stream_count, const Context& ctx)
{
    auto input = openInput(parser, stream, ctx);
    if (!input) {
        const std::string& message = input.error().message;
        if (stream_count > 1 && message.find(stream) == std::string::npos)
            return Error{stream + ": " + message};
        return input.error();
    }
    return input;
}

} // namespace

int benchCommand(const QStringList& args, const Context& ctx)
{
    QCommandLineParser parser;
    parser.setApplicationDescription(
        "Times the pipeline per frame (mean and standard deviation, per stage) next to a floor "
        "(only the scan lines' LUT lookups) and a full-frame OpenCV baseline. With several "
        "streams, each is timed on its own and the table has one row per stream and a combined "
        "row over all their frames, as the paper's Table 1, then the stages per stream.");
    parser.addPositionalArgument("STREAM", "Image folder, .strm file or video file; one or more.",
                                 "STREAM...");
    parser.addOption({"lut",
                      "Colour lookup table for every stream (default: each stream's own "
                      "default.lut).",
                      "FILE"});
    parser.addOption(setOption());
    parser.addOption(paramsOption());
    parser.addOption(orientationOption());
    parser.addOption(adaptOption());
    parser.addOption({"repeat", "Passes over each stream (default 1).", "N"});
    parser.addOption(threadsOption("1"));
    parser.addOption({"json", "Also write the numbers as fieldsight-bench/1 JSON.", "FILE"});
    parser.addOption({"limit", "Use only the first N frames of each stream.", "N"});
    if (auto done = parseCommand(parser, "bench", args, 1, std::numeric_limits<int>::max(), ctx))
        return *done;

    try {
        std::vector<std::string> streams; // one or more; each is benched on its own
        for (const QString& stream : parser.positionalArguments())
            streams.push_back(toLocalPath(stream));
        const std::string json_path = toLocalPath(parser.value("json")); // empty: no JSON
        std::vector<std::string> read = streams;
        read.push_back(toLocalPath(parser.value("lut")));
        read.push_back(toLocalPath(parser.value("params")));
        if (Status s = checkOutputFile("bench --json", json_path, read, kBenchFile); !s)
            return badInput(ctx, s.error().message);
        BenchOptions options;
        QString error;
        const auto repeat = intOption(parser, "repeat", 1, 1, error);
        const auto threads = intOption(parser, "threads", 1, 0, error);
        const auto limit = intOption(parser, "limit", 0, 1, error);
        if (!repeat || !threads || !limit)
            return badInput(ctx, ("bench: " + error).toStdString());
        options.repeat = int(*repeat);
        options.threads = int(*threads);
        options.limit = std::size_t(*limit);

        // Every stream is opened and checked before any is timed, so a bad last stream does
        // not cost a long run first.
        std::vector<StreamInput> inputs;
        for (const std::string& stream : streams) {
            auto input = openBenchInput(parser, stream, streams.size(), ctx);
            if (!input)
                return badInput(ctx, input.error().message);
            inputs.push_back(std::move(input).value());
        }
        std::vector<BenchResults> results;
        for (StreamInput& input : inputs) {
            auto r = runBench(input, options);
            if (!r)
                return badInput(ctx, r.error().message);
            results.push_back(std::move(r).value());
        }

        std::string table, json;
        if (results.size() == 1) {
            table = benchTable(results.front());
            json = benchJson(results.front());
        } else {
            const MultiBenchResults m = combineBenches(streams, std::move(results));
            table = multiBenchTable(m);
            json = multiBenchJson(m);
        }
        return finishReport(ctx, table, json_path, json);
    } catch (const std::exception& e) {
        return failure(ctx, "bench", e);
    }
}

} // namespace fieldsight::cli
