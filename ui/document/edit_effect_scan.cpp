#include "ui/document/edit_effect_scan.h"

#include "ui/adapters/local_path.h"

#include "visioncore/services/lut_compare.h"

#include <QMetaObject>

#ifdef __linux__
#include <sys/resource.h>
#include <sys/syscall.h>
#include <unistd.h>
#endif

namespace fieldsight::ui {

namespace {

/// The scan yields to the window and its frame worker: its threads run at a lower priority
/// (nice 10 on Linux; the threads end with the scan).
void lowerThreadPriority()
{
#ifdef __linux__
    thread_local bool lowered = false;
    if (!lowered) {
        lowered = true;
        setpriority(PRIO_PROCESS, id_t(syscall(SYS_gettid)), 10);
    }
#endif
}

} // namespace

EditEffectScan::EditEffectScan(const Pipeline& pipeline, QObject* parent)
    : QObject(parent), m_pipeline(pipeline)
{
    m_delay.setSingleShot(true);
    m_delay.setInterval(150);
    connect(&m_delay, &QTimer::timeout, this, &EditEffectScan::start);
    m_poll.setInterval(100);
    connect(&m_poll, &QTimer::timeout, this, &EditEffectScan::collect);
}

EditEffectScan::~EditEffectScan()
{
    m_cancel = true;
    if (m_thread.joinable())
        m_thread.join();
}

void EditEffectScan::setStream(const QString& spec, std::shared_ptr<const ColourLut> lut)
{
    m_delay.stop();
    stop();
    clearResults(); // a collect the old scan queued cannot bring its stream's effects back
    m_spec = spec.startsWith(QLatin1String("camera:")) ? QString() : spec;
    m_input.reset();
    m_previous.clear();
    m_shows_edit = false;
    m_lut = std::move(lut);
    m_pending.reset();
    if (m_spec.isEmpty() || !m_lut)
        return;
    m_pending = Job{nullptr, m_lut, m_params, m_skip};
    m_requested = std::chrono::steady_clock::now();
    start();
}

void EditEffectScan::setSettings(std::shared_ptr<const ParamSet> params,
                                 std::set<std::string, std::less<>> skip)
{
    m_params = params ? std::move(params) : std::make_shared<ParamSet>();
    m_skip = std::move(skip);
    m_settings_changed = true;
    if (m_spec.isEmpty() || !m_lut)
        return;
    if (!m_pending)
        m_requested = std::chrono::steady_clock::now();
    m_pending = Job{nullptr, m_lut, m_params, m_skip};
    m_delay.start();
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
    m_pending = Job{std::move(before), m_lut, m_params, m_skip};
    m_delay.start();
}

void EditEffectScan::stop()
{
    m_cancel = true;
    if (m_thread.joinable())
        m_thread.join();
    m_poll.stop();
    collect();
}

void EditEffectScan::start()
{
    stop();
    if (!m_pending)
        return;
    Job job = std::move(*m_pending);
    m_pending.reset();
    job.rerun_all = m_settings_changed;
    m_settings_changed = false;
    m_shows_edit = job.before != nullptr;
    clearResults();
    m_cancel = false;
    m_started = m_requested;
    const int generation = m_generation;
    m_thread = std::thread([this, generation, job = std::move(job)]() mutable {
        scan(std::move(job));
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

void EditEffectScan::scan(Job job)
{
    Shared& shared = *m_shared;
    auto fail = [&](std::string message) {
        std::lock_guard lock(shared.mutex);
        shared.error = std::move(message);
    };
    try {
        if (!m_input) {
            auto reader = openStream(toLocalPath(m_spec));
            if (!reader)
                return fail(reader.error().message);
            StreamInput input;
            input.stream = toLocalPath(m_spec);
            input.reader = std::move(reader).value();
            input.pipeline = &m_pipeline;
            m_input.emplace(std::move(input));
            m_previous.assign(m_input->info().frame_count, std::nullopt);
            m_previous_lut.assign(m_input->info().frame_count, nullptr);
        }
        StreamInput& input = *m_input;
        input.lut = job.after;
        input.params = *job.params;
        input.skip.assign(job.skip.begin(), job.skip.end());
        const CellMask mask =
            job.before ? CellMask::differences(*job.before, *job.after) : CellMask();
        const PixelTallier tally_pixels(*job.after, mask);
        const std::size_t frames = input.info().frame_count;
        const int width = input.info().width;
        const int height = input.info().height;
        {
            std::lock_guard lock(shared.mutex);
            shared.effects.assign(frames, FrameEffect{});
            shared.changed_cells = mask.count();
        }
        const auto record = [&](std::size_t index, const PixelTally& tally,
                                const DetectionDelta& delta) {
            FrameEffect effect;
            effect.done = true;
            effect.changed_pixels = std::uint32_t(tally.in_mask);
            effect.unclassified = std::uint32_t(tally.unclassified);
            effect.pixels = std::uint32_t(tally.pixels);
            effect.delta = delta;
            std::lock_guard lock(shared.mutex);
            shared.effects[index] = effect;
            ++shared.done;
        };
        std::vector<PixelTally> tallies(frames);
        RunHooks hooks;
        hooks.cancel = &m_cancel;
        // A frame none of whose pixels changed class keeps its result: the pipeline runs only
        // where the edit shows (or everywhere when the settings changed).
        hooks.prefilter = [&](std::size_t index, const Frame& frame) {
            lowerThreadPriority();
            tallies[index] = tally_pixels(frame.ycbcr);
            const bool unchanged = job.before && !job.rerun_all && tallies[index].in_mask == 0 &&
                                   m_previous[index] && m_previous_lut[index] == job.before;
            if (!unchanged)
                return true;
            m_previous_lut[index] = job.after;
            record(index, tallies[index], {});
            return false;
        };
        // A damaged frame is marked and passed: the rest of the stream still shows the edit.
        hooks.on_unreadable = [&](std::size_t index, const std::string& message) {
            FrameEffect effect;
            effect.done = true;
            effect.unreadable = true;
            std::lock_guard lock(shared.mutex);
            shared.effects[index] = effect;
            shared.unreadable[index] = message;
            ++shared.done;
        };
        hooks.on_frame = [&](const FrameResult& result, const Frame&,
                             const DebugCanvas&) -> Status {
            const std::size_t index = result.index;
            DetectionDelta delta;
            std::optional<PerceptSet>& previous = m_previous[index];
            if (job.before && previous)
                delta = compareDetections(*previous, result.percepts, width, height);
            previous = result.percepts; // one frame per index: no other thread writes it
            m_previous_lut[index] = job.after;
            record(index, tallies[index], delta);
            return {};
        };
        auto run = runStream(input, firstFrames(frames), m_threads, hooks);
        if (!run)
            return fail(run.error().message);
        std::lock_guard lock(shared.mutex);
        shared.finished = !run.value().cancelled;
        shared.ended = std::chrono::steady_clock::now();
    } catch (const std::exception& e) {
        fail(e.what());
    }
}

void EditEffectScan::clearResults()
{
    ++m_generation; // what the previous scan still queues is ignored
    {
        std::lock_guard lock(m_shared->mutex);
        m_shared->effects.clear();
        m_shared->unreadable.clear();
        m_shared->done = 0;
        m_shared->finished = false;
        m_shared->error.clear();
    }
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
    bool ended = false;
    std::chrono::steady_clock::time_point ended_at;
    {
        std::lock_guard lock(m_shared->mutex);
        m_effects = m_shared->effects;
        m_frames_done = m_shared->done;
        m_changed_cells = m_shared->changed_cells;
        if (m_shared->unreadable.size() != m_unreadable.size()) {
            m_unreadable.clear();
            for (const auto& [index, message] : m_shared->unreadable)
                m_unreadable.emplace(index, QString::fromStdString(message));
        }
        if (!m_shared->error.empty() && m_error.isEmpty())
            m_error = QString::fromStdString(m_shared->error);
        ended = m_shared->finished;
        ended_at = m_shared->ended;
        m_shared->finished = false;
    }
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
