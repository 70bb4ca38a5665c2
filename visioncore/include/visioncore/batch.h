// The headless commands of SPEC §5 (run, bench, eval) as Qt-free library code: the command line
// only parses arguments into these option structs, and tests can call the pieces directly.
#pragma once

#include "visioncore/annotations.h"
#include "visioncore/blackboard.h"
#include "visioncore/colour_lut.h"
#include "visioncore/control_wrapper.h"
#include "visioncore/controller.h"
#include "visioncore/evaluation.h"
#include "visioncore/result.h"
#include "visioncore/stream_reader.h"

#include <cstddef>
#include <iosfwd>
#include <memory>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

namespace fieldsight {

/// Exit statuses of the commands (SPEC §5).
inline constexpr int kExitOk = 0;
inline constexpr int kExitFailure = 1;  ///< failure while running
inline constexpr int kExitBadInput = 2; ///< bad usage or bad input

/// The stream and LUT a command works on, opened and checked.
struct BatchInput
{
    std::string stream;                   ///< the stream argument as given
    std::unique_ptr<StreamReader> reader; ///< for names and info; workers open their own
    std::string lut_path;                 ///< the LUT file in use
    ColourLut lut;
    /// Stage parameters set on every core: (stage id, parameter, value).
    std::vector<std::tuple<std::string, std::string, double>> params;

    const StreamInfo& info() const { return reader->info(); }
};

/// Opens `stream` and the LUT `lut_path`, or the stream's default LUT when `lut_path` is empty.
/// Errors name the file and the problem. `settings` are --set values (see applySettings).
Result<BatchInput> openBatchInput(const std::string& stream, const std::string& lut_path,
                                  const std::vector<std::string>& settings = {});

/// Parses --set settings "STAGE.PARAM=VALUE" (e.g. transitions.goal_colour=9), checks them against
/// the pipeline's parameter registry and stores them in input.params.
Status applySettings(BatchInput& input, const std::vector<std::string>& settings);
/// Applies input.params to a core (already checked by applySettings).
Status configureControl(ControlWrapper& control, const BatchInput& input);

/// Checks --skip ids against the pipeline (whether a stage may be skipped is checked when the
/// control wrappers are set up).
Status checkStageIds(const std::vector<std::string>& ids);

/// What the pipeline produced for one frame: one entry of fieldsight-results/1.
struct FrameResult
{
    std::size_t index = 0; ///< frame index in the stream
    std::string name;
    FrameReport report;                ///< timings, and which stages ran
    std::vector<PointF> green_horizon; ///< hull polyline, x ascending
    std::vector<Ball> balls;
    std::vector<Goalpost> goalposts;
    std::vector<Obstacle> obstacles;
    std::vector<FieldLine> field_lines;
    std::vector<Diagnostic> diagnostics;

    /// Did stage `stage_id` run on this frame (a skipped stage's list is absent from the output).
    bool stageRan(std::string_view stage_id) const;
    FrameDetections detections() const;
};

/// Runs the pipeline over frames `indices` of `input` with `threads` workers (0: one per core).
/// Every worker has its own StreamReader (the first borrows input.reader), StreamDataWrapper and
/// ControlWrapper; results come back in the order of `indices`. Errors (a frame that cannot be
/// read, a stage that cannot be skipped) are bad input. A failure of the pipeline itself throws
/// std::runtime_error.
Result<std::vector<FrameResult>> processFrames(BatchInput& input,
                                               const std::vector<std::size_t>& indices,
                                               const std::vector<std::string>& skip, int threads);

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

// --- run ---------------------------------------------------------------------------------------

struct RunOptions
{
    std::string stream;
    std::string lut;                             ///< empty: the stream's default LUT
    std::string out = "fieldsight-results.json"; ///< "-" for stdout
    std::vector<std::string> skip;               ///< stage ids to switch off
    std::vector<std::string> set;                ///< "STAGE.PARAM=VALUE" settings
    int threads = 1;                             ///< 0: one per core
    std::size_t limit = 0;                       ///< process only the first `limit` frames; 0: all
    std::string overlays; ///< when set, write each frame with its detections drawn as PNG here
};

/// The fieldsight-results/1 document (SPEC §5.1): one line per frame.
std::string resultsJson(const BatchInput& input, const std::vector<FrameResult>& frames,
                        const std::vector<std::string>& skip);

/// The frame (BGR, twice the size) with the detections drawn, and the truth in dark lines if given.
cv::Mat renderOverlay(const cv::Mat& ycbcr, const FrameResult& frame, const FrameAnnotation* truth);
/// Writes renderOverlay() of every frame to `dir`/<frame stem>.png (truth: the stream's
/// annotations).
Status writeOverlays(BatchInput& input, const std::vector<FrameResult>& frames,
                     const std::string& dir, const Annotations* truth);

// --- bench -------------------------------------------------------------------------------------

struct BenchOptions
{
    std::vector<std::string> streams; ///< one or more; each is benched on its own
    std::string lut;                  ///< empty: each stream's default LUT
    int repeat = 1;                   ///< passes over each stream
    std::vector<std::string> set;     ///< "STAGE.PARAM=VALUE" settings
    int threads = 1;                  ///< 0: one per core
    std::size_t limit = 0;            ///< only the first `limit` frames; 0: all
    std::string json;                 ///< also write fieldsight-bench/1 here when not empty
};

/// Streams with fewer frames than this are decoded once and kept in memory for all passes.
inline constexpr std::size_t kBenchInMemoryFrames = 2000;

struct BenchResults
{
    std::string stream;
    std::string lut_path;
    int width = 0;  ///< px
    int height = 0; ///< px
    std::size_t frames = 0;
    int repeat = 1;
    int threads = 1;
    bool in_memory = false;
    TimingStats pipeline; ///< ControlWrapper::runFrame, wall clock
    std::vector<std::pair<std::string, TimingStats>> stages; ///< pipeline order, runs only
    /// Only the LUT lookups of the pixels the scan lines touch (a lower bound for any scan-line
    /// design on these frames).
    TimingStats floor;
    double floor_pixels_per_frame = 0;
    /// Every pixel through the LUT into a class image, then OpenCV connected components of the
    /// ball and goal classes (what one would write without scan lines).
    TimingStats baseline;
};

/// Times the pipeline and the two reference loops on the same frames (see BenchResults).
/// options.streams and options.lut are not used: `input` is already open.
Result<BenchResults> runBench(BatchInput& input, const BenchOptions& options);
std::string benchTable(const BenchResults& results);
std::string benchJson(const BenchResults& results); ///< fieldsight-bench/1

/// Several streams benched with the same options, laid out as the paper's Table 1: one row per
/// stream and a combined row over all frames of all streams.
struct MultiBenchResults
{
    std::vector<std::string> names;    ///< row labels (benchStreamName), in the order given
    std::vector<BenchResults> streams; ///< same order as names
    /// Every run of every stream pooled (TimingStats::pooled), per stage too; frames is the sum,
    /// stream and lut are empty, width and height are 0 unless all streams share a size.
    BenchResults combined;
};

/// A stream's label in the table: the folder's name, or the file name for a .strm or video
/// file ("camera:N" as it is).
std::string benchStreamName(const std::string& stream);
/// Labels the streams (the path as given where two would share a name) and pools them.
MultiBenchResults combineBenches(const std::vector<std::string>& streams,
                                 std::vector<BenchResults> results);
/// The Table-1 style table, then the per-stage table (rows stages, columns streams, mean ms).
std::string multiBenchTable(const MultiBenchResults& results);
/// fieldsight-bench/1 with a "streams" array (each entry as benchJson's, plus "name") and
/// "combined".
std::string multiBenchJson(const MultiBenchResults& results);

// --- eval --------------------------------------------------------------------------------------

struct EvalOptions
{
    std::string stream;
    std::string lut;              ///< empty: the stream's default LUT
    std::string truth;            ///< empty: annotations.json in the stream folder
    std::vector<std::string> set; ///< "STAGE.PARAM=VALUE" settings
    std::string json;             ///< also write fieldsight-eval/1 here when not empty
    int threads = 0;              ///< 0: one per core
};

struct EvalReport
{
    std::string stream;
    std::string lut_path;
    std::string truth_path;
    EvaluationScores scores;
};

/// annotations.json in the stream's folder (the folder itself, or the one holding the file).
std::string defaultTruthPath(const std::string& stream);
std::string evalTable(const EvalReport& report);
std::string evalJson(const EvalReport& report); ///< fieldsight-eval/1

// --- the commands ------------------------------------------------------------------------------

/// Each prints its results to `out` and at most one line, "fieldsight: <problem>", to `err`, and
/// returns the exit status.
int runCommand(const RunOptions& options, std::ostream& out, std::ostream& err);
int benchCommand(const BenchOptions& options, std::ostream& out, std::ostream& err);
int evalCommand(const EvalOptions& options, std::ostream& out, std::ostream& err);

} // namespace fieldsight
