#include "ui/scans/edit_effect_scan.h"

#include "ui/adapters/local_path.h"

#include <QMetaObject>

namespace fieldsight::ui {

EditEffectScan::EditEffectScan(const Pipeline& pipeline, QObject* parent)
    : QObject(parent), m_scanner(pipeline)
{
    m_delay.setSingleShot(true);
    m_delay.setInterval(150);
    connect(&m_delay, &QTimer::timeout, this, &EditEffectScan::start);
    m_poll.setInterval(100);
    connect(&m_poll, &QTimer::timeout, this, &EditEffectScan::collect);
}

EditEffectScan::~EditEffectScan()
{
    m_stopping = true;
    m_scanner.cancel();
    if (m_thread.joinable())
        m_thread.join();
}

void EditEffectScan::setStream(const QString& spec, std::shared_ptr<const ColourLut> lut,
                               StreamOptions options)
{
    m_delay.stop();
    stop();
    clearResults(); // a collect the old scan queued cannot bring its stream's effects back
    m_spec = spec.startsWith(QLatin1String("camera:")) ? QString() : spec;
    m_options = options;
    m_scanner.setStream(toLocalPath(m_spec), options);
    m_shows_edit = false;
    m_shows_settings = false;
    m_shows_light_switch = false;
    m_shows_following = m_follow_light;
    m_lut = std::move(lut);
    m_pending.reset();
    if (m_spec.isEmpty() || !m_lut)
        return;
    m_pending = EditEffectJob{nullptr, m_lut, m_params, m_skip};
    m_requested = std::chrono::steady_clock::now();
    start();
}

void EditEffectScan::setSettings(std::shared_ptr<const ParamSet> params,
                                 std::set<std::string, std::less<>> skip)
{
    m_params = params ? std::move(params) : std::make_shared<ParamSet>();
    m_skip = std::move(skip);
    m_params_changed = true;
    rerunForSettings();
}

void EditEffectScan::rerunForSettings()
{
    m_settings_changed = true;
    if (m_spec.isEmpty() || !m_lut)
        return;
    // Compared with each frame's result before the change (the same table), so the strip shows
    // the detections a parameter or a stage switch made appear or vanish.
    std::shared_ptr<const ColourLut> before = m_lut;
    if (m_pending && m_pending->before)
        before = m_pending->before;
    else if (!m_pending)
        m_requested = std::chrono::steady_clock::now();
    m_pending = EditEffectJob{std::move(before), m_lut, m_params, m_skip};
    m_delay.start();
}

void EditEffectScan::setFollowLight(bool on)
{
    if (on == m_follow_light)
        return;
    m_follow_light = on;
    m_light_switched = true;
    rerunForSettings(); // every frame read otherwise: none of their results holds
}

void EditEffectScan::edited(std::shared_ptr<const ColourLut> before,
                            std::shared_ptr<const ColourLut> after)
{
    if (!after)
        return;
    if (!before)
        before = m_lut;
    m_lut = std::move(after);
    if (m_spec.isEmpty())
        return;
    // Edits within the quiet time are scanned as one, from the first one's table.
    if (m_pending && m_pending->before)
        before = m_pending->before;
    else
        m_requested = std::chrono::steady_clock::now();
    m_pending = EditEffectJob{std::move(before), m_lut, m_params, m_skip};
    m_delay.start();
}

void EditEffectScan::setGate(std::shared_ptr<ScanGate> gate)
{
    stop(); // the scanner's gate is set only while no scan runs
    m_gate = std::move(gate);
    if (!m_gate) {
        m_scanner.setFrameGate({});
        return;
    }
    m_scanner.setFrameGate([gate = m_gate.get(), stopping = &m_stopping] { gate->pass(stopping); });
}

void EditEffectScan::stop()
{
    m_stopping = true;
    m_scanner.cancel();
    if (m_thread.joinable())
        m_thread.join();
    m_stopping = false;
    m_poll.stop();
    collect();
}

void EditEffectScan::start()
{
    stop();
    if (!m_pending)
        return;
    EditEffectJob job = std::move(*m_pending);
    m_pending.reset();
    job.rerun_all = m_settings_changed;
    if (m_follow_light)
        job.adapt = LightTrackingOptions{};
    m_shows_settings = m_settings_changed;
    m_shows_light_switch = m_light_switched && !m_params_changed;
    m_shows_following = m_follow_light;
    m_settings_changed = false;
    m_light_switched = false;
    m_params_changed = false;
    m_shows_edit = job.before != nullptr;
    clearResults(); // and forgets the cancel that stopped the last scan
    m_started = m_requested;
    const int generation = m_generation;
    m_thread = std::thread([this, generation, job = std::move(job)] {
        m_scanner.run(job);
        // Collect at once rather than at the next poll; a later scan ignores this one's call.
        QMetaObject::invokeMethod(
            this,
            [this, generation] {
                if (generation == m_generation)
                    collect();
            },
            Qt::QueuedConnection);
    });
    m_poll.start();
}

void EditEffectScan::clearResults()
{
    ++m_generation; // what the previous scan still queues is ignored
    m_scanner.clearResults();
    m_effects.clear();
    m_unreadable.clear();
    m_frames_done = 0;
    m_changed_cells = 0;
    m_last_scan_ms = -1;
    m_error.clear();
}

QString EditEffectScan::unreadableReason(std::size_t index) const
{
    const auto it = m_unreadable.find(index);
    return it == m_unreadable.end() ? QString() : it->second;
}

std::size_t EditEffectScan::firstUnreadable() const
{
    return m_unreadable.empty() ? m_effects.size() : m_unreadable.begin()->first;
}

void EditEffectScan::collect()
{
    EditEffectProgress progress = m_scanner.collect();
    m_effects = std::move(progress.effects);
    m_frames_done = progress.done;
    m_changed_cells = progress.changed_cells;
    if (progress.unreadable.size() != m_unreadable.size()) {
        m_unreadable.clear();
        for (const auto& [index, message] : progress.unreadable)
            m_unreadable.emplace(index, QString::fromStdString(message));
    }
    if (!progress.error.empty() && m_error.isEmpty())
        m_error = QString::fromStdString(progress.error);
    const bool ended = progress.finished;
    const std::chrono::steady_clock::time_point ended_at = progress.ended;
    if (!ended && !m_error.isEmpty() && m_thread.joinable()) {
        m_thread.join(); // it stopped on the error
        m_poll.stop();
    }
    if (ended) {
        m_last_scan_ms = std::chrono::duration<double, std::milli>(ended_at - m_started).count();
        if (m_thread.joinable())
            m_thread.join(); // it has set finished: only returning is left
        m_poll.stop();
    }
    emit updated();
    if (ended)
        emit finished();
}

} // namespace fieldsight::ui
