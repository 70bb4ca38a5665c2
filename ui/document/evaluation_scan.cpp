#include "ui/document/evaluation_scan.h"

#include "ui/adapters/local_path.h"

#include <QtConcurrent/QtConcurrentRun>

#include <algorithm>
#include <chrono>
#include <exception>
#include <filesystem>
#include <new>

namespace fieldsight::ui {

struct EvaluationScan::Job
{
    std::string stream;
    StreamOptions options;
    const Pipeline* pipeline = nullptr;
    std::shared_ptr<const ColourLut> lut;
    std::shared_ptr<const ParamSet> params;
    std::vector<std::string> skip;
    int threads = 0;
    /// The annotations to score against; null: read them beside the stream first.
    std::shared_ptr<const Annotations> truth;
    std::string truth_path;
    int truth_serial = 0;
    bool edit = false; ///< follows a table or settings change
    std::chrono::steady_clock::time_point requested;

    std::atomic<bool> cancel{false};
    std::atomic<std::size_t> done{0};
    std::atomic<std::size_t> total{0};
};

struct EvaluationScan::Outcome
{
    bool loaded_truth = false; ///< `truth` was read by this job
    std::shared_ptr<const Annotations> truth;
    std::size_t scored_frames = 0;
    std::optional<EvalReport> report;
    std::string error;
    bool cancelled = false;
};

Result<std::shared_ptr<const Annotations>>
streamAnnotations(const QString& spec, const Pipeline& pipeline, std::size_t frames)
{
    const std::string path = defaultTruthPath(toLocalPath(spec));
    std::error_code ec;
    if (!std::filesystem::exists(path, ec))
        return std::shared_ptr<const Annotations>();
    auto loaded = Annotations::load(path, pipeline.perceptKinds(), frames);
    if (!loaded)
        return loaded.error();
    return std::make_shared<const Annotations>(std::move(loaded).value());
}

EvaluationScan::EvaluationScan(const Pipeline& pipeline, QObject* parent)
    : QObject(parent), m_pipeline(pipeline)
{
    // A pool of its own: the run's calling thread lowers its priority, which must not stay
    // with a thread of the global pool.
    m_pool.setMaxThreadCount(1);
    m_delay.setSingleShot(true);
    m_delay.setInterval(300);
    connect(&m_delay, &QTimer::timeout, this, &EvaluationScan::start);
    m_poll.setInterval(100);
    connect(&m_poll, &QTimer::timeout, this, &EvaluationScan::progressed);
    connect(&m_watcher, &QFutureWatcherBase::finished, this, &EvaluationScan::onFinished);
}

EvaluationScan::~EvaluationScan()
{
    if (m_job)
        m_job->cancel = true;
    m_watcher.waitForFinished();
}

EvaluationScan::Outcome EvaluationScan::runJob(const std::shared_ptr<Job>& job)
{
    Outcome out;
    try {
        std::shared_ptr<const Annotations> truth = job->truth;
        auto reader = openStream(job->stream, job->options);
        if (!reader) {
            out.error = reader.error().message;
            return out;
        }
        if (!truth) {
            auto loaded = streamAnnotations(QString::fromStdString(job->stream), *job->pipeline,
                                            reader.value()->info().frame_count);
            if (!loaded) {
                out.error = loaded.error().message;
                return out;
            }
            out.loaded_truth = true;
            out.truth = loaded.value();
            truth = out.truth;
            if (!truth)
                return out;
        }
        out.scored_frames =
            std::size_t(std::count_if(truth->frames.begin(), truth->frames.end(),
                                      [](const auto& f) { return isScored(f.second); }));
        if (out.scored_frames == 0)
            return out;
        job->total = out.scored_frames;
        StreamInput input;
        input.stream = job->stream;
        input.reader = std::move(reader).value();
        input.pipeline = job->pipeline;
        input.lut = job->lut;
        input.params = *job->params;
        input.skip = job->skip;
        RunHooks hooks;
        hooks.cancel = &job->cancel;
        hooks.progress = [&job](std::size_t done, std::size_t) { job->done = done; };
        hooks.prefilter = [](std::size_t, const Frame&) {
            lowerThreadPriority();
            return true;
        };
        auto report = evaluateStream(input, *truth, job->truth_path, job->threads, hooks);
        if (job->cancel)
            out.cancelled = true;
        else if (!report)
            out.error = report.error().message;
        else
            out.report = std::move(report).value();
    } catch (const std::bad_alloc&) {
        out.error = job->stream + ": not enough memory to evaluate it";
    } catch (const std::exception& e) {
        out.error = job->stream + ": " + e.what();
    }
    return out;
}

void EvaluationScan::setStream(const QString& spec, std::shared_ptr<const ColourLut> lut,
                               StreamOptions options)
{
    m_delay.stop();
    if (m_job)
        m_job->cancel = true; // its outcome is dropped: it belongs to another stream
    m_spec = spec.startsWith(QLatin1String("camera:")) ? QString() : spec;
    m_options = options;
    m_lut = std::move(lut);
    m_truth.reset();
    m_truth_path = m_spec.isEmpty() ? QString()
                                    : QString::fromStdString(defaultTruthPath(toLocalPath(m_spec)));
    ++m_truth_serial;
    m_scored_frames = 0;
    m_report.reset();
    m_before.reset();
    m_failing.clear();
    m_problem.clear();
    m_pending = !m_spec.isEmpty() && m_lut;
    m_pending_edit = false;
    m_load_truth = true;
    m_requested = std::chrono::steady_clock::now();
    emit finished(); // what was shown is gone
    start();
}

void EvaluationScan::setTruth(std::shared_ptr<const Annotations> truth, const QString& path)
{
    m_truth = std::move(truth);
    m_truth_path = path;
    m_load_truth = false;
    ++m_truth_serial;
    m_scored_frames =
        m_truth ? std::size_t(std::count_if(m_truth->frames.begin(), m_truth->frames.end(),
                                            [](const auto& f) { return isScored(f.second); }))
                : 0;
    schedule(false);
}

void EvaluationScan::setLut(std::shared_ptr<const ColourLut> lut)
{
    if (!lut || lut == m_lut)
        return;
    m_lut = std::move(lut);
    schedule(true);
}

void EvaluationScan::setSettings(std::shared_ptr<const ParamSet> params,
                                 std::set<std::string, std::less<>> skip)
{
    m_params = params ? std::move(params) : std::make_shared<ParamSet>();
    m_skip = std::move(skip);
    schedule(true);
}

void EvaluationScan::schedule(bool edit)
{
    if (m_spec.isEmpty() || !m_lut)
        return;
    if (!m_pending)
        m_requested = std::chrono::steady_clock::now();
    m_pending = true;
    m_pending_edit = m_pending_edit || edit;
    if (m_job)
        m_job->cancel = true; // stale: its frames ran with what the change replaced
    m_delay.start();
}

void EvaluationScan::evaluate()
{
    if (m_spec.isEmpty() || !m_lut)
        return;
    if (!m_pending)
        m_requested = std::chrono::steady_clock::now();
    m_pending = true;
    start();
}

void EvaluationScan::cancel()
{
    m_delay.stop();
    m_pending = false;
    m_pending_edit = false;
    if (m_job)
        m_job->cancel = true;
}

std::pair<std::size_t, std::size_t> EvaluationScan::progress() const
{
    if (!m_job)
        return {0, 0};
    return {m_job->done.load(), m_job->total.load()};
}

void EvaluationScan::start()
{
    m_delay.stop();
    if (m_job) {
        m_job->cancel = true; // onFinished() starts the pending one
        return;
    }
    if (!m_pending || m_spec.isEmpty() || !m_lut)
        return;
    if (!m_load_truth && m_scored_frames == 0) {
        m_pending = false;
        m_problem = m_truth ? tr("%1: no frame is done or has a reviewed kind").arg(m_truth_path)
                            : tr("No annotations for this stream (%1)").arg(m_truth_path);
        emit finished();
        return;
    }
    auto job = std::make_shared<Job>();
    job->stream = toLocalPath(m_spec);
    job->options = m_options;
    job->pipeline = &m_pipeline;
    job->lut = m_lut;
    job->params = m_params;
    job->skip.assign(m_skip.begin(), m_skip.end());
    job->threads = m_threads;
    job->truth = m_load_truth ? nullptr : m_truth;
    job->truth_path = toLocalPath(m_truth_path);
    job->truth_serial = m_truth_serial;
    job->edit = m_pending_edit;
    job->requested = m_requested;
    job->total = m_scored_frames;
    m_pending = false;
    m_pending_edit = false;
    m_job = job;
    m_watcher.setFuture(
        QtConcurrent::run(&m_pool, [job] { return std::make_shared<Outcome>(runJob(job)); }));
    m_poll.start();
    emit started();
}

void EvaluationScan::onFinished()
{
    const std::shared_ptr<Job> job = std::exchange(m_job, nullptr);
    m_poll.stop();
    if (!job)
        return;
    const std::shared_ptr<Outcome> out = m_watcher.result();
    // A run for another stream or other annotations (cancelled when they changed) is dropped.
    const bool current = job->truth_serial == m_truth_serial;
    if (current && out->loaded_truth) {
        m_truth = out->truth;
        m_load_truth = false;
        m_scored_frames = out->scored_frames;
    }
    if (current && !out->cancelled) {
        m_problem.clear();
        if (!out->error.empty()) {
            m_problem = QString::fromStdString(out->error);
        } else if (!out->report) {
            m_problem = m_truth
                            ? tr("%1: no frame is done or has a reviewed kind").arg(m_truth_path)
                            : tr("No annotations for this stream (%1)").arg(m_truth_path);
        } else {
            if (!job->edit)
                m_before.reset();
            else if (m_report && m_report_truth == job->truth_serial)
                m_before = m_report->scores;
            m_report = std::move(out->report);
            m_report_truth = job->truth_serial;
            m_last_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() -
                                                                  job->requested)
                            .count();
            m_failing.clear();
            const std::vector<const PerceptKind*>& kinds = scoredKinds();
            for (const FrameDisagreement& d : m_report->disagreements)
                m_failing.push_back({m_report->frame_index.at(d.frame), d});
            const auto rank = [&kinds](const PerceptKind* k) {
                return std::find(kinds.begin(), kinds.end(), k) - kinds.begin();
            };
            std::stable_sort(m_failing.begin(), m_failing.end(),
                             [&rank](const FailingFrame& a, const FailingFrame& b) {
                                 return a.index != b.index
                                            ? a.index < b.index
                                            : rank(a.disagreement.kind) < rank(b.disagreement.kind);
                             });
        }
    }
    emit finished();
    if (m_pending && !m_delay.isActive())
        start();
}

} // namespace fieldsight::ui
