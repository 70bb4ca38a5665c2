// A/B comparison of two colour tables or two parameter sets over one stream: the pipeline runs
// twice over the scored frames (those `eval` scores), each frame is matched by matchFrame() (the
// one matching path of `eval` and the window: concealed objects apart, reviewed kinds, field
// lines), and per class the frames that got fixed or broken are listed. The command line
// (`fieldsight compare`) and the window's dialog both drive it.
#pragma once

#include "visioncore/io/annotations.h"
#include "visioncore/services/evaluation.h"
#include "visioncore/services/stream_runner.h"

#include <cstddef>
#include <memory>
#include <string>
#include <vector>

namespace fieldsight {

/// The second side of a comparison: what differs from the first (the StreamInput's table and
/// parameters). The stream, the skipped stages and the truth are shared.
struct AbSide
{
    std::string lut_path; ///< for reports (empty: the same table as A)
    std::shared_ptr<const ColourLut> lut;
    std::string params_path; ///< for reports (empty: no parameter file)
    ParamSet params;
};

/// One frame where a class was scored, with each side's score of that frame.
struct AbFrame
{
    std::size_t index = 0; ///< in the stream
    std::string name;      ///< as the annotations name it
    ClassScore a;
    ClassScore b;

    /// Misses (of objects not concealed) and false detections.
    static int errors(const ClassScore& s) { return s.fp + s.fn; }
};

/// One class (a percept kind with a matching rule) over the frames where its truth is complete.
struct AbClass
{
    const PerceptKind* kind = nullptr; ///< from the percept registry
    std::string name;                  ///< as `eval` names the class (scoredClassName)
    std::size_t frames = 0;            ///< frames where the class's truth is complete
    ClassScore a;                      ///< summed over those frames
    ClassScore b;
    std::vector<AbFrame> fixed;  ///< fewer errors (misses, false) with B than A; by frame index
    std::vector<AbFrame> broken; ///< more errors with B than with A; by frame index
    std::size_t wrong_both = 0;  ///< frames with as many errors, some, on both sides
};

struct AbComparison
{
    std::size_t frames = 0; ///< scored frames (isScored: done, or some kind reviewed)
    std::vector<AbClass> classes;
    /// The field boundary's mean error over the frames where its truth is complete and both
    /// boundaries exist (EvaluationScores::boundaryMeanError; negative: none).
    double boundary_a = -1;
    double boundary_b = -1;
    std::size_t boundary_frames_a = 0;
    std::size_t boundary_frames_b = 0;
    bool cancelled = false; ///< then nothing else is filled in
};

/// Runs `input` (side A: its table and parameters) and then side `b` over the scored frames of
/// `truth` (scoredFrameIndices: a scored frame the stream lacks is an Error naming `truth_path`)
/// and compares them. Progress counts both runs (2 x frames); a cancel ends with
/// `cancelled` set. Bad input (a frame that cannot be read) is an Error.
Result<AbComparison> compareAb(StreamInput& input, const AbSide& b, const Annotations& truth,
                               const std::string& truth_path, int threads,
                               const RunHooks& hooks = {});

} // namespace fieldsight
