// Running the pipeline over a stream: open a stream with its LUT and settings, run frames on
// several cores with progress and cancel, and collect one FrameResult per frame. No printing:
// the command line and the GUI both drive it.
#pragma once

#include "visioncore/basics/colour_lut.h"
#include "visioncore/framework/blackboard.h"
#include "visioncore/framework/controller.h"
#include "visioncore/framework/param_set.h"
#include "visioncore/io/stream_reader.h"
#include "visioncore/percepts/percept_set.h"
#include "visioncore/basics/result.h"
#include "visioncore/services/light_tracking.h"

#include <atomic>
#include <cstddef>
#include <functional>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace fieldsight {

/// A stream, its LUT and the pipeline settings a run uses, opened and checked.
struct StreamInput
{
    std::string stream;                   ///< the stream argument as given
    std::unique_ptr<StreamReader> reader; ///< for names and info; workers open their own
    std::string lut_path;                 ///< the LUT file in use
    std::shared_ptr<const ColourLut> lut; ///< shared by every worker, never changed
    const Pipeline* pipeline = &Pipeline::standard();
    ParamSet params;               ///< set on every core
    std::vector<std::string> skip; ///< stage ids switched off on every core
    /// Follow the light (--adapt): each frame is classified through the input map of its light
    /// as trackLight follows it from frame 0, whatever frames are run and on how many workers.
    std::optional<LightTrackingOptions> adapt;

    const StreamInfo& info() const { return reader->info(); }
    /// The skip list and parameters are known to the pipeline and valid.
    Status checkSettings() const;
};

/// Every id names a stage of `pipeline` that can be skipped.
Status checkSkip(const Pipeline& pipeline, const std::vector<std::string>& skip);

/// The stream's own parameters (StreamInfo::params; none: empty), checked against `pipeline`.
/// Errors name the stream's manifest, the file and the problem.
Result<ParamSet> streamParams(const StreamInfo& info, const Pipeline& pipeline);

/// Opens `stream` (with `options`: its orientation) and the LUT `lut_path`, or the stream's
/// default LUT when `lut_path` is empty, with the stream's own parameters (streamParams). Errors
/// name the file and the problem.
Result<StreamInput> openStreamInput(const std::string& stream, const std::string& lut_path,
                                    const Pipeline& pipeline = Pipeline::standard(),
                                    const StreamOptions& options = {});

/// What the pipeline produced for one frame.
struct FrameResult
{
    std::size_t index = 0; ///< frame index in the stream
    std::string name;
    FrameReport report;  ///< timings, and which stages ran
    PerceptSet percepts; ///< a skipped stage's lists are absent
    std::vector<Diagnostic> diagnostics;
};

/// The FrameResult of the frame a core just ran.
FrameResult collectResult(std::size_t index, std::string name, FrameReport report,
                          const Blackboard& bb);

/// Optional hooks of a run. All are called on worker threads.
struct RunHooks
{
    /// Debug layers the cores draw (passed to on_frame).
    std::set<std::string, std::less<>> layers;
    /// Called for every frame once it is done, with its image and the requested drawings; an
    /// error stops the run (a failure, as for an output that cannot be written).
    std::function<Status(const FrameResult&, const Frame&, const DebugCanvas&)> on_frame;
    /// Called with each frame once it is read, before the pipeline, and the table the pipeline
    /// will read it with (with StreamInput::adapt, through the input map of the frame's light):
    /// false leaves the frame out (its FrameResult keeps only its index and name, and on_frame
    /// is not called for it).
    std::function<bool(std::size_t index, const Frame&, const ColourLut& table)> prefilter;
    /// When set, a frame that cannot be read (a damaged file in a folder, a bad record) is handed
    /// to it with the reader's message and the run goes on (its FrameResult keeps only its index
    /// and name, as a prefiltered frame). Unset, such a frame is the run's Error. Called from the
    /// workers, several at a time.
    std::function<void(std::size_t index, const std::string& message)> on_unreadable;
    /// Called (one call at a time) after every frame with the count done so far and the total.
    std::function<void(std::size_t done, std::size_t total)> progress;
    /// When it becomes true the workers stop after their current frame.
    const std::atomic<bool>* cancel = nullptr;
    /// Called by a worker before it reads each frame and again before it runs it (prefilter
    /// included); it may block (a background run pausing while the user steps through the
    /// stream). `cancel` is checked after each return.
    std::function<void()> pause;
};

struct StreamRun
{
    std::vector<FrameResult> frames; ///< in the order of the indices asked for
    /// With StreamInput::adapt, the light of every frame from 0 to the last one run (else empty).
    std::vector<LightState> light;
    bool cancelled = false; ///< then `frames` holds the frames done before the first one not done
};

/// Runs the pipeline over frames `indices` of `input` with `threads` workers (0: one per core).
/// Every worker has its own StreamReader (the first borrows input.reader) and ControlWrapper.
/// Bad input (a frame that cannot be read, a bad setting) is an Error; a failure of the pipeline
/// itself or of on_frame throws std::runtime_error. The first problem stops every worker; when
/// several are met before they stop, the one at the earliest position in `indices` is reported.
Result<StreamRun> runStream(StreamInput& input, const std::vector<std::size_t>& indices,
                            int threads, const RunHooks& hooks = {});

/// 0, 1, ..., n-1
std::vector<std::size_t> firstFrames(std::size_t n);

/// The calling thread yields to the others: a background run (the whole-stream scan, the
/// window's evaluation) calls it from its workers so the window and its frame worker come
/// first (`niceness` on Linux, 10 by default; the threads end with the run).
void lowerThreadPriority(int niceness = 10);

/// Population mean and standard deviation of a set of timings.
struct TimingStats
{
    double mean_ms = 0;
    double std_ms = 0;
    std::size_t samples = 0;

    static TimingStats of(const std::vector<double>& samples_ms);
    /// The statistics of all the samples behind `parts` taken together (exactly what of() gives
    /// on the concatenated samples, up to rounding), not the mean of their means.
    static TimingStats pooled(const std::vector<TimingStats>& parts);
};

} // namespace fieldsight
