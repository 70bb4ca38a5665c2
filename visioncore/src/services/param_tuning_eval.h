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
};

/// Reads every scored frame of `truth` from `input` (on the input's workers) in stream order.
Result<std::vector<HeldFrame>> readScoredFrames(StreamInput& input, const Annotations& truth,
                                                const std::string& truth_path, int threads);

/// One core that scores parameter sets: a pipeline and its DataWrapper, owned by one thread.
class Scorer
{
public:
    Scorer(const StreamInput& input);
    /// The score of `params` (every value the core needs beside the defaults) on the frames of
    /// `frames` at `positions`. Throws std::invalid_argument on a value the core refuses.
    TuneScore score(const ParamSet& params, const std::vector<HeldFrame>& frames,
                    const std::vector<std::size_t>& positions,
                    const std::map<std::string, double, std::less<>>& weights);

private:
    MemoryDataWrapper m_data;
    std::unique_ptr<ControlWrapper> m_control;
};

} // namespace fieldsight::tuning
