#include "ui/scans/evaluation_scan.h"

#include "ui/adapters/local_path.h"

#include <QtConcurrent/QtConcurrentRun>

#include <algorithm>
#include <exception>
#include <new>

namespace fieldsight::ui {

namespace {

/// The evaluation's threads yield to the window and its frame worker, but less than the
/// whole-stream scan's: its few frames give the scores of an edit before the scan's strip is full.
constexpr int kEvaluationNiceness = 5;

/// The frames of `truth` with something to score by `pipeline`'s kinds.
std::size_t scoredCount(const Annotations* truth, const Pipeline& pipeline)
{
    const std::vector<const PerceptKind*> kinds = scoredKinds(pipeline.perceptKinds());
    return truth ? std::size_t(
                       std::count_if(truth->frames.begin(), truth->frames.end(),
                                     [&kinds](const auto& f) { return isScored(f.second, kinds); }))
                 : 0;
}

} // namespace

struct EvaluationScan::Job
{
    std::string stream;
    StreamOptions options;
    const Pipeline* pipeline = nullptr;
    std::shared_ptr<const ColourLut> lut;
    std::shared_ptr<const ParamSet> params;
    std::vector<std::string> skip;
    bool follow_light = false;
    int threads = 0;
    std::shared_ptr<ScanGate> gate; ///< passed before each frame (null: none)
    std::shared_ptr<const Annotations> truth;
    std::string truth_path;
    int truth_serial = 0;
    int settings_serial = 0;
    /// Detections made with this job's table and settings (not run again).
    std::shared_ptr<const Detections> known;
    /// Detections made before the table or settings change this job follows (null: it follows
    /// none): the scores before the change are theirs, on this job's annotations.
    std::shared_ptr<const Detections> baseline;
    std::chrono::steady_clock::time_point requested;

    std::atomic<bool> cancel{false};
    std::atomic<std::size_t> done{0};
    std::atomic<std::size_t> total{0};
};

struct EvaluationScan::Outcome
{
    std::optional<EvalReport> report;
    /// The job's annotations scored with its baseline's detections (a frame the baseline lacks,
    /// newly scored, with the report's: unchanged by the edit).
    std::optional<EvaluationScores> before;
    std::size_t frames_run = 0;
    std::string error;
    bool cancelled = false;
};

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
    lowerThreadPriority(kEvaluationNiceness); // from the start: following the light reads first
    Outcome out;
    try {
        auto reader = openStream(job->stream, job->options);
        if (!reader) {
            out.error = reader.error().message;
            return out;
        }
        StreamInput input;
        input.stream = job->stream;
        input.reader = std::move(reader).value();
        input.pipeline = job->pipeline;
        input.lut = job->lut;
        input.params = *job->params;
        input.skip = job->skip;
        if (job->follow_light)
            input.adapt = LightTrackingOptions{};
        RunHooks hooks;
        hooks.cancel = &job->cancel;
        hooks.progress = [&job](std::size_t done, std::size_t total) {
            job->done = done;
            job->total = total;
        };
        if (job->gate)
            hooks.pause = [&job] { job->gate->pass(&job->cancel); };
        hooks.prefilter = [](std::size_t, const Frame&, const ColourLut&) {
            lowerThreadPriority(kEvaluationNiceness);
            return true;
        };
        static const Detections none;
        auto report = evaluateStream(input, *job->truth, job->truth_path, job->threads, hooks,
                                     job->known ? *job->known : none, &out.frames_run);
        if (job->cancel)
            out.cancelled = true;
        else if (!report)
            out.error = report.error().message;
        else
            out.report = std::move(report).value();
        if (out.report && job->baseline) {
            Detections before = out.report->detected;
            for (auto& [name, percepts] : before)
                if (const auto b = job->baseline->find(name); b != job->baseline->end())
                    percepts = b->second;
            out.before =
                fieldsight::evaluate(before, *job->truth, input.info().width, input.info().height,
                                     scoredKinds(job->pipeline->perceptKinds()));
        }
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
    ++m_settings_serial;
    ++m_truth_serial;
    m_report.reset();
    m_detected.reset();
    m_before.reset();
    m_baseline.reset();
    m_failing.clear();
    m_problem.clear();
    m_pending = !m_spec.isEmpty() && m_lut;
    m_pending_edit = false;
    m_requested = std::chrono::steady_clock::now();
    emit finished(); // what was shown is gone
    start();
}

void EvaluationScan::setTruth(std::shared_ptr<const Annotations> truth, const QString& path)
{
    m_truth = std::move(truth);
    m_truth_path = path;
    ++m_truth_serial;
    schedule(false);
}

void EvaluationScan::setLut(std::shared_ptr<const ColourLut> lut)
{
    if (!lut || lut == m_lut)
        return;
    m_lut = std::move(lut);
    ++m_settings_serial;
    schedule(true);
}

void EvaluationScan::setSettings(std::shared_ptr<const ParamSet> params,
                                 std::set<std::string, std::less<>> skip)
{
    m_params = params ? std::move(params) : std::make_shared<ParamSet>();
    m_skip = std::move(skip);
    ++m_settings_serial;
    schedule(true);
}

void EvaluationScan::setFollowLight(bool on)
{
    if (on == m_follow_light)
        return;
    m_follow_light = on;
    ++m_settings_serial;
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
    // What the change is measured against: the detections before the first change of a burst,
    // kept until a report on the changed table and settings is in (whatever the annotations
    // became meanwhile).
    if (edit && !m_baseline)
        m_baseline = m_detected;
    // Stale: its frames ran with what the change replaced. A run under annotations that changed
    // goes on: its detections still hold.
    if (m_job && edit)
        m_job->cancel = true;
    m_delay.start();
}

void EvaluationScan::evaluate()
{
    if (m_spec.isEmpty() || !m_lut)
        return;
    if (!m_pending)
        m_requested = std::chrono::steady_clock::now();
    m_pending = true;
    m_rerun_all = true;
    start();
}

void EvaluationScan::cancel()
{
    m_delay.stop();
    m_pending = false;
    m_pending_edit = false;
    m_rerun_all = false;
    if (m_job)
        m_job->cancel = true;
}

std::pair<std::size_t, std::size_t> EvaluationScan::progress() const
{
    if (!m_job)
        return {0, 0};
    return {m_job->done.load(), m_job->total.load()};
}

const EvaluationScan::Detections& EvaluationScan::detected() const
{
    static const Detections none;
    return m_detected ? *m_detected : none;
}

bool EvaluationScan::nothingToScore()
{
    if (scoredCount(m_truth.get(), m_pipeline) > 0)
        return false;
    m_report.reset();
    m_detected.reset();
    m_before.reset();
    m_baseline.reset();
    m_failing.clear();
    m_problem = m_truth && !m_truth->frames.empty()
                    ? tr("Nothing to score: no annotated frame is marked done or has a reviewed "
                         "kind")
                    : tr("No annotations for this stream yet: annotate frames and mark them done "
                         "to score the detectors");
    return true;
}

void EvaluationScan::start()
{
    m_delay.stop();
    if (m_job) {
        if (m_pending_edit || m_rerun_all)
            m_job->cancel = true; // onFinished() starts the pending one
        return;
    }
    if (!m_pending || m_spec.isEmpty() || !m_lut)
        return;
    m_pending = false;
    if (nothingToScore()) {
        m_pending_edit = false;
        m_rerun_all = false;
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
    job->follow_light = m_follow_light;
    job->threads = m_threads;
    job->gate = m_gate;
    job->truth = m_truth;
    job->truth_path = toLocalPath(m_truth_path);
    job->truth_serial = m_truth_serial;
    job->settings_serial = m_settings_serial;
    if (!m_rerun_all && m_detected_serial == m_settings_serial)
        job->known = m_detected;
    job->baseline = m_baseline;
    job->requested = m_requested;
    job->total = scoredCount(m_truth.get(), m_pipeline);
    m_pending_edit = false;
    m_rerun_all = false;
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
    const bool same_settings = job->settings_serial == m_settings_serial;
    // Detections made with the table and settings in use serve the next run, whatever the
    // annotations became meanwhile.
    if (out->report && same_settings) {
        m_detected = std::make_shared<const Detections>(std::move(out->report->detected));
        m_detected_serial = job->settings_serial;
    }
    if (same_settings && job->truth_serial == m_truth_serial && !out->cancelled) {
        m_problem.clear();
        if (!out->error.empty()) {
            m_problem = QString::fromStdString(out->error);
        } else if (out->report) {
            m_before = out->before;
            m_baseline.reset(); // the change is measured
            m_report = std::move(out->report);
            m_report_truth = job->truth_serial;
            m_last_frames_run = out->frames_run;
            m_last_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() -
                                                                  job->requested)
                            .count();
            m_failing.clear();
            const std::vector<const PerceptKind*> kinds = scoredKinds(m_pipeline.perceptKinds());
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
