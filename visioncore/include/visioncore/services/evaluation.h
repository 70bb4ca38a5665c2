// Scoring detections against ground-truth annotations with the matching rules of SPEC §5.3 (and
// the field line rule of docs/formats.md), so every scorer (the eval command, the window's
// evaluation, the edit-effect scan, tests) agrees: one matching path, matchFrame(); and
// evaluating a whole stream.
#pragma once

#include "visioncore/io/annotations.h"
#include "visioncore/basics/geometry.h"
#include "visioncore/percepts/ball.h"
#include "visioncore/percepts/field_line.h"
#include "visioncore/percepts/goalpost.h"
#include "visioncore/percepts/obstacle.h"
#include "visioncore/percepts/percept_set.h"
#include "visioncore/services/stream_runner.h"

#include <cstddef>
#include <map>
#include <string>
#include <string_view>
#include <vector>

namespace fieldsight {

/// True positives, false positives and false negatives of one object class. A concealed true
/// object (ObjectFlags::concealed) is counted apart: found, its detection is neither a true nor a
/// false positive; missed, it is no false negative.
struct ClassScore
{
    int tp = 0;               ///< detections matched to a true object
    int fp = 0;               ///< detections left unmatched
    int fn = 0;               ///< true objects left unmatched
    int concealed_found = 0;  ///< concealed true objects matched by a detection
    int concealed_missed = 0; ///< concealed true objects left unmatched

    /// tp / (tp + fp), defined as 1 when there were no detections at all.
    double precision() const { return tp + fp == 0 ? 1.0 : double(tp) / double(tp + fp); }
    /// tp / (tp + fn), defined as 1 when there was nothing to find.
    double recall() const { return tp + fn == 0 ? 1.0 : double(tp) / double(tp + fn); }

    ClassScore& operator+=(const ClassScore& other)
    {
        tp += other.tp;
        fp += other.fp;
        fn += other.fn;
        concealed_found += other.concealed_found;
        concealed_missed += other.concealed_missed;
        return *this;
    }
    friend bool operator==(const ClassScore&, const ClassScore&) = default;
};

/// One accepted pairing of a detection with a true object (indices into the two lists).
struct MatchPair
{
    std::size_t detection = 0;
    std::size_t truth = 0;
    friend bool operator==(const MatchPair&, const MatchPair&) = default;
};

/// The pairs chosen by greedy one-to-one matching, nearest first, and the score they give.
struct MatchResult
{
    std::vector<MatchPair> pairs; ///< in the order they were accepted (nearest first)
    ClassScore score;
};

/// Each kind's rule is its PerceptTraits::matchCost (percepts/ball.h and the others); these
/// match two lists of one kind by it, greedily, nearest first.
///
/// Balls match when the centre distance is <= max(3 px, 0.5 x true radius); nearest first.
MatchResult matchBalls(const std::vector<Ball>& detected, const std::vector<Ball>& truth);

/// Goalposts match when |detected base_x - true (left+right)/2| <= max(4 px, true right-left+1)
/// and the detected bottom is within max(6 px, 10% of the true height) of the true bottom, the
/// latter waived when the true post touches the image bottom (bottom >= image_height-1). Nearest
/// (smallest base_x distance) first.
MatchResult matchGoalposts(const std::vector<Goalpost>& detected,
                           const std::vector<Goalpost>& truth, int image_height);

/// Obstacles match when their horizontal overlap / horizontal union (inclusive columns) is
/// >= 0.3; the highest ratio first.
MatchResult matchObstacles(const std::vector<Obstacle>& detected,
                           const std::vector<Obstacle>& truth);

/// Field lines match by fieldLineMatchCost(); the smallest cost first.
MatchResult matchFieldLines(const std::vector<FieldLine>& detected,
                            const std::vector<FieldLine>& truth);

/// The y of a polyline (x ascending) at column x, linearly interpolated, constant beyond its
/// ends. The polyline must not be empty.
double polylineYAt(const std::vector<PointF>& polyline, double x);

/// Mean |a(x) - b(x)| in px over x = 0..width-1, both polylines linearly interpolated (and held
/// constant beyond their ends). Returns a negative value when either polyline is empty.
double polylineMeanAbsDifference(const std::vector<PointF>& a, const std::vector<PointF>& b,
                                 int width);

/// The kinds of `kinds` (a pipeline's perceptKinds()) with a matching rule (PerceptKind::match),
/// in the order every score lists them: by PerceptKind::class_order, then as in `kinds`.
std::vector<const PerceptKind*> scoredKinds(const std::vector<const PerceptKind*>& kinds);
/// scoredKinds() of the standard pipeline: balls, goalposts, obstacles, field lines.
const std::vector<const PerceptKind*>& scoredKinds();
/// The name `eval` and `compare` key a scored kind's class with in their JSON
/// (PerceptKind::class_name: "ball", "goalpost", "obstacle", "field_line"); another kind's
/// results key.
std::string scoredClassName(const PerceptKind& kind);
/// The same name as text tables print it: "_" a space ("field line").
std::string scoredClassText(const PerceptKind& kind);
/// The kind scored by its boundary error (SPEC §5.3) instead of matching: the field boundary.
const PerceptKind& boundaryKind();

/// One kind's matching on one frame (indices into the frame's detected and true lists).
struct KindMatch
{
    const PerceptKind* kind = nullptr;
    std::vector<MatchPair> pairs;              ///< in the order accepted (plain objects, then
                                               ///< concealed ones, each nearest first)
    ClassScore score;                          ///< concealed objects counted apart
    std::vector<std::size_t> false_detections; ///< detections nothing true matches, ascending
    std::vector<std::size_t> missed;           ///< true objects, not concealed, nothing matches
    std::vector<std::size_t> concealed_missed; ///< concealed true objects nothing matches
};

/// One frame's matching: a KindMatch for each scored kind (`kinds`, in order) whose truth is
/// complete on the frame, and the boundary error when the boundary's is and both exist.
struct FrameMatch
{
    std::vector<KindMatch> kinds;
    double boundary_error = -1; ///< px, mean |y| difference; negative when not scored
    /// A miss (of an object not concealed) or a false detection in some kind.
    bool disagrees() const;
};

/// Matches one frame: only the kinds of `kinds` (scoredKinds() of the pipeline that made the
/// detections) whose list is complete on it (`truth.complete(key)`: the frame is done, or the
/// kind reviewed) are scored; the others' detections are ignored. Absent lists count as empty.
/// THE matching path: evaluate(), scoreFrame() and compareDetections() go through it.
FrameMatch matchFrame(const PerceptSet& detected, const FrameAnnotation& truth, int width,
                      int height, const std::vector<const PerceptKind*>& kinds = scoredKinds());

/// Scores over a set of frames, kind by kind.
struct EvaluationScores
{
    /// Lists the standard pipeline's scoredKinds(), nothing counted.
    EvaluationScores();
    /// Lists `kinds` (scored kinds, in the order scores list them), nothing counted.
    explicit EvaluationScores(const std::vector<const PerceptKind*>& kinds);

    std::size_t frames = 0;          ///< done frames scored
    std::size_t frames_not_done = 0; ///< annotated frames that are not done
    /// Of frames_not_done, those scored for their reviewed kinds only (FrameAnnotation::reviewed).
    std::size_t frames_reviewed = 0;
    std::size_t frames_missing = 0;  ///< scored frames without detections (scored as finding none)
    double boundary_error_sum = 0;   ///< px, sum over boundary_frames of the per-frame mean error
    std::size_t boundary_frames = 0; ///< frames where both boundaries exist

    /// px, mean over boundary_frames of the per-frame mean |y| difference; negative when none.
    double boundaryMeanError() const
    {
        return boundary_frames == 0 ? -1.0 : boundary_error_sum / double(boundary_frames);
    }
    /// The score of `kind`; null when it is not listed.
    const ClassScore* find(const PerceptKind& kind) const;
    /// The score of `kind`, listed last (nothing counted) when it was not.
    ClassScore& operator[](const PerceptKind& kind);
    /// The score of `kind`; nothing counted when it is not listed.
    const ClassScore& of(const PerceptKind& kind) const;
    template <class P> const ClassScore& of() const { return of(perceptKind<P>()); }
    template <class P> ClassScore& of() { return (*this)[perceptKind<P>()]; }
    /// Every listed kind with its score, in order (for readers that name no kind).
    const std::vector<std::pair<const PerceptKind*, ClassScore>>& classes() const
    {
        return m_classes;
    }
    /// Adds one frame's matching (the frame counters are the caller's).
    void add(const FrameMatch& frame);

private:
    std::vector<std::pair<const PerceptKind*, ClassScore>> m_classes;
};

/// Scores one frame's detections against its true percepts (whether or not the frame is done:
/// every kind counts as complete, no object as concealed). Absent lists count as empty.
void scoreFrame(const PerceptSet& detected, const PerceptSet& truth, int width, int height,
                EvaluationScores& scores,
                const std::vector<const PerceptKind*>& kinds = scoredKinds());

/// One percept kind's part of a DetectionDelta.
struct KindDelta
{
    const PerceptKind* kind = nullptr; ///< from the percept registry (perceptKind<P>())
    int appeared = 0;                  ///< detections of the run after that nothing before matches
    int vanished = 0;                  ///< detections of the run before that nothing after matches
};

/// What changed between two runs of one frame (before and after a LUT edit), by the same
/// matching rules, the run before playing the truth: a detection of `after` that nothing in
/// `before` matches appeared; one of `before` that nothing in `after` matches vanished. Per
/// percept kind, so a new kind with a matching rule needs no change here or in its readers.
struct DetectionDelta
{
    /// compareDetections gives every kind it compares, always in the same order (so sums of
    /// its results keep that order); a kind not listed counts as nothing changed.
    std::vector<KindDelta> kinds;

    /// The counts of the kind with results key `key` (PerceptKind::key, e.g. "balls"); zero
    /// counts when it is not listed.
    KindDelta of(std::string_view key) const;
    int appeared() const;
    int vanished() const;
    /// Adds `other`'s counts kind by kind (a kind new to this one is appended).
    DetectionDelta& operator+=(const DetectionDelta& other);
    /// The same counts for every kind (an unlisted kind counting as zero).
    friend bool operator==(const DetectionDelta& a, const DetectionDelta& b);
};

/// Every kind of `kinds` (scored kinds, in that order), the run before playing the truth.
DetectionDelta compareDetections(const PerceptSet& before, const PerceptSet& after, int width,
                                 int height,
                                 const std::vector<const PerceptKind*>& kinds = scoredKinds());

/// A scored frame where the detections and the truth disagree in one kind: the detections
/// nothing true matches and the true objects (not concealed) nothing detected matches.
struct FrameDisagreement
{
    std::string frame; ///< the frame's name in the annotations
    const PerceptKind* kind = nullptr;
    std::vector<std::size_t> false_detections; ///< indices into the frame's detected list
    std::vector<std::size_t> missed;           ///< indices into the frame's true list
};

/// The scores and where they come from.
struct Evaluation
{
    EvaluationScores scores;
    /// By frame name (the annotations' order), then kind (in the scores' order).
    std::vector<FrameDisagreement> disagreements;
};

/// Whether `annotation` has anything to score: it is done, or some kind of `kinds` (scored
/// kinds) or the boundary is reviewed.
bool isScored(const FrameAnnotation& annotation,
              const std::vector<const PerceptKind*>& kinds = scoredKinds());

/// Scores every scored frame of `truth` (isScored) against `detected` (by frame name), each kind
/// of `kinds` (scored kinds, all of them listed in the scores) only where its truth is complete;
/// other frames are ignored. A scored frame missing from `detected` is scored as if nothing was
/// detected.
Evaluation evaluateFrames(const std::map<std::string, PerceptSet>& detected,
                          const Annotations& truth, int width, int height,
                          const std::vector<const PerceptKind*>& kinds = scoredKinds());
/// evaluateFrames(...).scores
EvaluationScores evaluate(const std::map<std::string, PerceptSet>& detected,
                          const Annotations& truth, int width, int height,
                          const std::vector<const PerceptKind*>& kinds = scoredKinds());

/// annotations.json in the stream's folder (the folder itself, or the one holding the file).
std::string defaultTruthPath(const std::string& stream);

struct EvalReport
{
    std::string stream;
    std::string lut_path;
    std::string truth_path;
    EvaluationScores scores;
    std::vector<FrameDisagreement> disagreements;   ///< as Evaluation's
    std::map<std::string, std::size_t> frame_index; ///< each scored frame's index in the stream
    std::map<std::string, PerceptSet> detected;     ///< each scored frame's detections
};

/// The stream index of every scored frame of `truth` (isScored), by name, else by name without
/// extension (a .strm names its frames frame_000000 where the PNG folder beside it has
/// frame_000000.png). A scored frame the stream lacks is an Error naming `truth_path`.
Result<std::map<std::string, std::size_t>> scoredFrameIndices(const StreamInput& input,
                                                              const Annotations& truth,
                                                              const std::string& truth_path);

/// Runs the pipeline (`input.pipeline`) over the scored frames of `truth` (scoredFrameIndices) and
/// scores them, every scored kind of that pipeline. A
/// scored frame the stream lacks is bad input; a cancelled run is an Error.
Result<EvalReport> evaluateStream(StreamInput& input, const Annotations& truth,
                                  const std::string& truth_path, int threads,
                                  const RunHooks& hooks = {});
/// The same, but a scored frame whose detections `known` holds (by its name in `truth`; made
/// with the same table and settings) is not run again: a change of the truth alone is scored
/// without running the pipeline on the frames scored before. `frames_run`, when given, is set
/// to the frames the pipeline ran.
Result<EvalReport> evaluateStream(StreamInput& input, const Annotations& truth,
                                  const std::string& truth_path, int threads, const RunHooks& hooks,
                                  const std::map<std::string, PerceptSet>& known,
                                  std::size_t* frames_run = nullptr);

} // namespace fieldsight
