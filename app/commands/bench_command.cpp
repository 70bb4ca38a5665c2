// `fieldsight bench`: ms per frame as in the paper's Table 1, next to two references measured on
// the same frames in the same run: the LUT lookups the scan lines need (a floor for any scan-line
// design) and a full-frame classification with OpenCV connected components (a common baseline).
#include "commands/commands.h"

#include "visioncore/basics/json_text.h"
#include "visioncore/framework/control_wrapper.h"
#include "visioncore/datawrappers/memory_data_wrapper.h"
#include "visioncore/services/worker_pool.h"

#include <nlohmann/json.hpp>
#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <map>
#include <mutex>
#include <optional>
#include <limits>
#include <stdexcept>
#include <string_view>

namespace fieldsight::cli {
namespace {

struct BenchOptions
{
    std::vector<std::string> streams; ///< one or more; each is benched on its own
    int repeat = 1;                   ///< passes over each stream
    int threads = 1;                  ///< 0: one per core
    std::size_t limit = 0;            ///< only the first `limit` frames; 0: all
    std::string json;                 ///< also write fieldsight-bench/1 here when not empty
};

/// Streams with fewer frames than this are decoded once and kept in memory for all passes.
inline constexpr std::size_t kBenchInMemoryFrames = 2000;

struct BenchResults
{
    std::string stream;
    std::string lut_path;
    int width = 0;  ///< px
    int height = 0; ///< px
    std::size_t frames = 0;
    int repeat = 1;
    int threads = 1;
    bool in_memory = false;
    TimingStats pipeline; ///< ControlWrapper::runFrame, wall clock
    std::vector<std::pair<std::string, TimingStats>> stages; ///< pipeline order, runs only
    /// Only the LUT lookups of the pixels the scan lines touch (a lower bound for any scan-line
    /// design on these frames).
    TimingStats floor;
    double floor_pixels_per_frame = 0;
    /// Every pixel through the LUT into a class image, then OpenCV connected components of the
    /// ball and goal classes (what one would write without scan lines).
    TimingStats baseline;
};

/// Several streams benched with the same options, laid out as the paper's Table 1: one row per
/// stream and a combined row over all frames of all streams.
struct MultiBenchResults
{
    std::vector<std::string> names;    ///< row labels (benchStreamName), in the order given
    std::vector<BenchResults> streams; ///< same order as names
    /// Every run of every stream pooled (TimingStats::pooled), per stage too; frames is the sum,
    /// stream and lut are empty, width and height are 0 unless all streams share a size.
    BenchResults combined;
};

using Clock = std::chrono::steady_clock;

double msSince(Clock::time_point start)
{
    return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

/// The floor: only the lookups of the pixels the pipeline's scan lines touch (full-width rows at
/// `rows`, and columns from each start down to the bottom), through the scan lines' own lookup
/// loop. Returns a checksum of the classes so the work cannot be optimised away; `pixels`
/// receives the number of lookups.
std::uint32_t floorLookups(const cv::Mat& image, const ColourLut& lut, const std::vector<int>& rows,
                           const std::vector<PixelPoint>& starts,
                           std::vector<std::uint8_t>& classes, std::size_t& pixels)
{
    classes.resize(std::size_t(std::max(image.rows, image.cols)));
    std::uint32_t sum = 0;
    std::size_t count = 0;
    for (int y : rows) {
        if (y < 0 || y >= image.rows)
            continue;
        lut.classifyRun(image.ptr<std::uint8_t>(y), 3, image.cols, classes.data());
        sum += classes[std::size_t(image.cols) / 2];
        count += std::size_t(image.cols);
    }
    const std::ptrdiff_t step = std::ptrdiff_t(image.step[0]);
    for (const PixelPoint& s : starts) {
        if (s.x < 0 || s.x >= image.cols)
            continue;
        const int y0 = std::max(0, s.y);
        lut.classifyRun(image.ptr<std::uint8_t>(y0) + 3 * s.x, step, image.rows - y0,
                        classes.data());
        sum += classes[0];
        count += std::size_t(image.rows - y0);
    }
    pixels = count;
    return sum;
}

struct BaselineBuffers
{
    cv::Mat classes, mask, labels, stats, centroids;
};

/// The baseline: a class image of the whole frame, then for the ball (orange) and goal (yellow)
/// classes a mask and connected components, keeping the largest blob. Returns a checksum.
std::uint32_t fullFrameBaseline(const cv::Mat& image, const ColourLut& lut, BaselineBuffers& b)
{
    lut.classifyImage(image, b.classes);
    std::uint32_t sum = 0;
    for (Colour colour : {Colour::Orange, Colour::Yellow}) {
        cv::compare(b.classes, cv::Scalar(double(colour)), b.mask, cv::CMP_EQ);
        const int n =
            cv::connectedComponentsWithStats(b.mask, b.labels, b.stats, b.centroids, 8, CV_32S);
        int best = 0;
        int best_area = 0;
        for (int i = 1; i < n; ++i) {
            const int area = b.stats.at<int>(i, cv::CC_STAT_AREA);
            if (area > best_area) {
                best_area = area;
                best = i;
            }
        }
        if (best > 0)
            sum += std::uint32_t(best_area + b.stats.at<int>(best, cv::CC_STAT_LEFT) +
                                 b.stats.at<int>(best, cv::CC_STAT_TOP));
    }
    return sum;
}

/// What one worker measured; merged after all workers finish.
struct Samples
{
    std::vector<double> pipeline;
    std::map<std::size_t, std::vector<double>> stages; ///< by position in the pipeline
    std::vector<std::string> stage_ids;                ///< pipeline order
    std::vector<double> floor;
    std::vector<double> baseline;
    double floor_pixels = 0;
};

Result<BenchResults> runBench(StreamInput& input, const BenchOptions& options)
{
    std::size_t count = input.info().frame_count;
    if (options.limit > 0)
        count = std::min(count, options.limit);
    int threads = workerCount(options.threads, count);
    if (input.info().kind == StreamKind::Camera)
        threads = 1;
    const int repeat = std::max(1, options.repeat);
    const bool in_memory = count < kBenchInMemoryFrames;

    std::vector<Samples> samples{std::size_t(threads)};
    std::mutex problem_mutex;
    std::optional<std::string> problem;
    bool problem_is_failure = false;
    auto report = [&](std::string message, bool failure) {
        std::lock_guard lock(problem_mutex);
        if (!problem) {
            problem = std::move(message);
            problem_is_failure = failure;
        }
    };

    // Worker t takes a contiguous block of frames, so its reader reads sequentially.
    auto worker = [&](int t) {
        try {
            const std::size_t begin = count * std::size_t(t) / std::size_t(threads);
            const std::size_t end = count * std::size_t(t + 1) / std::size_t(threads);
            // Worker 0 reuses the input's reader; the others open their own.
            std::unique_ptr<StreamReader> own;
            if (t > 0) {
                auto opened = openStream(input.stream);
                if (!opened) {
                    report(opened.error().message, false);
                    return;
                }
                own = std::move(opened).value();
            }
            StreamReader& source = own ? *own : *input.reader;
            MemoryDataWrapper data(input.lut);
            ControlWrapper control(data, *input.pipeline);
            if (Status s = control.applyParams(input.params); !s) {
                report("--set: " + s.error().message, false);
                return;
            }
            Samples& out = samples[std::size_t(t)];
            for (const StageDescriptor& stage : control.stages())
                out.stage_ids.push_back(stage.info.id);

            std::vector<Frame> cached;
            if (in_memory) {
                cached.reserve(end - begin);
                for (std::size_t i = begin; i < end; ++i) {
                    auto frame = source.read(i);
                    if (!frame) {
                        report(frame.error().message, false);
                        return;
                    }
                    cached.push_back(std::move(frame).value());
                }
            }

            cv::Mat warm;
            std::vector<std::uint8_t> floor_classes;
            BaselineBuffers buffers;
            volatile std::uint32_t sink = 0; // keeps the reference loops from being optimised out
            const std::size_t runs = (end - begin) * std::size_t(repeat);
            out.pipeline.reserve(runs);
            out.floor.reserve(runs);
            out.baseline.reserve(runs);
            Frame loaded;
            // Untimed: one run of all three on the first frame, so one-off costs (allocations,
            // OpenCV's first calls) do not land on whichever stream is benched first.
            if (begin < end) {
                const Frame* first = nullptr;
                if (in_memory) {
                    first = &cached.front();
                } else if (auto read = source.read(begin)) {
                    loaded = std::move(read).value();
                    first = &loaded;
                }
                if (first) {
                    data.setFrame(*first);
                    if (control.runFrame()) {
                        std::size_t pixels = 0;
                        const Blackboard& bb = control.blackboard();
                        sink = sink + floorLookups(first->ycbcr, *input.lut, bb.horizontal_scan_ys,
                                                   bb.vertical_scan_starts, floor_classes, pixels);
                    }
                    sink = sink + fullFrameBaseline(first->ycbcr, *input.lut, buffers);
                }
            }
            for (int pass = 0; pass < repeat; ++pass) {
                for (std::size_t i = begin; i < end; ++i) {
                    {
                        std::lock_guard lock(problem_mutex);
                        if (problem)
                            return;
                    }
                    const Frame* frame = nullptr;
                    if (in_memory) {
                        frame = &cached[i - begin];
                    } else {
                        auto read = source.read(i);
                        if (!read) {
                            report(read.error().message, false);
                            return;
                        }
                        loaded = std::move(read).value();
                        frame = &loaded;
                    }
                    data.setFrame(*frame);
                    // Untimed: bring the frame and its LUT cells into cache, so all three
                    // measurements below start from the same state.
                    input.lut->classifyImage(frame->ycbcr, warm);

                    const auto start = Clock::now();
                    auto frame_report = control.runFrame();
                    const double pipeline_ms = msSince(start);
                    if (!frame_report) {
                        report(input.stream + ": frame " + frame->name + ": " +
                                   frame_report.error().message,
                               true);
                        return;
                    }
                    out.pipeline.push_back(pipeline_ms);
                    const auto& stages = frame_report.value().stages;
                    for (std::size_t s = 0; s < stages.size(); ++s)
                        if (stages[s].ran)
                            out.stages[s].push_back(stages[s].ms);

                    const Blackboard& bb = control.blackboard();
                    std::size_t pixels = 0;
                    const auto floor_start = Clock::now();
                    sink = sink + floorLookups(frame->ycbcr, *input.lut, bb.horizontal_scan_ys,
                                               bb.vertical_scan_starts, floor_classes, pixels);
                    out.floor.push_back(msSince(floor_start));
                    out.floor_pixels += double(pixels);

                    const auto baseline_start = Clock::now();
                    sink = sink + fullFrameBaseline(frame->ycbcr, *input.lut, buffers);
                    out.baseline.push_back(msSince(baseline_start));
                }
            }
        } catch (const std::exception& e) {
            report(input.stream + ": " + e.what(), true);
        }
    };

    runOnWorkers(threads, worker);
    if (problem) {
        if (problem_is_failure)
            throw std::runtime_error(*problem);
        return Error{*problem};
    }

    // Merge the workers' samples.
    Samples all;
    std::vector<std::vector<double>> stage_samples;
    std::vector<std::string> stage_ids;
    for (Samples& s : samples) {
        all.pipeline.insert(all.pipeline.end(), s.pipeline.begin(), s.pipeline.end());
        all.floor.insert(all.floor.end(), s.floor.begin(), s.floor.end());
        all.baseline.insert(all.baseline.end(), s.baseline.begin(), s.baseline.end());
        all.floor_pixels += s.floor_pixels;
        if (stage_ids.empty() && !s.stage_ids.empty()) {
            stage_ids = s.stage_ids;
            stage_samples.resize(stage_ids.size());
        }
        for (auto& [position, values] : s.stages)
            if (position < stage_samples.size())
                stage_samples[position].insert(stage_samples[position].end(), values.begin(),
                                               values.end());
    }

    BenchResults r;
    r.stream = input.stream;
    r.lut_path = input.lut_path;
    r.width = input.info().width;
    r.height = input.info().height;
    r.frames = count;
    r.repeat = repeat;
    r.threads = threads;
    r.in_memory = in_memory;
    r.pipeline = TimingStats::of(all.pipeline);
    for (std::size_t s = 0; s < stage_ids.size(); ++s)
        if (!stage_samples[s].empty())
            r.stages.emplace_back(stage_ids[s], TimingStats::of(stage_samples[s]));
    r.floor = TimingStats::of(all.floor);
    r.floor_pixels_per_frame = all.floor.empty() ? 0 : all.floor_pixels / double(all.floor.size());
    r.baseline = TimingStats::of(all.baseline);
    return r;
}

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

std::string benchStreamName(const std::string& stream)
{
    if (stream.rfind("camera:", 0) == 0)
        return stream;
    // Absolute and normal first, so "x/", "." and ".." name the folder they mean.
    std::error_code ec;
    std::filesystem::path path = std::filesystem::absolute(stream, ec).lexically_normal();
    if (ec)
        return stream;
    if (!path.has_filename())
        path = path.parent_path();
    const std::string name = path.filename().string();
    return name.empty() ? stream : name;
}

MultiBenchResults combineBenches(const std::vector<std::string>& streams,
                                 std::vector<BenchResults> results)
{
    MultiBenchResults m;
    std::vector<std::string> base;
    for (const std::string& stream : streams)
        base.push_back(benchStreamName(stream));
    // Streams that share a name (lab/a/stream, lab/b/stream) are shown as given instead.
    for (std::size_t i = 0; i < base.size(); ++i) {
        const bool ambiguous =
            base[i] == "combined" || std::count(base.begin(), base.end(), base[i]) > 1;
        m.names.push_back(ambiguous ? streams[i] : base[i]);
    }
    m.streams = std::move(results);

    BenchResults& c = m.combined;
    std::vector<TimingStats> pipeline, floor, baseline;
    std::vector<std::string> stage_ids; // pipeline order, first seen first
    double floor_pixels = 0;
    for (std::size_t i = 0; i < m.streams.size(); ++i) {
        const BenchResults& r = m.streams[i];
        if (i == 0) {
            c.width = r.width;
            c.height = r.height;
            c.repeat = r.repeat;
            c.in_memory = r.in_memory;
        } else if (r.width != c.width || r.height != c.height) {
            c.width = c.height = 0;
        }
        c.frames += r.frames;
        c.threads = std::max(c.threads, r.threads);
        c.in_memory = c.in_memory && r.in_memory;
        pipeline.push_back(r.pipeline);
        floor.push_back(r.floor);
        baseline.push_back(r.baseline);
        floor_pixels += r.floor_pixels_per_frame * double(r.floor.samples);
        for (const auto& [id, stats] : r.stages)
            if (std::find(stage_ids.begin(), stage_ids.end(), id) == stage_ids.end())
                stage_ids.push_back(id);
    }
    c.pipeline = TimingStats::pooled(pipeline);
    c.floor = TimingStats::pooled(floor);
    c.baseline = TimingStats::pooled(baseline);
    c.floor_pixels_per_frame = c.floor.samples > 0 ? floor_pixels / double(c.floor.samples) : 0;
    for (const std::string& id : stage_ids) {
        std::vector<TimingStats> parts;
        for (const BenchResults& r : m.streams)
            for (const auto& [stage, stats] : r.stages)
                if (stage == id)
                    parts.push_back(stats);
        c.stages.emplace_back(id, TimingStats::pooled(parts));
    }
    return m;
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
    parser.addOption({"repeat", "Passes over each stream (default 1).", "N"});
    parser.addOption(threadsOption("1"));
    parser.addOption({"json", "Also write the numbers as fieldsight-bench/1 JSON.", "FILE"});
    parser.addOption({"limit", "Use only the first N frames of each stream.", "N"});
    if (auto done = parseCommand(parser, "bench", args, 1, std::numeric_limits<int>::max(), ctx))
        return *done;

    try {
        BenchOptions options;
        for (const QString& stream : parser.positionalArguments())
            options.streams.push_back(toLocalPath(stream));
        options.json = toLocalPath(parser.value("json"));
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
        for (const std::string& stream : options.streams) {
            auto input = openBenchInput(parser, stream, options.streams.size(), ctx);
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
            const MultiBenchResults m = combineBenches(options.streams, std::move(results));
            table = multiBenchTable(m);
            json = multiBenchJson(m);
        }
        return finishReport(ctx, table, options.json, json);
    } catch (const std::exception& e) {
        printError(ctx.err, e.what());
        return kExitFailure;
    }
}

} // namespace fieldsight::cli
