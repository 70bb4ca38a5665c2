// The parameter search (param_tuning.h, what `fieldsight tune` runs) for the window, on a thread
// of its own: it fits the pipeline's parameters to a copy of the annotations over another reader
// of the stream shown, with progress (evaluations done, the best fit score so far) and a cancel
// that keeps the best found so far, and hands the result back on the GUI thread; what becomes of
// it is the caller's (FitActions).
#pragma once

#include "visioncore/services/param_tuning.h"

#include <QFutureWatcher>
#include <QObject>
#include <QThreadPool>

#include <atomic>
#include <functional>
#include <memory>
#include <string>

namespace fieldsight::ui {

class TuneRun : public QObject
{
    Q_OBJECT
public:
    /// What searches: tuneParams, unless replaced (a test gives one it controls).
    using Tuner = std::function<Result<TuneResult>(StreamInput&, const Annotations&,
                                                   const std::string&, const TuneOptions&)>;

    explicit TuneRun(QObject* parent = nullptr);
    /// Cancels a run and waits for its thread.
    ~TuneRun() override;

    void setTuner(Tuner tuner) { m_tuner = std::move(tuner); }
    /// Starts the search over `input` (its table, parameters and skipped stages are the start)
    /// against `truth` (a copy: later edits do not reach the run); false while one runs.
    /// `options`' progress and cancel are the run's own.
    bool start(std::shared_ptr<StreamInput> input, Annotations truth, std::string truth_path,
               TuneOptions options);
    bool running() const { return m_watcher.isRunning(); }
    /// Asks the search to stop; it ends with the best parameters found so far.
    void cancel() { m_cancel = true; }
    bool cancelling() const { return m_cancel; }
    /// Evaluations done and the budget, while it runs.
    std::pair<std::size_t, std::size_t> progress() const { return {m_done, m_budget}; }
    /// The best fit score so far (negative before the first evaluation).
    double bestFit() const { return m_best; }

signals:
    /// The search ended: its result (`cancelled` set when it was cut short: the best so far),
    /// or why it could not run.
    void finished(const fieldsight::Result<fieldsight::TuneResult>& result);

private:
    Tuner m_tuner;
    /// A pool of its own: the search's calling thread lowers its priority (and its workers
    /// inherit it), which must not stay with a thread of the global pool.
    QThreadPool m_pool;
    QFutureWatcher<Result<TuneResult>> m_watcher;
    std::atomic<bool> m_cancel{false};
    std::atomic<std::size_t> m_done{0};
    std::atomic<std::size_t> m_budget{0};
    std::atomic<double> m_best{-1};
};

} // namespace fieldsight::ui
