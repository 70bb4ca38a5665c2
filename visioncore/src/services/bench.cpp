// The benchmark: each worker times the pipeline and the two references on its block of frames;
// the workers' samples are merged into one set of statistics.
#include "visioncore/services/bench.h"

#include "visioncore/datawrappers/memory_data_wrapper.h"
#include "visioncore/framework/control_wrapper.h"
#include "visioncore/services/worker_pool.h"

#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <chrono>
#include <exception>
#include <filesystem>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <stdexcept>

namespace fieldsight {

namespace {

using Clock = std::chrono::steady_clock;

double msSince(Clock::time_point start)
{
    return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
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

/// The first problem any worker reports; the others then stop at their next frame.
class Problems
{
public:
    /// `failure`: the pipeline or the machine failed (thrown), not the input (an Error).
    void report(std::string message, bool failure)
    {
        std::lock_guard lock(m_mutex);
        if (!m_problem) {
            m_problem = std::move(message);
            m_failure = failure;
        }
    }
    bool any() const
    {
        std::lock_guard lock(m_mutex);
        return m_problem.has_value();
    }
    /// After the workers: throws a failure, returns an input problem, or nothing.
    std::optional<Error> result() const
    {
        if (!m_problem)
            return std::nullopt;
        if (m_failure)
            throw std::runtime_error(*m_problem);
        return Error{*m_problem};
    }

private:
    mutable std::mutex m_mutex;
    std::optional<std::string> m_problem;
    bool m_failure = false;
};

/// The frames a worker times: [begin, end), `repeat` passes, decoded once when `in_memory`.
struct Block
{
    std::size_t begin = 0;
    std::size_t end = 0;
    int repeat = 1;
    bool in_memory = false;
};

/// One worker: its own core on `source`, timing the pipeline and the references frame by frame.
class BenchWorker
{
public:
    BenchWorker(StreamInput& input, StreamReader& source, const Block& block, Samples& out,
                Problems& problems)
        : m_input(input), m_source(source), m_block(block), m_out(out), m_problems(problems),
          m_lut(input.adapt ? std::make_shared<ColourLut>(*input.lut) : nullptr),
          m_data(m_lut ? m_lut : input.lut), m_control(m_data, *input.pipeline)
    {
    }

    void run()
    {
        if (Status s = m_control.applyParams(m_input.params); !s) {
            m_problems.report("--set: " + s.error().message, false);
            return;
        }
        for (const StageDescriptor& stage : m_control.stages())
            m_out.stage_ids.push_back(stage.info.id);
        if (m_block.in_memory && !cacheFrames())
            return;
        const std::size_t runs = (m_block.end - m_block.begin) * std::size_t(m_block.repeat);
        m_out.pipeline.reserve(runs);
        m_out.floor.reserve(runs);
        m_out.baseline.reserve(runs);
        warmUp();
        for (int pass = 0; pass < m_block.repeat; ++pass) {
            if (m_input.adapt) // every pass follows the light from the block's first frame
                m_tracker.emplace(m_input.lut, *m_input.adapt);
            for (std::size_t i = m_block.begin; i < m_block.end; ++i) {
                if (m_problems.any())
                    return;
                const Frame* frame = frameAt(i);
                if (!frame || !timeFrame(*frame))
                    return;
            }
        }
    }

private:
    /// Decodes the block's frames once, for all passes; false (reported) when one cannot be read.
    bool cacheFrames()
    {
        m_cached.reserve(m_block.end - m_block.begin);
        for (std::size_t i = m_block.begin; i < m_block.end; ++i) {
            auto frame = m_source.read(i);
            if (!frame) {
                m_problems.report(frame.error().message, false);
                return false;
            }
            m_cached.push_back(std::move(frame).value());
        }
        return true;
    }

    /// Frame `i` of the block, from memory or read now; nullptr (reported) when unreadable.
    const Frame* frameAt(std::size_t i)
    {
        if (m_block.in_memory)
            return &m_cached[i - m_block.begin];
        auto read = m_source.read(i);
        if (!read) {
            m_problems.report(read.error().message, false);
            return nullptr;
        }
        m_loaded = std::move(read).value();
        return &m_loaded;
    }

    /// Untimed: one run of all three on the first frame, so one-off costs (allocations, OpenCV's
    /// first calls) do not land on whichever stream is benched first. A first frame that cannot
    /// be read is left to the timed passes to report.
    void warmUp()
    {
        if (m_block.begin >= m_block.end)
            return;
        const Frame* first = nullptr;
        if (m_block.in_memory) {
            first = &m_cached.front();
        } else if (auto read = m_source.read(m_block.begin)) {
            m_loaded = std::move(read).value();
            first = &m_loaded;
        }
        if (!first)
            return;
        m_data.setFrame(*first);
        if (m_control.runFrame()) {
            std::size_t pixels = 0;
            const Blackboard& bb = m_control.blackboard();
            m_sink = m_sink + floorLookups(first->ycbcr, m_data.lut(), bb.horizontal_scan_ys,
                                           bb.vertical_scan_starts, m_floor_classes, pixels);
        }
        m_sink = m_sink + fullFrameBaseline(first->ycbcr, m_data.lut(), m_buffers);
    }

    /// Times the pipeline, the floor and the baseline on `frame`; false (reported) when the
    /// pipeline fails on it.
    bool timeFrame(const Frame& frame)
    {
        m_data.setFrame(frame);
        // Untimed: bring the frame and its LUT cells into cache, so all three measurements below
        // start from the same state.
        m_input.lut->classifyImage(frame.ycbcr, m_warm);

        const auto start = Clock::now();
        if (m_tracker) // following the light is part of the pipeline's time
            m_lut->setInputMap(
                m_maps.mapFor(m_tracker->observe(frame.ycbcr, frame.horizon.value_or(Horizon{}))));
        auto frame_report = m_control.runFrame();
        const double pipeline_ms = msSince(start);
        if (!frame_report) {
            m_problems.report(m_input.stream + ": frame " + frame.name + ": " +
                                  frame_report.error().message,
                              true);
            return false;
        }
        m_out.pipeline.push_back(pipeline_ms);
        const auto& stages = frame_report.value().stages;
        for (std::size_t s = 0; s < stages.size(); ++s)
            if (stages[s].ran)
                m_out.stages[s].push_back(stages[s].ms);

        const Blackboard& bb = m_control.blackboard();
        std::size_t pixels = 0;
        const auto floor_start = Clock::now();
        m_sink = m_sink + floorLookups(frame.ycbcr, m_data.lut(), bb.horizontal_scan_ys,
                                       bb.vertical_scan_starts, m_floor_classes, pixels);
        m_out.floor.push_back(msSince(floor_start));
        m_out.floor_pixels += double(pixels);

        const auto baseline_start = Clock::now();
        m_sink = m_sink + fullFrameBaseline(frame.ycbcr, m_data.lut(), m_buffers);
        m_out.baseline.push_back(msSince(baseline_start));
        return true;
    }

    StreamInput& m_input;
    StreamReader& m_source;
    const Block m_block;
    Samples& m_out;
    Problems& m_problems;
    std::shared_ptr<ColourLut> m_lut; ///< with --adapt, the worker's copy its light's map is set on
    std::optional<LightTracker> m_tracker;
    LightMapCache m_maps;
    MemoryDataWrapper m_data;
    ControlWrapper m_control;
    std::vector<Frame> m_cached; ///< the block's frames, when in memory
    Frame m_loaded;              ///< the frame read last, when not
    cv::Mat m_warm;
    std::vector<std::uint8_t> m_floor_classes;
    BaselineBuffers m_buffers;
    volatile std::uint32_t m_sink = 0; ///< keeps the reference loops from being optimised out
};

/// Worker t of `threads`: a contiguous block of frames, so its reader reads sequentially.
/// Worker 0 reuses the input's reader; the others open their own.
void benchBlock(StreamInput& input, Block block, int t, int threads, std::size_t count,
                Samples& out, Problems& problems)
{
    try {
        block.begin = count * std::size_t(t) / std::size_t(threads);
        block.end = count * std::size_t(t + 1) / std::size_t(threads);
        std::unique_ptr<StreamReader> own;
        if (t > 0) {
            auto opened = input.reader->reopen(); // the same frames, turned alike
            if (!opened) {
                problems.report(opened.error().message, false);
                return;
            }
            own = std::move(opened).value();
        }
        BenchWorker(input, own ? *own : *input.reader, block, out, problems).run();
    } catch (const std::exception& e) {
        problems.report(input.stream + ": " + e.what(), true);
    }
}

/// The workers' samples as one set of statistics.
BenchResults mergeSamples(const StreamInput& input, std::vector<Samples>& samples)
{
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
    r.pipeline = TimingStats::of(all.pipeline);
    for (std::size_t s = 0; s < stage_ids.size(); ++s)
        if (!stage_samples[s].empty())
            r.stages.emplace_back(stage_ids[s], TimingStats::of(stage_samples[s]));
    r.floor = TimingStats::of(all.floor);
    r.floor_pixels_per_frame = all.floor.empty() ? 0 : all.floor_pixels / double(all.floor.size());
    r.baseline = TimingStats::of(all.baseline);
    return r;
}

} // namespace

Result<BenchResults> runBench(StreamInput& input, const BenchOptions& options)
{
    std::size_t count = input.info().frame_count;
    if (options.limit > 0)
        count = std::min(count, options.limit);
    int threads = workerCount(options.threads, count);
    if (input.info().kind == StreamKind::Camera)
        threads = 1;
    Block block;
    block.repeat = std::max(1, options.repeat);
    block.in_memory = count < kBenchInMemoryFrames;

    std::vector<Samples> samples{std::size_t(threads)};
    Problems problems;
    runOnWorkers(threads, [&](int t) {
        benchBlock(input, block, t, threads, count, samples[std::size_t(t)], problems);
    });
    if (std::optional<Error> problem = problems.result())
        return *problem;

    BenchResults r = mergeSamples(input, samples);
    r.frames = count;
    r.repeat = block.repeat;
    r.threads = threads;
    r.in_memory = block.in_memory;
    return r;
}

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

} // namespace fieldsight
