// What the parameter search needs beside the search itself: the scored frames held in memory,
// their split into fit and held-out frames, and scoring one parameter set on some of them.
#pragma once

#include "visioncore/datawrappers/memory_data_wrapper.h"
#include "visioncore/framework/control_wrapper.h"
#include "visioncore/services/param_tuning.h"

#include <memory>
#include <string>
#include <vector>

namespace fieldsight::tuning {

/// One scored frame, decoded once.
struct HeldFrame
{
    std::size_t index = 0; ///< in the stream
    std::string name;      ///< in the annotations
    Frame frame;
    const FrameAnnotation* truth = nullptr; ///< into the annotations the search was given
    /// The table of the frame's stream (tuneParams' `more`); null: the first stream's.
    std::shared_ptr<const ColourLut> lut;
};

/// Reads every scored frame of `truth` from `input` (on the input's workers) in stream order.
Result<std::vector<HeldFrame>> readScoredFrames(StreamInput& input, const Annotations& truth,
                                                const std::string& truth_path, int threads);

/// What a scored frame is for in a search.
enum class FrameRole {
    Fit,        ///< the search maximises the score on it
    Held,       ///< held out of a fitted stream: scored for the report
    Validation, ///< a stream kept aside (TuneStream::validation): scored for the report
};

/// The scored frames of `input` and of each of `more` streams, the first's first, and what each
/// is for: of a fitted stream, held out or not (none held with `folds`; else the same share of
/// each stream, its blocks drawn with options.seed + its place); of a validation stream, every
/// frame Validation. Another stream's frames keep its table and are named "STREAM/NAME"; every
/// stream must start from the first's parameters and skip its stages.
Result<std::pair<std::vector<HeldFrame>, std::vector<FrameRole>>>
readStreams(StreamInput& input, const Annotations& truth, const std::string& truth_path,
            const TuneOptions& options, const std::vector<TuneStream>& more, bool folds);

/// The raw counts behind a TuneScore, which add up over frames.
struct Tally
{
    std::map<std::string, ClassScore> classes; ///< by scoredClassName
    std::vector<double> boundary;              ///< px, each frame's boundary error where scored
    std::size_t frames = 0;
    double core_ms = 0; ///< the stages' time on the frames run whole (wall clock)
    std::size_t timed_frames = 0;
    Tally& operator+=(const Tally& other);
};

/// The score of `tally` with `weights` (TuneScore's rule).
TuneScore scoreOf(const Tally& tally, const std::map<std::string, double, std::less<>>& weights);

/// One core that scores parameter sets: a pipeline and its DataWrapper, owned by one thread.
class Scorer
{
public:
    /// `reuse`: keep what the first stages made of each frame while their parameters stay.
    Scorer(const StreamInput& input, bool reuse);
    /// The score of `params` (every value the core needs beside the defaults) on the frames of
    /// `frames` at `positions`. Throws std::invalid_argument on a value the core refuses.
    /// `split` > 0: `params` moves no parameter of the stages before position `split` from the
    /// last call's with the same split, so what those stages made of each frame is reused
    /// (kept from the first call that ran them, when `reuse`).
    Tally tally(const ParamSet& params, const std::vector<HeldFrame>& frames,
                const std::vector<std::size_t>& positions, std::size_t split = 0);
    /// The same, one Tally per position.
    std::vector<Tally> tallies(const ParamSet& params, const std::vector<HeldFrame>& frames,
                               const std::vector<std::size_t>& positions, std::size_t split = 0);

private:
    /// The values of every parameter of the stages before `split`, as text.
    std::string prefixKey(std::size_t split) const;

    std::shared_ptr<const ColourLut> m_lut; ///< the first stream's
    MemoryDataWrapper m_data;
    std::unique_ptr<ControlWrapper> m_control;
    std::vector<const PerceptKind*> m_kinds; ///< the pipeline's scored kinds
    bool m_reuse = true;
    std::size_t m_split = 0;                  ///< of the kept blackboards
    std::string m_key;                        ///< prefixKey(m_split) they were made with
    std::map<std::size_t, Blackboard> m_kept; ///< by frame position, after stages [0, m_split)
};

} // namespace fieldsight::tuning
