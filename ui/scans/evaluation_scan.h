// The evaluation of the open stream against its annotations, for the window: the core's
// evaluateStream (the matching `fieldsight eval` uses) over every scored frame on a background
// thread, with progress and cancel. A table or settings change runs the scored frames again (a
// burst of edits once it pauses, a stale run cancelled), keeping the scores before the change so
// the window can say what it did; a change of the annotations alone is scored again with the
// detections already made, running only frames scored for the first time.
#pragma once

#include "ui/scans/scan_gate.h"
#include "visioncore/framework/controller.h"
#include "visioncore/framework/param_set.h"
#include "visioncore/services/evaluation.h"

#include <QFutureWatcher>
#include <QObject>
#include <QString>
#include <QThreadPool>
#include <QTimer>

#include <atomic>
#include <chrono>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace fieldsight::ui {

/// One frame and kind where the detections and the truth disagree, placed in the stream.
struct FailingFrame
{
    std::size_t index = 0; ///< in the stream
    FrameDisagreement disagreement;
};

class EvaluationScan : public QObject
{
    Q_OBJECT
public:
    using Detections = std::map<std::string, PerceptSet>;

    explicit EvaluationScan(const Pipeline& pipeline = Pipeline::standard(),
                            QObject* parent = nullptr);
    /// Cancels a run and waits for it (after the frame each thread is on).
    ~EvaluationScan() override;

    /// The pipeline it runs (its scored kinds are the scores' rows).
    const Pipeline& pipeline() const { return m_pipeline; }

    /// Worker threads of a run (0: one per core).
    void setThreads(int threads) { m_threads = threads; }
    /// Quiet time after a change before the run starts, so a brush stroke is scored once.
    void setDelay(int ms) { m_delay.setInterval(ms); }
    /// The gate each frame of a run passes (null: none): the run pauses while it is held.
    void setGate(std::shared_ptr<ScanGate> gate) { m_gate = std::move(gate); }

    /// The stream (a file stream; a camera or an empty spec clears it) turned by `options` as
    /// the window shows it, run with `lut` and the settings given last, against the annotations
    /// given last: evaluated at once.
    void setStream(const QString& spec, std::shared_ptr<const ColourLut> lut,
                   StreamOptions options = {});
    /// The annotations (`path` names them in messages; null: none): scored again once they pause.
    void setTruth(std::shared_ptr<const Annotations> truth, const QString& path);
    /// The table changed: the scored frames are run again once the edits pause.
    void setLut(std::shared_ptr<const ColourLut> lut);
    /// The pipeline settings changed: the same.
    void setSettings(std::shared_ptr<const ParamSet> params,
                     std::set<std::string, std::less<>> skip);
    /// Follow the light (as the window's View > Follow the light): the frames are run through
    /// their light's map, as --adapt does; a switch is a change of the settings.
    void setFollowLight(bool on);
    bool followsLight() const { return m_follow_light; }

    /// Evaluates now, every scored frame run again (a change waiting for its quiet time is
    /// included).
    void evaluate();
    /// Stops the running evaluation; the last finished one stays shown.
    void cancel();

    QString stream() const { return m_spec; }
    const StreamOptions& streamOptions() const { return m_options; }
    QString truthPath() const { return m_truth_path; }
    /// The annotations in use (null when there are none).
    const std::shared_ptr<const Annotations>& truth() const { return m_truth; }
    /// Why there is nothing to evaluate or the last run failed (empty when it did not).
    QString problem() const { return m_problem; }

    /// A run is going (from its start to the GUI thread hearing it ended).
    bool running() const { return m_job != nullptr; }
    /// A change waits for its quiet time, or for the stale run to stop.
    bool pending() const { return m_pending; }
    /// Frames run so far and frames to run, while running.
    std::pair<std::size_t, std::size_t> progress() const;

    /// The last finished evaluation (null before the first); its detections are detected().
    const EvalReport* report() const { return m_report ? &*m_report : nullptr; }
    /// Each scored frame's detections in the last report, by its name in the annotations.
    const Detections& detected() const;
    /// The scores before the change the last evaluation followed (a table or settings change):
    /// the detections from before it, on the annotations of the last report (an annotation edit
    /// landing meanwhile does not lose the change); null when it followed no such change.
    const EvaluationScores* before() const { return m_before ? &*m_before : nullptr; }
    /// The last report's disagreements, in stream order (then kind order).
    const std::vector<FailingFrame>& failing() const { return m_failing; }
    /// ms from the change to its evaluation's end (negative before the first).
    double lastRunMs() const { return m_last_ms; }
    /// Frames the pipeline ran for the last report (the others' detections were known).
    std::size_t lastFramesRun() const { return m_last_frames_run; }

signals:
    /// A run started.
    void started();
    /// More frames are done (about ten times a second while running).
    void progressed();
    /// A run finished (a report is in, or problem() says why not) or was cancelled.
    void finished();

private:
    struct Job;
    struct Outcome;
    static Outcome runJob(const std::shared_ptr<Job>& job);
    /// A change: evaluated once it has been quiet for the delay. A table or settings change
    /// (`edit`) makes the detections stale and cancels a running evaluation.
    void schedule(bool edit);
    void start();
    void onFinished();
    /// Says why there is nothing to evaluate, if so.
    bool nothingToScore();

    const Pipeline& m_pipeline;
    int m_threads = 0;
    std::shared_ptr<ScanGate> m_gate;
    QThreadPool m_pool;
    QTimer m_delay;
    QTimer m_poll;
    QString m_spec;
    StreamOptions m_options;
    std::shared_ptr<const ColourLut> m_lut;
    std::shared_ptr<const ParamSet> m_params = std::make_shared<ParamSet>();
    std::set<std::string, std::less<>> m_skip;
    bool m_follow_light = false;
    int m_settings_serial = 0; ///< which table, settings and stream detections were made with
    std::shared_ptr<const Annotations> m_truth;
    QString m_truth_path;
    int m_truth_serial = 0; ///< which annotations a report was made with

    bool m_pending = false;      ///< a change not yet evaluated
    bool m_pending_edit = false; ///< it includes a table or settings change
    bool m_rerun_all = false;    ///< evaluate() asked for every frame to be run again
    std::chrono::steady_clock::time_point m_requested; ///< of the first change pending
    std::shared_ptr<Job> m_job;                        ///< the running one
    QFutureWatcher<std::shared_ptr<Outcome>> m_watcher;

    std::optional<EvalReport> m_report;
    int m_report_truth = -1;
    /// The detections of the last report and the settings serial they were made with.
    std::shared_ptr<const Detections> m_detected;
    int m_detected_serial = -1;
    std::optional<EvaluationScores> m_before;
    /// The detections before a table or settings change not yet measured (null: none).
    std::shared_ptr<const Detections> m_baseline;
    std::vector<FailingFrame> m_failing;
    QString m_problem;
    double m_last_ms = -1;
    std::size_t m_last_frames_run = 0;
};

} // namespace fieldsight::ui
