// The effect of a LUT edit on a whole stream: every frame is run again with the new table and,
// per frame, the pixels whose class changed and the detections that appeared or vanished (by the
// eval matching rules) against that frame's previous result are counted. Frames none of whose
// pixels changed class keep their result without running the pipeline.
#pragma once

#include "visioncore/basics/colour_lut.h"
#include "visioncore/framework/controller.h"
#include "visioncore/framework/param_set.h"
#include "visioncore/services/evaluation.h"
#include "visioncore/services/light_tracking.h"
#include "visioncore/services/stream_runner.h"

#include <atomic>
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace fieldsight {

/// One frame's effect of the last edit.
struct FrameEffect
{
    bool done = false;                ///< scanned since the last edit
    bool unreadable = false;          ///< the frame could not be read (the progress says why)
    std::uint32_t changed_pixels = 0; ///< pixels whose class the edit changed
    std::uint32_t unclassified = 0;   ///< pixels the current table leaves unclassified
    std::uint32_t pixels = 0;
    DetectionDelta delta; ///< against the frame's previous result (none on the first scan)
};

/// One scan of the stream.
struct EditEffectJob
{
    std::shared_ptr<const ColourLut> before; ///< null: record every frame's result, compare none
    std::shared_ptr<const ColourLut> after;  ///< the table to run with; must be set
    std::shared_ptr<const ParamSet> params = std::make_shared<ParamSet>();
    std::set<std::string, std::less<>> skip{}; ///< stage ids switched off
    bool rerun_all = false; ///< the settings changed: no earlier result still holds
    /// Follow the light (as --adapt, from frame 0 with `after`): each frame is run, and its
    /// pixels counted, through the input map of its light, as the window shows it. Set it on
    /// every job while the window follows the light (rerun_all when it is switched).
    std::optional<LightTrackingOptions> adapt{};
};

/// How far a scan has got, copied under the scanner's lock.
struct EditEffectProgress
{
    std::vector<FrameEffect> effects; ///< one per frame (empty until the stream is open)
    std::size_t done = 0;             ///< frames scanned, unreadable ones included
    std::size_t changed_cells = 0;    ///< cells that differ between the job's two tables
    std::map<std::size_t, std::string> unreadable; ///< frame index: the reader's message
    std::string error;                           ///< why the scan stopped early (empty: it did not)
    bool finished = false;                       ///< the scan covered every frame (see collect())
    std::chrono::steady_clock::time_point ended; ///< when it finished
};

/// Runs scan jobs over one file stream and keeps each frame's last result and the table it was
/// run with between them. run() is called on one thread at a time (the scan thread);
/// collect() and cancel() from any thread while it runs; the rest only while no run() is going.
class EditEffectScanner
{
public:
    explicit EditEffectScanner(const Pipeline& pipeline = Pipeline::standard());

    /// Worker threads of a scan (0: one per core).
    void setThreads(int threads) { m_threads = threads; }
    /// Called by each scan thread before it reads a frame and again before it runs one; it may
    /// block (the window pausing the scan while the user steps). Set only while no run() goes.
    void setFrameGate(std::function<void()> gate) { m_gate = std::move(gate); }
    /// The stream to scan (a local path; empty: none), opened with `options` (its orientation,
    /// as the window shows it). Forgets every frame's result, so the next job only records.
    void setStream(std::string path, StreamOptions options = {});
    const std::string& stream() const { return m_path; }

    /// Empties the results and forgets an earlier cancel(): called before each run().
    void clearResults();
    /// Scans every frame with `job` (opening the stream the first time). The scan threads run at
    /// a lower priority (nice 10 on Linux). A frame that cannot be read is marked and passed;
    /// other problems end the scan with `error` set.
    void run(const EditEffectJob& job);
    /// Stops a running scan after the frame each thread is on.
    void cancel() { m_cancel = true; }

    /// The results so far. `finished` is reported by the first collect() after the scan ended
    /// and is false after that, so each end is heard of once.
    EditEffectProgress collect();

private:
    void fail(std::string message);

    const Pipeline& m_pipeline;
    int m_threads = 0;
    std::function<void()> m_gate;
    std::atomic<bool> m_cancel{false};

    std::mutex m_mutex; ///< guards m_progress
    EditEffectProgress m_progress;

    // Touched only by run() (or, between runs, setStream()).
    std::string m_path;
    StreamOptions m_options;
    std::optional<StreamInput> m_input;
    std::vector<std::optional<PerceptSet>> m_previous;              ///< each frame's last result
    std::vector<std::shared_ptr<const ColourLut>> m_previous_lut;   ///< the table it was run with
    std::vector<std::shared_ptr<const LutInputMap>> m_previous_map; ///< and its light's map
};

} // namespace fieldsight
