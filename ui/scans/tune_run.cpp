#include "ui/scans/tune_run.h"

#include <QtConcurrent/QtConcurrentRun>

#include <exception>
#include <new>

namespace fieldsight::ui {

namespace {

/// The search yields to the window and its frame worker (its workers, started from the calling
/// thread, inherit the priority).
constexpr int kSearchNiceness = 5;

} // namespace

TuneRun::TuneRun(QObject* parent) : QObject(parent), m_tuner(&tuneParams)
{
    m_pool.setMaxThreadCount(1);
    connect(&m_watcher, &QFutureWatcher<Result<TuneResult>>::finished, this, [this] {
        Result<TuneResult> result = m_watcher.result();
        // A cancel that came after the last evaluation still says the search was cut short.
        if (result && m_cancel)
            result.value().cancelled = true;
        emit finished(result);
    });
}

TuneRun::~TuneRun()
{
    m_cancel = true;
    m_watcher.waitForFinished();
}

bool TuneRun::start(std::shared_ptr<StreamInput> input, Annotations truth, std::string truth_path,
                    TuneOptions options)
{
    if (running() || !input || !input->reader)
        return false;
    m_cancel = false;
    m_done = 0;
    m_budget = std::size_t(std::max(0, options.budget));
    m_best = -1;
    options.cancel = &m_cancel;
    options.progress = [this](const TuneProgress& p) {
        m_done = std::size_t(std::max(0, p.evaluations));
        m_budget = std::size_t(std::max(0, p.budget));
        m_best = p.best_fit;
    };
    m_watcher.setFuture(QtConcurrent::run(
        &m_pool,
        [input = std::move(input), truth = std::move(truth), truth_path = std::move(truth_path),
         options = std::move(options), tuner = m_tuner]() -> Result<TuneResult> {
            try {
                lowerThreadPriority(kSearchNiceness);
                return tuner(*input, truth, truth_path, options);
            } catch (const std::bad_alloc&) {
                return Error{input->stream + ": not enough memory to fit the parameters"};
            } catch (const std::exception& e) {
                return Error{input->stream + ": " + e.what()};
            }
        }));
    return true;
}

} // namespace fieldsight::ui
