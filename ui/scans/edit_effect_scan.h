// The effect of a LUT edit on the whole stream, for the window: after every edit (once the quiet
// time has passed) the core's EditEffectScanner runs every frame again on a background thread;
// its per-frame counts come back to the GUI thread as they are made.
#pragma once

#include "ui/scans/scan_gate.h"
#include "visioncore/framework/controller.h"
#include "visioncore/framework/param_set.h"
#include "visioncore/services/edit_effect.h"

#include <QObject>
#include <QString>
#include <QTimer>

#include <atomic>
#include <chrono>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <thread>
#include <vector>

namespace fieldsight::ui {

using fieldsight::FrameEffect;

class EditEffectScan : public QObject
{
    Q_OBJECT
public:
    explicit EditEffectScan(const Pipeline& pipeline = Pipeline::standard(),
                            QObject* parent = nullptr);
    /// Stops the scan (after the frame each thread is on).
    ~EditEffectScan() override;

    /// Worker threads of a scan (0: one per core).
    void setThreads(int threads) { m_scanner.setThreads(threads); }
    /// Quiet time after an edit before the scan starts, so a brush stroke scans once it pauses.
    void setDelay(int ms) { m_delay.setInterval(ms); }
    /// The gate each frame of a scan passes (null: none): the scan pauses while it is held. Set
    /// before the first stream (a scan running is stopped).
    void setGate(std::shared_ptr<ScanGate> gate);

    /// The stream to scan: a file stream (a camera or an empty spec clears it), opened with
    /// `options` (turned as the window shows it). Starts a first scan that records every frame's
    /// detections with `lut`, so the next edit has something to compare with.
    void setStream(const QString& spec, std::shared_ptr<const ColourLut> lut,
                   StreamOptions options = {});
    const StreamOptions& streamOptions() const { return m_options; }
    /// The pipeline settings the scans use; a change records every frame's detections again.
    void setSettings(std::shared_ptr<const ParamSet> params,
                     std::set<std::string, std::less<>> skip);
    /// Follow the light (as the window's View > Follow the light): each frame is run and
    /// counted through its light's map, as --adapt does; a switch is a change of the settings.
    void setFollowLight(bool on);
    bool followsLight() const { return m_follow_light; }
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
    /// The scan shown includes a change of the parameters or stage switches.
    bool showsSettingsChange() const { return m_shows_settings; }
    /// The scan shown is of Follow the light switched (showsFollowing(): on), nothing else.
    bool showsLightSwitch() const { return m_shows_light_switch; }
    /// The scan shown followed the light (followsLight() when it started).
    bool showsFollowing() const { return m_shows_following; }
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
    void stop();
    /// Empties the shown and the scanner's results, and starts a new generation.
    void clearResults();
    void start();
    /// A change of how every frame is run (the settings, following the light): all run again.
    void rerunForSettings();
    void collect(); ///< on the GUI thread

    EditEffectScanner m_scanner;
    QTimer m_delay;
    QTimer m_poll;
    std::thread m_thread; ///< runs m_scanner.run(); joined before the scanner is touched else
    std::shared_ptr<ScanGate> m_gate;
    std::atomic<bool> m_stopping{false}; ///< a scan waiting at the gate stops waiting
    QString m_spec;
    StreamOptions m_options;

    std::optional<EditEffectJob> m_pending;
    std::shared_ptr<const ColourLut> m_lut; ///< the newest table
    std::shared_ptr<const ParamSet> m_params = std::make_shared<ParamSet>();
    std::set<std::string, std::less<>> m_skip;
    bool m_follow_light = false;
    bool m_params_changed = false; ///< since the last job started
    bool m_light_switched = false; ///< since the last job started
    bool m_shows_light_switch = false;
    bool m_shows_following = false;
    bool m_settings_changed = false; ///< since the last job started
    bool m_shows_settings = false;

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
