// The automatic table (lut_auto.h) run for the window on a thread of its own: it reads the frames
// of the stream shown (another reader of it, turned as shown) with progress and cancel, and hands
// the result back on the GUI thread; what becomes of it is the caller's (CalibrateActions).
#pragma once

#include "visioncore/services/lut_auto.h"

#include <QFutureWatcher>
#include <QObject>

#include <atomic>
#include <functional>
#include <memory>
#include <optional>

namespace fieldsight::ui {

class AutoLutRun : public QObject
{
    Q_OBJECT
public:
    /// What makes the table: buildAutoLut, unless replaced (a test gives one it controls).
    using Builder = std::function<Result<AutoLut>(StreamReader&, const AutoLutOptions&,
                                                  const AutoLutProgress&)>;
    using Opener = std::function<Result<std::unique_ptr<StreamReader>>()>;

    explicit AutoLutRun(QObject* parent = nullptr);
    /// Cancels a run and waits for its thread.
    ~AutoLutRun() override;

    void setBuilder(Builder builder) { m_builder = std::move(builder); }
    /// Starts a run over the frames `open` gives (called on the run's thread); false while one
    /// runs.
    bool start(Opener open, AutoLutOptions options = {});
    bool running() const { return m_watcher.isRunning(); }
    /// Asks the run to stop after the frame it is reading (its table is then not to be used).
    void cancel() { m_cancel = true; }
    /// Frames read and frames to read, while it runs.
    std::pair<std::size_t, std::size_t> progress() const { return {m_done, m_total}; }

signals:
    /// The run ended: its table (`cancelled` set when it was cancelled), or why it could not be
    /// made.
    void finished(const fieldsight::Result<fieldsight::AutoLut>& result);

private:
    Builder m_builder;
    QFutureWatcher<Result<AutoLut>> m_watcher;
    std::atomic<bool> m_cancel{false};
    std::atomic<std::size_t> m_done{0};
    std::atomic<std::size_t> m_total{0};
};

} // namespace fieldsight::ui
