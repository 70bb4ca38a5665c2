// Opening a batch input and running the pipeline over frames with one core per worker thread.
#include "visioncore/batch.h"

#include "visioncore/control_wrapper.h"
#include "visioncore/stream_data_wrapper.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <mutex>
#include <optional>
#include <stdexcept>
#include <thread>

namespace fieldsight {

Result<BatchInput> openBatchInput(const std::string& stream, const std::string& lut_path,
                                  const std::vector<std::string>& settings)
{
    auto reader = openStream(stream);
    if (!reader)
        return reader.error();
    BatchInput input;
    input.stream = stream;
    input.reader = std::move(reader).value();
    input.lut_path = lut_path.empty() ? input.info().default_lut : lut_path;
    if (input.lut_path.empty())
        return Error{stream + ": no LUT: pass --lut or put default.lut in the stream folder"};
    auto lut = ColourLut::load(input.lut_path);
    if (!lut)
        return lut.error();
    input.lut = std::move(lut).value();
    if (Status s = applySettings(input, settings); !s)
        return s.error();
    return input;
}

Status checkStageIds(const std::vector<std::string>& ids)
{
    const std::vector<std::string> known = pipelineStageIds();
    for (const std::string& id : ids) {
        if (std::find(known.begin(), known.end(), id) != known.end())
            continue;
        std::string list;
        for (const std::string& k : known)
            list += (list.empty() ? "" : ", ") + k;
        return Error{"--skip: unknown stage '" + id + "' (the stages are " + list + ")"};
    }
    return {};
}

bool FrameResult::stageRan(std::string_view stage_id) const
{
    for (const StageTiming& timing : report.stages)
        if (timing.stage == stage_id)
            return timing.ran;
    return false;
}

FrameDetections FrameResult::detections() const
{
    return {balls, goalposts, obstacles, green_horizon};
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

namespace {

FrameResult collectResult(std::size_t index, const std::string& name, FrameReport report,
                          const Blackboard& bb)
{
    FrameResult r;
    r.index = index;
    r.name = name;
    r.report = std::move(report);
    r.green_horizon = bb.green_horizon.hull();
    r.balls = bb.balls;
    r.goalposts = bb.goalposts;
    r.obstacles = bb.obstacles;
    r.field_lines = bb.field_lines;
    r.diagnostics = bb.diagnostics;
    return r;
}

/// Lends a reader to a StreamDataWrapper without giving it up, so a single worker reuses the
/// reader the input was opened with (opening a stream can decode a frame).
class BorrowedReader : public StreamReader
{
public:
    explicit BorrowedReader(StreamReader& reader) : m_reader(reader) {}
    const StreamInfo& info() const override { return m_reader.info(); }
    Result<Frame> read(std::size_t index) override { return m_reader.read(index); }
    std::string frameName(std::size_t index) const override { return m_reader.frameName(index); }

private:
    StreamReader& m_reader;
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

Result<std::vector<FrameResult>> processFrames(BatchInput& input,
                                               const std::vector<std::size_t>& indices,
                                               const std::vector<std::string>& skip, int threads)
{
    if (threads <= 0)
        threads = int(std::max(1u, std::thread::hardware_concurrency()));
    if (input.info().kind == StreamKind::Camera)
        threads = 1; // a camera opens only once
    threads =
        int(std::min<std::size_t>(std::size_t(threads), std::max<std::size_t>(1, indices.size())));

    std::vector<FrameResult> results(indices.size());
    // Small chunks balance the load while keeping each reader's access mostly sequential.
    const std::size_t chunk =
        std::clamp<std::size_t>(indices.size() / (4 * std::size_t(threads)), 1, 16);
    std::atomic<std::size_t> next{0};
    FirstProblem problem;

    std::atomic<bool> input_reader_lent{false};
    auto worker = [&]() {
        try {
            std::unique_ptr<StreamReader> reader;
            if (!input_reader_lent.exchange(true)) {
                reader = std::make_unique<BorrowedReader>(*input.reader);
            } else {
                auto opened = openStream(input.stream);
                if (!opened) {
                    problem.report(0, opened.error().message, false);
                    return;
                }
                reader = std::move(opened).value();
            }
            StreamDataWrapper data(std::move(reader), input.lut);
            ControlWrapper control(data);
            for (const std::string& id : skip) {
                if (Status s = control.setStageEnabled(id, false); !s) {
                    problem.report(0, "--skip: " + s.error().message, false);
                    return;
                }
            }
            if (Status s = configureControl(control, input); !s) {
                problem.report(0, "--set: " + s.error().message, false);
                return;
            }
            while (!problem.stopped()) {
                const std::size_t begin = next.fetch_add(chunk);
                if (begin >= indices.size())
                    break;
                const std::size_t end = std::min(indices.size(), begin + chunk);
                for (std::size_t pos = begin; pos < end && !problem.stopped(); ++pos) {
                    if (Status s = data.seek(indices[pos]); !s) {
                        problem.report(pos, s.error().message, false);
                        return;
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
                }
            }
        } catch (const std::exception& e) {
            problem.report(0, input.stream + ": " + e.what(), true);
        }
    };

    if (threads == 1) {
        worker();
    } else {
        std::vector<std::thread> pool;
        pool.reserve(std::size_t(threads));
        for (int t = 0; t < threads; ++t)
            pool.emplace_back(worker);
        for (std::thread& t : pool)
            t.join();
    }

    if (problem.message()) {
        if (problem.isFailure())
            throw std::runtime_error(*problem.message());
        return Error{*problem.message()};
    }
    return results;
}

Status applySettings(BatchInput& input, const std::vector<std::string>& settings)
{
    const Controller pipeline;
    for (const std::string& text : settings) {
        const auto dot = text.find('.');
        const auto eq = text.find('=');
        if (dot == std::string::npos || eq == std::string::npos || dot > eq)
            return Error{"--set " + text + ": expected STAGE.PARAM=VALUE"};
        const std::string stage = text.substr(0, dot);
        const std::string name = text.substr(dot + 1, eq - dot - 1);
        double value = 0;
        try {
            std::size_t used = 0;
            value = std::stod(text.substr(eq + 1), &used);
            if (used != text.size() - eq - 1)
                throw std::invalid_argument("trailing characters");
        } catch (const std::exception&) {
            return Error{"--set " + text + ": the value is not a number"};
        }
        Stage* s = pipeline.stage(stage);
        if (!s)
            return Error{"--set " + text + ": unknown stage '" + stage + "'"};
        if (Status ok = s->setParam(name, value); !ok)
            return Error{"--set " + text + ": " + ok.error().message};
        input.params.emplace_back(stage, name, value);
    }
    return {};
}

Status configureControl(ControlWrapper& control, const BatchInput& input)
{
    for (const auto& [stage, name, value] : input.params)
        if (Status s = control.setParam(stage, name, value); !s)
            return s;
    return {};
}

} // namespace fieldsight
