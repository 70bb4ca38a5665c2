// Pipeline > Fit to annotations (issue 34): the parameter search `fieldsight tune` runs, over the
// stream shown with the table being edited, the parameters in use and the annotations as the
// annotations document holds them (unsaved edits too), in the background with progress and a
// Cancel that keeps the best so far. The result is shown first (FitResultDialog: before/after
// per class on the fit and held-out frames, the parameters changed); Apply puts the tuned
// parameters in use as one undo step of the pipeline settings, which Pipeline > Save parameters
// to the stream then writes. A stream without done annotations gets a message instead of a run.
#pragma once

#include "ui/actions/menus.h"
#include "ui/scans/tune_run.h"

#include <QObject>
#include <QPointer>
#include <QString>

#include <memory>

namespace fieldsight::ui {

class FitResultDialog;

class FitActions : public QObject
{
    Q_OBJECT
public:
    /// The command line's default (`tune --budget`), so both search alike.
    static constexpr int kDefaultBudget = kDefaultTuneBudget;

    explicit FitActions(const MenuTarget& target);

    /// Pipeline > Fit to annotations: asks the budget (starting from the last one), then
    /// start(). Nothing while a search runs.
    void fitToAnnotations();
    /// Starts the search with `budget` evaluations; false, with a message in the window saying
    /// why, when there is no stream of files or no annotated frame to fit.
    bool start(int budget);
    bool running() const { return m_run->running(); }
    void cancel() { m_run->cancel(); }
    /// The evaluations the last search was given (remembered between sessions by the window).
    int budget() const { return m_budget; }
    void setBudget(int budget);
    /// The run, for tests that give it a search of their own.
    TuneRun& run() { return *m_run; }
    /// The result dialog shown last (null once it closed).
    FitResultDialog* resultDialog() const;
    /// Puts `result`'s parameters in use as one undo step (those equal to their default as
    /// defaults, not changes); false (a message says why) when the pipeline refuses them.
    bool apply(const TuneResult& result);

signals:
    /// A search ended: its result is shown (`shown`), or it failed or was dropped (a message
    /// says so).
    void finished(bool shown);

private:
    /// Whether there is a stream of files with done or reviewed annotations; else a message
    /// says what to do.
    bool ready();
    void onFinished(const Result<TuneResult>& result);

    MenuTarget m_target;
    TuneRun* m_run = nullptr;
    int m_budget = kDefaultBudget;
    bool m_stale = false; ///< the stream changed while the search read it
    /// The settings and table the search started from: another in use when it ends is noted.
    std::shared_ptr<const ParamSet> m_start_params;
    std::shared_ptr<const ColourLut> m_start_lut;
    QPointer<FitResultDialog> m_dialog;
};

} // namespace fieldsight::ui
