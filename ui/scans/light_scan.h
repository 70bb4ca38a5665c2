// "Follow the light" for the window: the core's trackLight over the whole stream on a background
// thread, from frame 0 in order, so a frame's light never depends on the order frames are
// browsed; started again when the table changes.
#pragma once

#include "ui/scans/scan_gate.h"
#include "visioncore/basics/colour_lut.h"
#include "visioncore/io/stream_reader.h"
#include "visioncore/services/light_tracking.h"

#include <QObject>
#include <QString>
#include <QTimer>

#include <atomic>
#include <memory>
#include <mutex>
#include <thread>

namespace fieldsight::ui {

class LightScan : public QObject
{
    Q_OBJECT
public:
    explicit LightScan(QObject* parent = nullptr);
    /// Stops the scan (after the frame it is on).
    ~LightScan() override;

    /// Off: no scan, and no track (the frames are read with the table as it is).
    void setEnabled(bool on);
    bool enabled() const { return m_enabled; }
    /// Quiet time after a change of the table before the scan starts again.
    void setDelay(int ms) { m_delay.setInterval(ms); }
    /// The gate each frame of a scan passes (null: none): the scan pauses while it is held. Set
    /// before the first stream.
    void setGate(std::shared_ptr<ScanGate> gate) { m_gate = std::move(gate); }
    /// The stream to follow (a camera or an empty spec clears it), turned by `options`, with
    /// the table `lut`.
    void setStream(const QString& spec, std::shared_ptr<const ColourLut> lut,
                   StreamOptions options = {});
    /// The table changed: the light is followed again from frame 0.
    void setLut(std::shared_ptr<const ColourLut> lut);

    /// The light of every frame, once a scan covered the stream (null before, or when off).
    const std::shared_ptr<const LightTrack>& track() const { return m_track; }
    std::size_t framesDone() const { return m_done.load(); }
    std::size_t frameCount() const { return m_total; }
    QString stream() const { return m_spec; }
    bool running() const { return m_thread.joinable() || m_delay.isActive(); }
    QString error() const { return m_error; }

signals:
    /// Following the light was turned on or off.
    void enabledChanged(bool on);
    /// The progress moved (about ten times a second while a scan runs).
    void progress();
    /// track() changed: a scan finished, or the track was dropped.
    void trackChanged();

private:
    void stop();
    void restart();
    void start();
    void poll(); ///< on the GUI thread

    bool m_enabled = false;
    QString m_spec;
    StreamOptions m_options;
    std::shared_ptr<const ColourLut> m_lut;
    std::shared_ptr<const LightTrack> m_track;
    QString m_error;
    QTimer m_delay;
    QTimer m_poll;
    std::shared_ptr<ScanGate> m_gate;

    std::thread m_thread;
    std::atomic<bool> m_cancel{false};
    std::atomic<std::size_t> m_done{0};
    std::size_t m_total = 0;
    std::mutex m_mutex; ///< guards the thread's result
    std::shared_ptr<const LightTrack> m_result;
    std::string m_result_error;
    bool m_finished = false;
};

} // namespace fieldsight::ui
