#include "ui/worker/frame_worker.h"

#include "ui/adapters/image_adapter.h"
#include "visioncore/services/layers.h"

#include <QMetaObject>
#include <QTimer>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>

namespace fieldsight::ui {

namespace {

/// After a run of the same frame again, the look-ahead waits for this long without a request.
constexpr int kIdleLookAheadMs = 60;

/// How long a request waits for a frame the read-ahead's thread is reading (at most one frame's
/// decoding; reading it again here would take as long).
constexpr std::chrono::milliseconds kWaitForReadAhead{2000};

LayerSet perceptLayers(const Pipeline& pipeline)
{
    const std::vector<std::string> ids = perceptLayerIds(pipeline.perceptKinds(), false);
    return LayerSet(ids.begin(), ids.end());
}

std::optional<double> number(const nlohmann::ordered_json& object, const char* key)
{
    const auto it = object.find(key);
    if (it == object.end() || !it->is_number())
        return std::nullopt;
    return it->get<double>();
}

/// Where a percept is, from the SPEC §5.1 fields it has (a circle, a box, a segment or a point).
std::optional<QRectF> boundsOf(const nlohmann::ordered_json& o)
{
    const auto x = number(o, "x"), y = number(o, "y"), r = number(o, "radius");
    const auto left = number(o, "left"), right = number(o, "right"), top = number(o, "top"),
               bottom = number(o, "bottom");
    const auto x1 = number(o, "x1"), y1 = number(o, "y1"), x2 = number(o, "x2"),
               y2 = number(o, "y2");
    if (x && y && r)
        return QRectF(*x - *r, *y - *r, 2 * *r, 2 * *r);
    if (left && right && top && bottom)
        return QRectF(QPointF(*left, *top), QPointF(*right, *bottom)).normalized();
    if (x1 && y1 && x2 && y2)
        return QRectF(QPointF(*x1, *y1), QPointF(*x2, *y2)).normalized().adjusted(-2, -2, 2, 2);
    if (x && y)
        return QRectF(*x - 2, *y - 2, 4, 4);
    return std::nullopt;
}

QString fieldsText(const nlohmann::ordered_json& o)
{
    QStringList lines;
    for (auto it = o.begin(); it != o.end(); ++it) {
        const QString key = QString::fromStdString(it.key());
        if (it->is_number_float())
            lines << QStringLiteral("%1: %2").arg(key).arg(it->get<double>(), 0, 'f', 1);
        else
            lines << QStringLiteral("%1: %2").arg(key, QString::fromStdString(it->dump()));
    }
    return lines.join('\n');
}

} // namespace

std::vector<PerceptItem> perceptItems(const PerceptSet& percepts)
{
    std::vector<PerceptItem> items;
    for (const PerceptEntry* entry : percepts.entries()) {
        nlohmann::ordered_json list;
        entry->toJson(PerceptNames::Results, list);
        if (!list.is_array())
            continue;
        const std::string layer =
            std::string(kPerceptLayerPrefix) + "." + std::string(entry->kind().key);
        for (std::size_t i = 0; i < list.size(); ++i) {
            const auto& object = list[i];
            if (!object.is_object())
                continue; // a polyline point, not a detection of its own
            const std::optional<QRectF> bounds = boundsOf(object);
            if (!bounds)
                continue;
            const QString label = perceptNoun(entry->kind()) + ' ' + QString::number(i + 1);
            items.push_back({layer, *bounds, label, label + '\n' + fieldsText(object)});
        }
    }
    return items;
}

FrameWorker::FrameWorker(const Pipeline& pipeline)
    : m_pipeline(pipeline), m_percept_layers(perceptLayers(pipeline)), m_control(m_data, pipeline)
{
    for (const StageDescriptor& stage : pipeline.descriptors())
        if (stage.info.skippable)
            m_skippable.push_back(stage.info.id);
}

void FrameWorker::submit(FrameRequest request)
{
    std::lock_guard lock(m_mutex);
    m_pending = std::move(request);
    if (m_scheduled)
        return; // the queued call takes the newest request
    m_scheduled = true;
    QMetaObject::invokeMethod(this, &FrameWorker::processPending, Qt::QueuedConnection);
}

void FrameWorker::processPending()
{
    FrameRequest request;
    {
        std::lock_guard lock(m_mutex);
        m_scheduled = false;
        if (!m_pending)
            return;
        request = std::move(*m_pending);
        m_pending.reset();
    }
    if (request.look_ahead_only) {
        if (request.source && request.source->reader) {
            try {
                (void)load(request.source, request.index);
            } catch (const std::exception&) {
                m_frame_valid = false; // the real read of that frame will report it
            }
        }
    } else {
        std::shared_ptr<FrameOutput> out;
        try {
            out = run(request);
        } catch (const std::exception& e) {
            // A failure outside the stages (decoding, memory): this frame's error, the tool goes
            // on.
            out = std::make_shared<FrameOutput>();
            out->serial = request.serial;
            out->index = request.index;
            out->error = QStringLiteral("frame %1: %2").arg(request.index).arg(e.what());
            m_frame_valid = false;
        }
        emit frameDone(std::move(out));
    }
    // At once after a step; after a run of the same frame again (a brush stroke, a parameter
    // dragged), only once no other request came for a while: another would follow soon, and a
    // look-ahead would only delay it.
    const bool stepped = request.look_ahead_only || m_last_index != request.index;
    m_last_index = request.index;
    const std::uint64_t taken = ++m_taken;
    const auto look = [this, request = std::move(request)] {
        try {
            lookAhead(request);
        } catch (const std::exception&) {
            m_prefetch_source.reset(); // the real read of that frame will report it
        }
    };
    if (stepped) {
        look();
        return;
    }
    try {
        prefetch();
    } catch (const std::exception&) {
        m_prefetch_source.reset();
    }
    QTimer::singleShot(kIdleLookAheadMs, this, [this, taken, look] {
        if (taken == m_taken) // nothing asked since
            look();
    });
}

bool FrameWorker::aheadAnswers(const FrameRequest& request, bool any_frame) const
{
    const FrameRequest& k = m_ahead_for;
    return m_ahead && k.source == request.source && (any_frame || k.index == request.index) &&
           k.lut == request.lut && k.params == request.params && k.skip == request.skip &&
           k.light == request.light &&
           std::includes(k.layers.begin(), k.layers.end(), request.layers.begin(),
                         request.layers.end()); // more layers than asked for answer it too
}

std::shared_ptr<FrameOutput> FrameWorker::takeAhead(const FrameRequest& request)
{
    std::lock_guard lock(m_mutex);
    return aheadAnswers(request, false) ? std::exchange(m_ahead, nullptr) : nullptr;
}

std::optional<std::size_t> FrameWorker::aheadIndex(const FrameRequest& like)
{
    std::lock_guard lock(m_mutex);
    return aheadAnswers(like, true) ? std::optional<std::size_t>(m_ahead_for.index) : std::nullopt;
}

void FrameWorker::swapPrefetch()
{
    std::swap(m_data.frame(), m_prefetch);
    std::swap(m_display, m_prefetch_display);
    std::swap(m_frame_source, m_prefetch_source);
    std::swap(m_frame_index, m_prefetch_index);
}

void FrameWorker::lookAhead(const FrameRequest& request)
{
    prefetch();
    FrameRequest next = request;
    next.index = request.index + 1;
    next.look_ahead_only = false;
    {
        std::lock_guard lock(m_mutex);
        if (m_pending)
            return; // there is real work
        if (aheadAnswers(next, false))
            return; // prepared already
    }
    if (!m_frame_valid || !m_prefetch_source || m_prefetch_source != request.source ||
        m_prefetch_index != next.index || !request.source->reader)
        return;
    const auto start = std::chrono::steady_clock::now();
    auto out = std::make_shared<FrameOutput>();
    out->index = next.index;
    out->layers = next.layers;
    swapPrefetch();
    try {
        runCore(next, m_control, m_applied_params, m_data.frame(), *out);
    } catch (const std::exception&) {
        out.reset(); // the real run of that frame will report it
    }
    swapPrefetch();
    if (!out || !out->error.isEmpty())
        return;
    out->worker_ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    std::lock_guard lock(m_mutex);
    m_ahead = std::move(out);
    m_ahead_for = std::move(next);
}

void FrameWorker::release(std::shared_ptr<FrameSource> source)
{
    QMetaObject::invokeMethod(
        this,
        [this, source = std::move(source)]() mutable {
            if (m_live_source == source) {
                m_live_control.reset();
                m_live_source.reset();
            }
            m_read_ahead.drop(source);
            m_recent.erase(
                std::remove_if(m_recent.begin(), m_recent.end(),
                               [&source](const RecentFrame& r) { return r.source == source; }),
                m_recent.end());
            {
                std::lock_guard lock(m_mutex);
                if (m_ahead_for.source == source) { // a step on the new stream never finds it
                    m_ahead.reset();
                    m_ahead_for = {};
                }
            }
            source.reset();
        },
        Qt::QueuedConnection);
}

Status FrameWorker::load(const std::shared_ptr<FrameSource>& source, std::size_t index)
{
    if (m_frame_valid && source == m_frame_source && index == m_frame_index)
        return {}; // the same frame again: settings changed
    keepRecent();
    m_frame_valid = false;
    if (source == m_prefetch_source && index == m_prefetch_index) {
        std::swap(m_data.frame(), m_prefetch);
        std::swap(m_display, m_prefetch_display);
        m_prefetch_source.reset();
        ++m_load_counts.read_ahead;
    } else if (takeRecent(source, index, m_data.frame(), m_display)) {
        ++m_load_counts.recent;
    } else if (ReadAhead::Decoded ahead;
               m_read_ahead.take(source, index, ahead, kWaitForReadAhead) ==
               ReadAhead::State::Taken) {
        // (Waits while the read-ahead's thread is reading it: reading it here too takes as long.)
        m_data.frame() = std::move(ahead.frame);
        m_display = std::move(ahead.display);
        ++m_load_counts.read_ahead;
    } else if (Frame fresh; Status s = source->reader->readInto(index, fresh)) {
        // Into a Frame of its own, never read into again: its display shares the pixels (the
        // buffer there may be one an output still shows).
        m_data.frame() = std::move(fresh);
        m_display = {};
        ++m_load_counts.read;
    } else {
        return s;
    }
    m_frame_source = source;
    m_frame_index = index;
    m_frame_valid = true;
    return {};
}

void FrameWorker::keepRecent()
{
    if (!m_frame_valid || !m_frame_source || !m_frame_source->reader || kRecentFrames == 0)
        return;
    if (m_recent.size() >= kRecentFrames)
        m_recent.erase(m_recent.begin());
    // Moved out: the next frame is read into a fresh buffer, never over one kept here.
    m_recent.push_back(
        {m_frame_source, m_frame_index, std::move(m_data.frame()), std::move(m_display)});
    m_data.frame() = {};
    m_display = {};
    m_frame_valid = false;
}

bool FrameWorker::takeRecent(const std::shared_ptr<FrameSource>& source, std::size_t index,
                             Frame& frame, Display& display)
{
    const auto it = std::find_if(m_recent.begin(), m_recent.end(), [&](const RecentFrame& r) {
        return r.source == source && r.index == index;
    });
    if (it == m_recent.end())
        return false;
    frame = std::move(it->frame);
    display = std::move(it->display);
    m_recent.erase(it);
    return true;
}

void FrameWorker::prefetch()
{
    {
        std::lock_guard lock(m_mutex);
        if (m_pending)
            return; // there is real work
    }
    if (!m_frame_valid || !m_frame_source)
        return;
    const StreamInfo& info = m_frame_source->reader->info();
    const std::size_t next = m_frame_index + 1;
    bool ready = m_prefetch_source == m_frame_source && m_prefetch_index == next;
    if (!ready && next < info.frame_count &&
        takeRecent(m_frame_source, next, m_prefetch, m_prefetch_display)) {
        m_prefetch_source = m_frame_source; // shown lately (a step back): not decoded again
        m_prefetch_index = next;
        ready = true;
    }
    // The next frames are read on the read-ahead's thread, while this one runs the core; one
    // prefetched already is not read again.
    m_read_ahead.want(m_frame_source, ready ? next + 1 : next, m_last_lut);
    if (next >= info.frame_count || ready)
        return;
    m_prefetch_source.reset();
    ReadAhead::Decoded ahead;
    ReadAhead::State state = ReadAhead::State::Reading;
    // Waits for the next frame in short spells: a request that comes meanwhile goes first.
    while ((state = m_read_ahead.take(m_frame_source, next, ahead, std::chrono::milliseconds(4))) ==
           ReadAhead::State::Reading) {
        std::lock_guard lock(m_mutex);
        if (m_pending)
            return;
    }
    if (state == ReadAhead::State::Taken) {
        m_prefetch = std::move(ahead.frame);
        m_prefetch_display = std::move(ahead.display);
        // A newer table (the pixels are the display's already).
        makeFrameDisplay(m_prefetch, m_last_lut, m_prefetch_display, FramePixels::Share);
    } else if (Frame fresh; m_frame_source->reader->readInto(next, fresh)) {
        m_prefetch = std::move(fresh); // never read into again: the display shares it
        m_prefetch_display = {};
        makeFrameDisplay(m_prefetch, m_last_lut, m_prefetch_display, FramePixels::Share);
    } else {
        return;
    }
    m_prefetch_source = m_frame_source;
    m_prefetch_index = next;
}

void FrameWorker::runCore(const FrameRequest& request, ControlWrapper& control,
                          std::shared_ptr<const ParamSet>& applied, const Frame& frame,
                          FrameOutput& out)
{
    if (request.params != applied) {
        control.resetParams();
        if (request.params) {
            if (Status s = control.applyParams(*request.params); !s) {
                out.error = QString::fromStdString(s.error().message);
                return; // and tried again on the next frame
            }
        }
        applied = request.params;
    }
    for (const std::string& id : m_skippable)
        (void)control.setStageEnabled(id, request.skip.count(id) == 0);
    const std::shared_ptr<const ColourLut> lut = lutFor(request, request.index);
    m_data.setLut(lut);
    m_data.setRequestedLayers(request.layers); // a live camera's core draws through m_data too
    m_last_lut = request.lut;

    Result<FrameReport> report = control.runFrame();
    out.frame.name = frame.name;
    out.frame.timestamp_ms = frame.timestamp_ms;
    out.frame.horizon = frame.horizon;
    // Through the frame's light map, when following. A file's frame was read into a Frame of its
    // own (load); a camera writes its frame again.
    makeFrameDisplay(frame, lut, m_display,
                     request.source->reader ? FramePixels::Share : FramePixels::Copy);
    out.frame.ycbcr = m_display.ycbcr;
    out.raw = m_display.raw;
    out.classified = m_display.classified;
    out.classes = m_display.classes;
    if (!report) {
        out.error = QString::fromStdString(frame.name + ": " + report.error().message);
        return;
    }
    out.result =
        collectResult(request.index, frame.name, std::move(report).value(), control.blackboard());

    LayerSet wanted = m_percept_layers;
    wanted.insert(request.layers.begin(), request.layers.end());
    out.drawings = frameDrawings(m_pipeline, wanted, m_data.canvas(), out.result.percepts, nullptr);
    out.items = perceptItems(out.result.percepts);
}

std::shared_ptr<const ColourLut> FrameWorker::lutFor(const FrameRequest& request, std::size_t index)
{
    if (!request.light || !request.lut || index >= request.light->frames.size())
        return request.lut;
    std::shared_ptr<const LutInputMap> map = m_light_maps.mapFor(request.light->frames[index]);
    if (!map)
        return request.lut;
    // A new table object for every table and map: the display is cached by table object, and an
    // output still shown may hold the one before.
    if (m_light_base != request.lut || !m_light_lut || m_light_lut->inputMap() != map) {
        auto lut = std::make_shared<ColourLut>(*request.lut);
        lut->setInputMap(std::move(map));
        m_light_base = request.lut;
        m_light_lut = std::move(lut);
    }
    return m_light_lut;
}

std::shared_ptr<FrameOutput> FrameWorker::run(const FrameRequest& request)
{
    const auto start = std::chrono::steady_clock::now();
    auto out = std::make_shared<FrameOutput>();
    out->serial = request.serial;
    out->index = request.index;
    out->wait_ms = std::chrono::duration<double, std::milli>(start - request.submitted).count();
    out->layers = request.layers; // asked for, whether or not the frame could be run
    if (!request.source || (!request.source->reader && !request.source->camera)) {
        out->error = QStringLiteral("no stream is open");
        return out;
    }
    ControlWrapper* control = &m_control;
    std::shared_ptr<const ParamSet>* applied = &m_applied_params;
    const Frame* frame = &m_data.frame();
    if (CameraDataWrapper* camera = request.source->camera.get()) {
        if (m_live_source != request.source) {
            m_live_control.reset();
            m_live_source = request.source;
            m_live_control = std::make_unique<ControlWrapper>(*camera, m_pipeline);
            m_live_params.reset(); // a new core has the defaults
        }
        camera->setLut(request.lut);
        camera->setDebugSink(&m_data);
        if (Status s = camera->latch(std::chrono::seconds(2)); !s) {
            out->error = QString::fromStdString(s.error().message);
            return out;
        }
        m_display = {}; // a new frame every run
        control = m_live_control.get();
        applied = &m_live_params;
        frame = &camera->frame();
    } else if (Status s = load(request.source, request.index); !s) {
        out->error = QString::fromStdString(s.error().message);
        out->frame.name = request.source->reader->frameName(request.index);
        return out;
    }

    runCore(request, *control, *applied, *frame, *out);
    out->worker_ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    return out;
}

} // namespace fieldsight::ui
