// The effect of a LUT edit on the whole stream: after every edit, every frame is run again in the
// background with the new table; per frame, how many pixels changed class and which detections
// appeared or vanished (by the eval matching rules) against that frame's previous result.
#pragma once

#include "visioncore/framework/controller.h"
#include "visioncore/framework/param_set.h"
#include "visioncore/services/evaluation.h"
#include "visioncore/services/stream_runner.h"

#include <QObject>
#include <QString>
#include <QTimer>

#include <atomic>
#include <chrono>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <set>
#include <string>
#include <thread>
#include <vector>

namespace fieldsight::ui {

/// One frame's effect of the last edit.
struct FrameEffect
{
    bool done = false;                ///< scanned since the last edit
    bool unreadable = false;          ///< the frame could not be read (unreadableReason says why)
    std::uint32_t changed_pixels = 0; ///< pixels whose class the edit changed
    std::uint32_t unclassified = 0;   ///< pixels the current table leaves unclassified
    std::uint32_t pixels = 0;
    DetectionDelta delta; ///< against the frame's previous result (none on the first scan)
};

class EditEffectScan : public QObject
{
    Q_OBJECT
public:
    explicit EditEffectScan(const Pipeline& pipeline = Pipeline::standard(),
                            QObject* parent = nullptr);
    /// Stops the scan (after the frame each thread is on).
    ~EditEffectScan() override;

    /// Worker threads of a scan (0: one per core).
    void setThreads(int threads) { m_threads = threads; }
    /// Quiet time after an edit before the scan starts, so a brush stroke scans once it pauses.
    void setDelay(int ms) { m_delay.setInterval(ms); }

    /// The stream to scan: a file stream (a camera or an empty spec clears it). Starts a first
    /// scan that records every frame's detections with `lut`, so the next edit has something to
    /// compare with.
    void setStream(const QString& spec, std::shared_ptr<const ColourLut> lut);
    /// The pipeline settings the scans use; a change records every frame's detections again.
    void setSettings(std::shared_ptr<const ParamSet> params,
                     std::set<std::string, std::less<>> skip);
    QString stream() const { return m_spec; }
    /// The table went from `before` (null: the last table given) to `after`: every frame is
    /// scanned again.
    void edited(std::shared_ptr<const ColourLut> before, std::shared_ptr<const ColourLut> after);

    /// Per frame, as far as the scan has got (updated about ten times a second while it runs).
    const std::vector<FrameEffect>& effects() const { return m_effects; }
    std::size_t framesDone() const { return m_frames_done; }
    bool running() const { return m_thread.joinable() || m_delay.isActive(); }
    /// The cells the last edit changed.
    std::size_t changedCells() const { return m_changed_cells; }
    /// Whether the effects describe an edit (false after the first scan of a stream).
    bool showsEdit() const { return m_shows_edit; }
    /// ms from the edit (or the settings change) to the scan's last frame (negative while none
    /// has finished).
    double lastScanMs() const { return m_last_scan_ms; }
    QString error() const { return m_error; }
    /// Frames the scan could not read (a damaged file): the scan goes on past them.
    std::size_t unreadableFrames() const { return m_unreadable.size(); }
    /// Why frame `index` could not be read (empty when it could).
    QString unreadableReason(std::size_t index) const;
    /// The first frame that could not be read (the frame count when every frame could).
    std::size_t firstUnreadable() const;

signals:
    /// New per-frame effects are in.
    void updated();
    /// A scan covered every frame.
    void finished();

private:
    struct Job
    {
        std::shared_ptr<const ColourLut> before; ///< null: record only
        std::shared_ptr<const ColourLut> after;
        std::shared_ptr<const ParamSet> params;
        std::set<std::string, std::less<>> skip;
        bool rerun_all = false; ///< the settings changed: no earlier result still holds
    };
    struct Shared
    {
        std::mutex mutex;
        std::vector<FrameEffect> effects;
        std::size_t done = 0;
        std::size_t changed_cells = 0;
        bool finished = false; ///< set once by a scan that covered every frame
        std::chrono::steady_clock::time_point ended;
        std::string error;
        std::map<std::size_t, std::string> unreadable; ///< frame index: the reader's message
    };

    void stop();
    /// Empties the shown and the shared results, and starts a new generation.
    void clearResults();
    void start();
    void scan(Job job); ///< on the scan thread
    void collect();     ///< on the GUI thread

    const Pipeline& m_pipeline;
    int m_threads = 0;
    QTimer m_delay;
    QTimer m_poll;
    std::thread m_thread;
    std::atomic<bool> m_cancel{false};
    std::shared_ptr<Shared> m_shared = std::make_shared<Shared>();

    // Touched by the scan thread only while it runs (the GUI thread joins it first).
    QString m_spec;
    std::optional<StreamInput> m_input;
    std::vector<std::optional<PerceptSet>> m_previous;            ///< each frame's last result
    std::vector<std::shared_ptr<const ColourLut>> m_previous_lut; ///< the table it was run with

    std::optional<Job> m_pending;
    std::shared_ptr<const ColourLut> m_lut; ///< the newest table
    std::shared_ptr<const ParamSet> m_params = std::make_shared<ParamSet>();
    std::set<std::string, std::less<>> m_skip;
    bool m_settings_changed = false; ///< since the last job started

    std::vector<FrameEffect> m_effects;
    std::size_t m_frames_done = 0;
    std::size_t m_changed_cells = 0;
    bool m_shows_edit = false;
    double m_last_scan_ms = -1;
    std::chrono::steady_clock::time_point m_requested; ///< of the pending job
    std::chrono::steady_clock::time_point m_started;   ///< of the running job
    int m_generation = 0;
    QString m_error;
    std::map<std::size_t, QString> m_unreadable;
};

} // namespace fieldsight::ui
