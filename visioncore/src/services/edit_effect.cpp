// The whole-stream scan of a LUT edit's effect: prefilter, rerun and detection delta per frame.
#include "visioncore/services/edit_effect.h"

#include "visioncore/services/lut_compare.h"

#include <exception>
#include <memory>
#include <mutex>
#include <utility>

namespace fieldsight {

namespace {

/// The table before the edit, read through the light of the frame each worker is on: a copy per
/// worker (its input map set frame by frame), so frames under different lights run side by side.
class BeforeThroughLight
{
public:
    explicit BeforeThroughLight(std::shared_ptr<const ColourLut> before)
        : m_before(std::move(before))
    {
    }

    /// `after` (with its input map) against the table before, through that map.
    PixelTally tally(const ColourLut& after, const cv::Mat& ycbcr)
    {
        if (!m_before)
            return tallyThroughMap(nullptr, after, ycbcr);
        std::unique_ptr<ColourLut> copy;
        {
            std::lock_guard lock(m_mutex);
            if (!m_free.empty()) {
                copy = std::move(m_free.back());
                m_free.pop_back();
            } else {
                // The copies from one that has had a map (and so names its cells), so that
                // they share what each cell reads through a map.
                if (!m_prototype) {
                    m_prototype = std::make_unique<ColourLut>(*m_before);
                    m_prototype->setInputMap(after.inputMap());
                }
                copy = std::make_unique<ColourLut>(*m_prototype);
            }
        }
        copy->setInputMap(after.inputMap());
        const PixelTally tally = tallyThroughMap(copy.get(), after, ycbcr);
        std::lock_guard lock(m_mutex);
        m_free.push_back(std::move(copy));
        return tally;
    }

private:
    std::shared_ptr<const ColourLut> m_before;
    std::mutex m_mutex;
    std::unique_ptr<ColourLut> m_prototype;
    std::vector<std::unique_ptr<ColourLut>> m_free;
};

} // namespace

EditEffectScanner::EditEffectScanner(const Pipeline& pipeline) : m_pipeline(pipeline) {}

void EditEffectScanner::setStream(std::string path, StreamOptions options)
{
    m_path = std::move(path);
    m_options = options;
    m_input.reset();
    m_previous.clear();
    m_previous_lut.clear();
    m_previous_map.clear();
}

void EditEffectScanner::clearResults()
{
    m_cancel = false;
    std::lock_guard lock(m_mutex);
    m_progress.effects.clear();
    m_progress.unreadable.clear();
    m_progress.done = 0;
    m_progress.finished = false;
    m_progress.error.clear();
}

EditEffectProgress EditEffectScanner::collect()
{
    std::lock_guard lock(m_mutex);
    EditEffectProgress copy = m_progress;
    m_progress.finished = false;
    return copy;
}

void EditEffectScanner::fail(std::string message)
{
    std::lock_guard lock(m_mutex);
    m_progress.error = std::move(message);
}

void EditEffectScanner::run(const EditEffectJob& job)
{
    // The scan yields to the window and its frame worker, its light-tracking pass included.
    lowerThreadPriority();
    try {
        if (!m_input) {
            auto reader = openStream(m_path, m_options);
            if (!reader)
                return fail(reader.error().message);
            StreamInput input;
            input.stream = m_path;
            input.reader = std::move(reader).value();
            input.pipeline = &m_pipeline;
            m_input.emplace(std::move(input));
            m_previous.assign(m_input->info().frame_count, std::nullopt);
            m_previous_lut.assign(m_input->info().frame_count, nullptr);
            m_previous_map.assign(m_input->info().frame_count, nullptr);
        }
        StreamInput& input = *m_input;
        input.lut = job.after;
        input.params = *job.params;
        input.skip.assign(job.skip.begin(), job.skip.end());
        input.adapt = job.adapt;
        const CellMask mask =
            job.before ? CellMask::differences(*job.before, *job.after) : CellMask();
        const PixelTallier tally_pixels(*job.after, mask);
        BeforeThroughLight before_through_light(job.before);
        const std::size_t frames = input.info().frame_count;
        const int width = input.info().width;
        const int height = input.info().height;
        const std::vector<const PerceptKind*> kinds = scoredKinds(m_pipeline.perceptKinds());
        {
            std::lock_guard lock(m_mutex);
            m_progress.effects.assign(frames, FrameEffect{});
            m_progress.changed_cells = mask.count();
        }
        const auto record = [&](std::size_t index, const PixelTally& tally,
                                const DetectionDelta& delta) {
            FrameEffect effect;
            effect.done = true;
            effect.changed_pixels = std::uint32_t(tally.in_mask);
            effect.unclassified = std::uint32_t(tally.unclassified);
            effect.pixels = std::uint32_t(tally.pixels);
            effect.delta = delta;
            std::lock_guard lock(m_mutex);
            m_progress.effects[index] = effect;
            ++m_progress.done;
        };
        std::vector<PixelTally> tallies(frames);
        std::vector<std::shared_ptr<const LutInputMap>> frame_maps(frames);
        RunHooks hooks;
        hooks.cancel = &m_cancel;
        hooks.pause = m_gate; // before each frame's read and its run
        // A frame none of whose pixels changed class keeps its result: the pipeline runs only
        // where the edit shows (or everywhere when the settings changed). Following the light,
        // a frame read through a map is counted through it, and its result holds only if it was
        // read through the same map.
        hooks.prefilter = [&](std::size_t index, const Frame& frame, const ColourLut& table) {
            lowerThreadPriority(); // the scan yields to the window and its frame worker
            tallies[index] = table.inputMap() ? before_through_light.tally(table, frame.ycbcr)
                                              : tally_pixels(frame.ycbcr);
            const bool unchanged = job.before && !job.rerun_all && tallies[index].in_mask == 0 &&
                                   m_previous[index] && m_previous_lut[index] == job.before &&
                                   m_previous_map[index] == table.inputMap();
            frame_maps[index] = table.inputMap();
            if (!unchanged)
                return true;
            m_previous_lut[index] = job.after;
            m_previous_map[index] = frame_maps[index];
            record(index, tallies[index], {});
            return false;
        };
        // A damaged frame is marked and passed: the rest of the stream still shows the edit.
        hooks.on_unreadable = [&](std::size_t index, const std::string& message) {
            FrameEffect effect;
            effect.done = true;
            effect.unreadable = true;
            std::lock_guard lock(m_mutex);
            m_progress.effects[index] = effect;
            m_progress.unreadable[index] = message;
            ++m_progress.done;
        };
        hooks.on_frame = [&](const FrameResult& result, const Frame&,
                             const DebugCanvas&) -> Status {
            const std::size_t index = result.index;
            DetectionDelta delta;
            std::optional<PerceptSet>& previous = m_previous[index];
            if (job.before && previous)
                delta = compareDetections(*previous, result.percepts, width, height, kinds);
            previous = result.percepts; // one frame per index: no other thread writes it
            m_previous_lut[index] = job.after;
            m_previous_map[index] = frame_maps[index];
            record(index, tallies[index], delta);
            return {};
        };
        auto run = runStream(input, firstFrames(frames), m_threads, hooks);
        if (!run)
            return fail(run.error().message);
        std::lock_guard lock(m_mutex);
        m_progress.finished = !run.value().cancelled;
        m_progress.ended = std::chrono::steady_clock::now();
    } catch (const std::exception& e) {
        fail(e.what());
    }
}

} // namespace fieldsight
