// The window's light scan: one thread, one reader of its own, trackLight from frame 0.
#include "ui/scans/light_scan.h"

#include "ui/adapters/local_path.h"
#include "visioncore/services/stream_runner.h"

namespace fieldsight::ui {

LightScan::LightScan(QObject* parent) : QObject(parent)
{
    m_delay.setSingleShot(true);
    m_delay.setInterval(300);
    connect(&m_delay, &QTimer::timeout, this, &LightScan::start);
    m_poll.setInterval(100);
    connect(&m_poll, &QTimer::timeout, this, &LightScan::poll);
}

LightScan::~LightScan()
{
    stop();
}

void LightScan::setEnabled(bool on)
{
    if (on == m_enabled)
        return;
    m_enabled = on;
    restart();
    emit enabledChanged(on);
}

void LightScan::setStream(const QString& spec, std::shared_ptr<const ColourLut> lut,
                          StreamOptions options)
{
    m_spec = spec;
    m_options = options;
    m_lut = std::move(lut);
    restart();
}

void LightScan::setLut(std::shared_ptr<const ColourLut> lut)
{
    if (lut == m_lut)
        return;
    m_lut = std::move(lut);
    restart();
}

void LightScan::stop()
{
    m_delay.stop();
    m_cancel = true;
    if (m_thread.joinable())
        m_thread.join();
    m_poll.stop();
    m_cancel = false;
    m_finished = false;
    m_result.reset();
}

void LightScan::restart()
{
    stop();
    m_error.clear();
    m_done = 0;
    m_total = 0;
    if (m_track) {
        m_track.reset();
        emit trackChanged();
    }
    if (m_enabled && !m_spec.isEmpty() && m_lut)
        m_delay.start();
}

void LightScan::start()
{
    if (m_thread.joinable())
        return;
    auto reader = openStream(toLocalPath(m_spec), m_options);
    if (!reader) {
        m_error = QString::fromStdString(reader.error().message);
        emit progress();
        return;
    }
    if (reader.value()->info().kind == StreamKind::Camera)
        return; // a live camera has no frames to follow in advance
    m_total = reader.value()->info().frame_count;
    m_thread = std::thread([this, reader = std::move(reader).value(), lut = m_lut, gate = m_gate] {
        lowerThreadPriority();
        std::string error;
        std::shared_ptr<const LightTrack> track;
        try {
            auto done = trackLight(
                *reader, lut, reader->info().frame_count, {},
                [this, &gate](std::size_t n, std::size_t) {
                    m_done = n;
                    if (gate)
                        gate->pass(&m_cancel); // before the next frame
                },
                &m_cancel);
            if (!done.cancelled)
                track = std::make_shared<const LightTrack>(std::move(done));
        } catch (const std::exception& e) {
            error = e.what();
        }
        std::lock_guard lock(m_mutex);
        m_result = std::move(track);
        m_result_error = std::move(error);
        m_finished = true;
    });
    m_poll.start();
}

void LightScan::poll()
{
    bool finished = false;
    {
        std::lock_guard lock(m_mutex);
        finished = m_finished;
    }
    if (!finished) {
        emit progress();
        return;
    }
    m_thread.join();
    m_poll.stop();
    m_finished = false;
    m_track = std::move(m_result);
    m_error = QString::fromStdString(m_result_error);
    emit progress();
    emit trackChanged();
}

} // namespace fieldsight::ui
