// Opening a stream input and running the pipeline over its frames with one core per worker.
#include "visioncore/services/stream_runner.h"

#include "visioncore/framework/control_wrapper.h"
#include "visioncore/datawrappers/stream_data_wrapper.h"
#include "visioncore/services/worker_pool.h"

#include <algorithm>
#include <cmath>
#include <mutex>
#include <optional>
#include <stdexcept>

#ifdef __linux__
#include <sys/resource.h>
#include <sys/syscall.h>
#include <unistd.h>
#endif

namespace fieldsight {

Result<ParamSet> streamParams(const StreamInfo& info, const Pipeline& pipeline)
{
    if (info.params.empty())
        return ParamSet{};
    const std::string named =
        info.path + " names the parameter file " + info.params + " (\"params\")";
    auto params = ParamSet::load(info.params);
    if (!params)
        return Error{named + ": " + params.error().message};
    if (Status s = params.value().check(pipeline); !s)
        return Error{named + ": " + s.error().message};
    return params;
}

Result<StreamInput> openStreamInput(const std::string& stream, const std::string& lut_path,
                                    const Pipeline& pipeline, const StreamOptions& options)
{
    auto reader = openStream(stream, options);
    if (!reader)
        return reader.error();
    StreamInput input;
    input.stream = stream;
    input.reader = std::move(reader).value();
    input.pipeline = &pipeline;
    input.lut_path = lut_path.empty() ? input.info().default_lut : lut_path;
    if (input.lut_path.empty())
        return Error{stream + ": no LUT given, and no default.lut in the stream folder"};
    auto lut = ColourLut::load(input.lut_path);
    if (!lut)
        return lut.error();
    input.lut = std::make_shared<const ColourLut>(std::move(lut).value());
    auto params = streamParams(input.info(), pipeline);
    if (!params)
        return params.error();
    input.params = std::move(params).value();
    return input;
}

Status checkSkip(const Pipeline& pipeline, const std::vector<std::string>& skip)
{
    for (const std::string& id : skip) {
        const StageDescriptor* d = pipeline.find(id);
        if (!d)
            return Error{"unknown stage '" + id + "' to skip (the stages are " + pipeline.idList() +
                         ")"};
        if (!d->info.skippable)
            return Error{"stage '" + id + "' cannot be skipped: later stages need it"};
    }
    return {};
}

Status StreamInput::checkSettings() const
{
    if (Status s = checkSkip(*pipeline, skip); !s)
        return s;
    return params.check(*pipeline);
}

FrameResult collectResult(std::size_t index, std::string name, FrameReport report,
                          const Blackboard& bb)
{
    FrameResult r;
    r.index = index;
    r.name = std::move(name);
    r.report = std::move(report);
    r.percepts = bb.percepts;
    r.diagnostics = bb.diagnostics;
    return r;
}

std::vector<std::size_t> firstFrames(std::size_t n)
{
    std::vector<std::size_t> indices(n);
    for (std::size_t i = 0; i < n; ++i)
        indices[i] = i;
    return indices;
}

void lowerThreadPriority(int niceness)
{
#ifdef __linux__
    thread_local int applied = 0;
    if (applied != niceness) {
        applied = niceness;
        setpriority(PRIO_PROCESS, id_t(syscall(SYS_gettid)), niceness);
    }
#else
    (void)niceness;
#endif
}

namespace {

/// Lends a reader to a StreamDataWrapper without giving it up, so a single worker reuses the
/// reader the input was opened with (opening a stream can decode a frame).
class BorrowedReader : public StreamReader
{
public:
    explicit BorrowedReader(StreamReader& reader) : m_reader(reader) {}
    const StreamInfo& info() const override { return m_reader.info(); }
    Result<Frame> read(std::size_t index) override { return m_reader.read(index); }
    Status readInto(std::size_t index, Frame& frame) override
    {
        return m_reader.readInto(index, frame);
    }
    std::string frameName(std::size_t index) const override { return m_reader.frameName(index); }

private:
    StreamReader& m_reader;
};

/// Receives the requested drawings of a worker's core.
class CanvasSink : public DebugSink
{
public:
    explicit CanvasSink(std::set<std::string, std::less<>> layers) : m_layers(std::move(layers)) {}
    std::set<std::string, std::less<>> requestedLayers() const override { return m_layers; }
    void publish(const DebugCanvas& canvas) override { m_canvas = &canvas; }
    const DebugCanvas& canvas() const { return m_canvas ? *m_canvas : m_empty; }

private:
    std::set<std::string, std::less<>> m_layers;
    const DebugCanvas* m_canvas = nullptr;
    DebugCanvas m_empty;
};

/// The first problem any worker met, by position in the work list, so the report is
/// deterministic whatever the thread timing.
class FirstProblem
{
public:
    void report(std::size_t position, std::string message, bool is_failure)
    {
        std::lock_guard lock(m_mutex);
        if (!m_message || position < m_position) {
            m_position = position;
            m_message = std::move(message);
            m_is_failure = is_failure;
        }
        m_stop = true;
    }
    bool stopped() const { return m_stop; }
    const std::optional<std::string>& message() const { return m_message; }
    bool isFailure() const { return m_is_failure; }

private:
    std::mutex m_mutex;
    std::atomic<bool> m_stop{false};
    std::size_t m_position = 0;
    std::optional<std::string> m_message;
    bool m_is_failure = false;
};

} // namespace

Result<StreamRun> runStream(StreamInput& input, const std::vector<std::size_t>& indices,
                            int threads, const RunHooks& hooks)
{
    if (Status s = input.checkSettings(); !s)
        return s.error();
    threads = workerCount(threads, indices.size());
    if (input.info().kind == StreamKind::Camera)
        threads = 1; // a camera opens only once

    std::vector<FrameResult> results(indices.size());
    std::vector<char> done(indices.size(), 0);
    // Small chunks balance the load while keeping each reader's access mostly sequential.
    const std::size_t chunk =
        std::clamp<std::size_t>(indices.size() / (4 * std::size_t(threads)), 1, 16);
    std::atomic<std::size_t> next{0};
    std::mutex progress_mutex;
    std::size_t done_count = 0;
    FirstProblem problem;
    const auto cancelled = [&] { return hooks.cancel && hooks.cancel->load(); };
    // The caller's pause (before a frame's read and before its run); false: cancelled meanwhile.
    const auto pausedThenGoOn = [&] {
        if (hooks.pause)
            hooks.pause();
        return !cancelled();
    };

    // Following the light: one worker running every frame from 0 in order tracks as it goes;
    // otherwise a first pass tracks frames 0 .. the last one asked for, and each worker reads
    // its frames' states. Either way a frame's light is the same.
    std::vector<LightState> light;
    const bool track_in_pass =
        input.adapt && threads == 1 && indices == firstFrames(indices.size());
    if (input.adapt && !track_in_pass && !indices.empty()) {
        const std::size_t last = *std::max_element(indices.begin(), indices.end());
        // The caller's pause holds this pass too (a background scan while the user steps).
        const auto pause = [&hooks](std::size_t, std::size_t) {
            if (hooks.pause)
                hooks.pause();
        };
        LightTrack track =
            trackLight(*input.reader, input.lut, last + 1, *input.adapt, pause, hooks.cancel);
        if (track.cancelled)
            return StreamRun{{}, {}, true};
        light = std::move(track.frames);
    } else if (track_in_pass) {
        light.resize(indices.size());
    }

    const auto markDone = [&](std::size_t pos) {
        done[pos] = 1;
        if (hooks.progress) {
            std::lock_guard lock(progress_mutex);
            hooks.progress(++done_count, indices.size());
        }
    };
    // A frame the run leaves out (unreadable, or refused by the prefilter) keeps only its index
    // and name.
    const auto leaveOut = [&](std::size_t pos, std::string name) {
        results[pos].index = indices[pos];
        results[pos].name = std::move(name);
        markDone(pos);
    };

    auto worker = [&](int t) {
        try {
            std::unique_ptr<StreamReader> reader;
            if (t == 0) {
                reader = std::make_unique<BorrowedReader>(*input.reader);
            } else {
                auto opened = input.reader->reopen();
                if (!opened) {
                    problem.report(0, opened.error().message, false);
                    return;
                }
                reader = std::move(opened).value();
            }
            StreamDataWrapper data(std::move(reader), input.lut);
            // With --adapt the worker's own copy of the table, its input map set frame by frame.
            std::shared_ptr<ColourLut> adapted;
            std::optional<LightTracker> tracker;
            LightMapCache maps;
            if (input.adapt) {
                adapted = std::make_shared<ColourLut>(*input.lut);
                data.setLut(adapted);
                if (track_in_pass)
                    tracker.emplace(input.lut, *input.adapt);
            }
            CanvasSink sink(hooks.layers);
            if (!hooks.layers.empty())
                data.setDebugSink(&sink);
            ControlWrapper control(data, *input.pipeline);
            for (const std::string& id : input.skip)
                if (Status s = control.setStageEnabled(id, false); !s)
                    throw std::logic_error(s.error().message); // checkSettings let it through
            if (Status s = control.applyParams(input.params); !s)
                throw std::logic_error(s.error().message);
            while (!problem.stopped() && !cancelled()) {
                const std::size_t begin = next.fetch_add(chunk);
                if (begin >= indices.size())
                    break;
                const std::size_t end = std::min(indices.size(), begin + chunk);
                for (std::size_t pos = begin; pos < end && !problem.stopped() && !cancelled();
                     ++pos) {
                    if (!pausedThenGoOn())
                        break;
                    if (Status s = data.seek(indices[pos]); !s) {
                        if (tracker)
                            light[pos] = tracker->skip();
                        if (!hooks.on_unreadable) {
                            problem.report(pos, s.error().message, false);
                            return;
                        }
                        hooks.on_unreadable(indices[pos], s.error().message);
                        leaveOut(pos, data.reader().frameName(indices[pos]));
                        continue;
                    }
                    if (tracker)
                        light[pos] = tracker->observe(data.frame().ycbcr, data.kinematicHorizon());
                    if (adapted)
                        adapted->setInputMap(maps.mapFor(light[indices[pos]]));
                    if (!pausedThenGoOn())
                        break;
                    if (hooks.prefilter && !hooks.prefilter(indices[pos], data.frame(),
                                                            adapted ? *adapted : *input.lut)) {
                        leaveOut(pos, data.frame().name);
                        continue;
                    }
                    auto report = control.runFrame();
                    if (!report) {
                        problem.report(pos,
                                       input.stream + ": frame " + data.frame().name + ": " +
                                           report.error().message,
                                       true);
                        return;
                    }
                    results[pos] = collectResult(indices[pos], data.frame().name,
                                                 std::move(report).value(), control.blackboard());
                    if (hooks.on_frame) {
                        if (Status s = hooks.on_frame(results[pos], data.frame(), sink.canvas());
                            !s) {
                            problem.report(pos, s.error().message, true);
                            return;
                        }
                    }
                    markDone(pos);
                }
            }
        } catch (const std::exception& e) {
            problem.report(0, input.stream + ": " + e.what(), true);
        } catch (...) {
            problem.report(0, input.stream + ": unknown exception", true);
        }
    };
    runOnWorkers(threads, worker);

    if (problem.message()) {
        if (problem.isFailure())
            throw std::runtime_error(*problem.message());
        return Error{*problem.message()};
    }
    // After a cancel, workers may have finished frames beyond one still undone: the run keeps
    // the contiguous prefix, so a caller can carry on from frames.size().
    StreamRun run;
    const std::size_t prefix = std::size_t(std::find(done.begin(), done.end(), 0) - done.begin());
    run.cancelled = prefix < done.size();
    results.resize(prefix);
    run.frames = std::move(results);
    if (track_in_pass)
        light.resize(prefix);
    run.light = std::move(light);
    return run;
}

TimingStats TimingStats::of(const std::vector<double>& samples_ms)
{
    TimingStats stats;
    stats.samples = samples_ms.size();
    if (samples_ms.empty())
        return stats;
    double sum = 0;
    for (double v : samples_ms)
        sum += v;
    stats.mean_ms = sum / double(samples_ms.size());
    double squares = 0;
    for (double v : samples_ms)
        squares += (v - stats.mean_ms) * (v - stats.mean_ms);
    stats.std_ms = std::sqrt(squares / double(samples_ms.size())); // population, as the paper
    return stats;
}

TimingStats TimingStats::pooled(const std::vector<TimingStats>& parts)
{
    TimingStats stats;
    double sum = 0;
    for (const TimingStats& p : parts) {
        stats.samples += p.samples;
        sum += double(p.samples) * p.mean_ms;
    }
    if (stats.samples == 0)
        return stats;
    stats.mean_ms = sum / double(stats.samples);
    // Each part's sum of squared deviations from the pooled mean is n * (std^2 + (mean - M)^2).
    double squares = 0;
    for (const TimingStats& p : parts) {
        const double offset = p.mean_ms - stats.mean_ms;
        squares += double(p.samples) * (p.std_ms * p.std_ms + offset * offset);
    }
    stats.std_ms = std::sqrt(squares / double(stats.samples));
    return stats;
}

} // namespace fieldsight
