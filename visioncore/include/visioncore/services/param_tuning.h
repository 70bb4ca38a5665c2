// Fitting the stages' parameters to a stream's annotations (`fieldsight tune`, the window's
// Pipeline > Fit to annotations): a seeded search over the registered ranges that maximises a
// weighted score on some annotated frames and reports it on the others, so overfitting shows.
#pragma once

#include "visioncore/basics/result.h"
#include "visioncore/framework/param_set.h"
#include "visioncore/io/annotations.h"
#include "visioncore/services/evaluation.h"
#include "visioncore/services/stream_runner.h"

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <map>
#include <string>
#include <vector>

namespace fieldsight {

/// The name the boundary's term goes by in TuneOptions::weights and TuneScore::terms.
inline constexpr const char* kBoundaryTerm = "boundary";

/// What a set of parameters scores on some frames (docs/formats.md, "How tune scores"):
/// total = sum over terms of weight x term / sum of the weights of the terms counted, where a
/// scored kind's term is its F1 (counted only when the frames have a true object or a detection
/// of it) and the boundary's is 2 / (2 + max(0, median per-frame boundary error - 1 px))
/// (counted when some frame has both boundaries).
struct TuneScore
{
    double total = 0;                          ///< in [0, 1]
    std::map<std::string, ClassScore> classes; ///< by scoredClassName
    std::map<std::string, double> terms;       ///< the terms counted, by class name / "boundary"
    double boundary_median = -1;               ///< px; negative when not scored
    double boundary_mean = -1;                 ///< px; negative when not scored
    std::size_t frames = 0;
    /// The core's mean time a frame in ms (wall clock, so only a guide: a parameter that makes
    /// a frame cost more shows here); negative when no frame was run whole.
    double ms_per_frame = -1;
};

/// F1 of a class score (1 when there was nothing to find and nothing found).
double f1Score(const ClassScore& score);

/// One parameter the search moved away from where it started.
struct TuneChange
{
    std::string stage;
    std::string name;
    double before = 0; ///< its value at the start (the stream's or the default)
    double after = 0;
    /// What it buys: the fit score of the result minus that of the result with this one
    /// parameter put back (its share; the shares need not add up to the whole gain).
    double gain = 0;
    /// The same, per term (class name or "boundary"): positive where this change helps.
    std::map<std::string, double> term_gain;
};

struct TuneProgress
{
    int evaluations = 0; ///< done so far
    int budget = 0;
    double best_fit = 0; ///< the best fit score so far
};

/// Evaluations a search spends unless told otherwise (`tune --budget`, the window's Fit): on two
/// cores about 7 s for B-Human's 46 annotated frames, where 300 left the held-out obstacles at
/// 0.00 and 3000 took them to 0.55 (issue 34's trial).
inline constexpr int kDefaultTuneBudget = 1500;

struct TuneOptions
{
    /// Stage ids whose parameters are searched; empty: every stage with parameters.
    std::vector<std::string> stages;
    int budget = kDefaultTuneBudget; ///< evaluations of a parameter set on the fit frames, at most
    std::uint64_t seed = 1;          ///< the same seed, stream and options give the same result
    /// The share of the scored frames held out (scored, never fitted), in [0, 0.9]. The frames
    /// are cut into contiguous blocks (neighbouring frames look alike, so they go together) and
    /// the seed picks the blocks held out. 0: every frame is fitted and nothing is held out.
    double holdout = 1.0 / 3.0;
    /// 2 or more: k-fold cross-validation instead of `holdout`. The frames are cut into this many
    /// contiguous blocks; each is scored with the parameters a search fitted on the others, so
    /// every frame is held out once, and the result is a search on every frame (k + 1 searches,
    /// each with the whole budget). 0: one held-out share.
    int folds = 0;
    /// The fit frames are cut into this many contiguous blocks, and a move is kept only when no
    /// block's score drops: a change that buys on some frames what it costs on others fits
    /// those frames, not the venue. 1: the total alone decides.
    int agree = 3;
    /// Weight of each term (a class name such as "ball", or "boundary"); unnamed terms weigh 1,
    /// a weight of 0 leaves a term out.
    std::map<std::string, double, std::less<>> weights;
    int threads = 0; ///< 0: one per core
    /// Keep what the first stages made of each frame while only later stages' parameters move
    /// (the same result either way, sooner; false for a test that checks that).
    bool reuse_stages = true;
    /// Let a parameter that sets a frame's cost (ParamInfo::work) go beyond twice its default's
    /// cost (samples up to 2x the default, spacings down to half).
    bool allow_costly = false;
    std::function<void(const TuneProgress&)> progress; ///< called on the calling thread
    const std::atomic<bool>* cancel = nullptr; ///< stops the search; the best so far is kept
};

struct TuneResult
{
    ParamSet start; ///< the parameters it started from (the stream's own, or the input's)
    /// What to save: the values that differ from the defaults, and every change (a value put
    /// back to its default is written too, so the file wins over the stream's own).
    ParamSet params;
    std::vector<TuneChange> changes; ///< pipeline order
    TuneScore start_fit;             ///< the start on the fit frames (every frame with folds)
    TuneScore tuned_fit;             ///< the result on the same frames
    TuneScore start_holdout;         ///< the start on the held-out frames
    /// The result on the held-out frames; with folds, each fold's frames scored with the
    /// parameters fitted without them (what the search's result is expected to reach).
    TuneScore tuned_holdout;
    int folds = 0; ///< the folds of the cross-validation (0: one held-out share)
    /// The start and the result on the validation streams' frames (TuneStream::validation):
    /// never fitted, never in a fold.
    TuneScore start_validation;
    TuneScore tuned_validation;
    std::vector<std::string> fit_frames;        ///< by name, in stream order
    std::vector<std::string> holdout_frames;    ///< by name, in stream order (fold by fold)
    std::vector<std::string> validation_frames; ///< "STREAM/NAME", in stream order
    int evaluations = 0;                        ///< of every search (the folds' too)
    /// The best fit score after each evaluation that improved it: (evaluations, score).
    std::vector<std::pair<int, double>> history;
    int parameters = 0; ///< parameters searched
    double seconds = 0; ///< wall-clock time of the search
    bool cancelled = false;
};

/// Checks `weights` names only scored classes (of `kinds`, the pipeline's scored kinds) and
/// "boundary", with weights >= 0.
Status checkTuneWeights(const std::map<std::string, double, std::less<>>& weights,
                        const std::vector<const PerceptKind*>& kinds = scoredKinds());

/// Another annotated stream fitted together with the first (tuneParams' `more`): more frames of
/// the same venue, each read and classified with its own stream's table.
struct TuneStream
{
    StreamInput* input = nullptr;
    const Annotations* truth = nullptr;
    std::string truth_path;
    /// Kept aside: every frame scored with the start and the result, none fitted (another game
    /// of the venue, to see whether what was fitted holds there).
    bool validation = false;
};

/// Reads the scored frames of `truth` from `input` once (into memory), then searches the
/// parameters of `options.stages` from input.params (the stream's own) to maximise the score
/// on the fit frames, scoring the held-out frames only for the report. Bad input (an unknown
/// stage, a bad weight, a frame the stream lacks, no scored frame) is an Error naming it.
Result<TuneResult> tuneParams(StreamInput& input, const Annotations& truth,
                              const std::string& truth_path, const TuneOptions& options);
/// tuneParams with `more` streams fitted together with the first: their scored frames are
/// fitted and held out with the first's (the same share of each stream, its blocks drawn with
/// seed + its place among the fitted streams), named "STREAM/NAME" in the result's lists; a
/// validation stream's frames are only scored (TuneResult's validation scores). They must start
/// from the same parameters and skip the same stages.
Result<TuneResult> tuneStreams(StreamInput& input, const Annotations& truth,
                               const std::string& truth_path, const TuneOptions& options,
                               const std::vector<TuneStream>& more);

/// Which of `frames` scored frames (in stream order) are held out: `share` of them, rounded to
/// whole contiguous blocks (six blocks, or one per frame when fewer; at least one block held out
/// and one fitted when share > 0 and there are two frames or more) picked by `seed`.
std::vector<bool> holdoutFrames(std::size_t frames, double share, std::uint64_t seed);

/// The parameters whose value differs from the default in `params`, every other dropped.
ParamSet differingFromDefaults(const ParamSet& params, const Pipeline& pipeline);

} // namespace fieldsight
