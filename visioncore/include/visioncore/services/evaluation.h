// Scoring detections against ground-truth annotations with the matching rules of SPEC §5.3, so
// every scorer (the eval command, tests, the GUI) agrees; and evaluating a whole stream.
#pragma once

#include "visioncore/io/annotations.h"
#include "visioncore/basics/geometry.h"
#include "visioncore/percepts/ball.h"
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

/// True positives, false positives and false negatives of one object class.
struct ClassScore
{
    int tp = 0; ///< detections matched to a true object
    int fp = 0; ///< detections left unmatched
    int fn = 0; ///< true objects left unmatched

    /// tp / (tp + fp), defined as 1 when there were no detections at all.
    double precision() const { return tp + fp == 0 ? 1.0 : double(tp) / double(tp + fp); }
    /// tp / (tp + fn), defined as 1 when there was nothing to find.
    double recall() const { return tp + fn == 0 ? 1.0 : double(tp) / double(tp + fn); }

    ClassScore& operator+=(const ClassScore& other)
    {
        tp += other.tp;
        fp += other.fp;
        fn += other.fn;
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

/// Horizontal intersection over union of two obstacles' inclusive column ranges, in [0, 1].
double horizontalIou(const Obstacle& a, const Obstacle& b);

/// The y of a polyline (x ascending) at column x, linearly interpolated, constant beyond its
/// ends. The polyline must not be empty.
double polylineYAt(const std::vector<PointF>& polyline, double x);

/// Mean |a(x) - b(x)| in px over x = 0..width-1, both polylines linearly interpolated (and held
/// constant beyond their ends). Returns a negative value when either polyline is empty.
double polylineMeanAbsDifference(const std::vector<PointF>& a, const std::vector<PointF>& b,
                                 int width);

/// Scores over a set of frames.
struct EvaluationScores
{
    std::size_t frames = 0;          ///< done frames scored
    std::size_t frames_not_done = 0; ///< annotated frames skipped because they are not done
    std::size_t frames_missing = 0;  ///< done frames without detections (scored as finding nothing)
    ClassScore balls;
    ClassScore goalposts;
    ClassScore obstacles;
    double boundary_error_sum = 0;   ///< px, sum over boundary_frames of the per-frame mean error
    std::size_t boundary_frames = 0; ///< frames where both boundaries exist

    /// px, mean over boundary_frames of the per-frame mean |y| difference; negative when none.
    double boundaryMeanError() const
    {
        return boundary_frames == 0 ? -1.0 : boundary_error_sum / double(boundary_frames);
    }
};

/// Scores one frame's detections against its true percepts (whether or not the frame is done).
/// Absent lists count as empty.
void scoreFrame(const PerceptSet& detected, const PerceptSet& truth, int width, int height,
                EvaluationScores& scores);

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

/// Balls, goalposts and obstacles (the kinds with a matching rule), in that order.
DetectionDelta compareDetections(const PerceptSet& before, const PerceptSet& after, int width,
                                 int height);

/// Scores every done frame of `truth` against `detected` (by frame name). Frames that are not done
/// are ignored; a done frame missing from `detected` is scored as if nothing was detected.
EvaluationScores evaluate(const std::map<std::string, PerceptSet>& detected,
                          const Annotations& truth, int width, int height);

/// annotations.json in the stream's folder (the folder itself, or the one holding the file).
std::string defaultTruthPath(const std::string& stream);

struct EvalReport
{
    std::string stream;
    std::string lut_path;
    std::string truth_path;
    EvaluationScores scores;
};

/// Runs the pipeline over the done frames of `truth` (found in the stream by name, or by name
/// without extension: a .strm names its frames frame_000000 where the PNG folder beside it has
/// frame_000000.png) and scores them. A done frame the stream lacks is bad input.
Result<EvalReport> evaluateStream(StreamInput& input, const Annotations& truth,
                                  const std::string& truth_path, int threads,
                                  const RunHooks& hooks = {});

} // namespace fieldsight
