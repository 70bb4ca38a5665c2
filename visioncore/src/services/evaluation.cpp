// Scoring detections against annotations (SPEC §5.3 and docs/formats.md): greedy one-to-one
// matching, nearest first, and the one path every scorer goes through, matchFrame().
#include "visioncore/services/evaluation.h"

#include "visioncore/percepts/field_boundary.h"

#include <algorithm>
#include <cmath>
#include <tuple>
#include <utility>

namespace fieldsight {
namespace {

/// A pair that satisfies a class's rule; `cost` orders the greedy matching (smaller first).
struct Candidate
{
    double cost = 0;
    std::size_t detection = 0;
    std::size_t truth = 0;
};

/// Accepts candidates nearest first, each detection and each true object at most once. Ties go
/// to the lower truth index, then the lower detection index, so the result is deterministic.
MatchResult greedyMatch(std::vector<Candidate> candidates, std::size_t detected_count,
                        std::size_t truth_count)
{
    std::sort(candidates.begin(), candidates.end(), [](const Candidate& a, const Candidate& b) {
        return std::tie(a.cost, a.truth, a.detection) < std::tie(b.cost, b.truth, b.detection);
    });
    std::vector<bool> detection_used(detected_count, false);
    std::vector<bool> truth_used(truth_count, false);
    MatchResult result;
    for (const Candidate& c : candidates) {
        if (detection_used[c.detection] || truth_used[c.truth])
            continue;
        detection_used[c.detection] = true;
        truth_used[c.truth] = true;
        result.pairs.push_back({c.detection, c.truth});
    }
    result.score.tp = int(result.pairs.size());
    result.score.fp = int(detected_count) - result.score.tp;
    result.score.fn = int(truth_count) - result.score.tp;
    return result;
}

} // namespace

MatchResult matchBalls(const std::vector<Ball>& detected, const std::vector<Ball>& truth)
{
    std::vector<Candidate> candidates;
    for (std::size_t t = 0; t < truth.size(); ++t) {
        const double limit = std::max(3.0, 0.5 * truth[t].radius);
        for (std::size_t d = 0; d < detected.size(); ++d) {
            const double distance =
                std::hypot(detected[d].x - truth[t].x, detected[d].y - truth[t].y);
            if (distance <= limit)
                candidates.push_back({distance, d, t});
        }
    }
    return greedyMatch(std::move(candidates), detected.size(), truth.size());
}

MatchResult matchGoalposts(const std::vector<Goalpost>& detected,
                           const std::vector<Goalpost>& truth, int image_height)
{
    std::vector<Candidate> candidates;
    for (std::size_t t = 0; t < truth.size(); ++t) {
        const Goalpost& post = truth[t];
        const double centre_x = 0.5 * (post.left + post.right);
        const double base_limit = std::max(4.0, double(post.right - post.left + 1));
        const double height = double(post.bottom - post.top + 1);
        const double bottom_limit = std::max(6.0, 0.1 * height);
        const bool touches_bottom = post.bottom >= image_height - 1;
        for (std::size_t d = 0; d < detected.size(); ++d) {
            const double base_distance = std::abs(detected[d].base_x - centre_x);
            if (base_distance > base_limit)
                continue;
            if (!touches_bottom && std::abs(detected[d].bottom - post.bottom) > bottom_limit)
                continue;
            candidates.push_back({base_distance, d, t});
        }
    }
    return greedyMatch(std::move(candidates), detected.size(), truth.size());
}

double horizontalIou(const Obstacle& a, const Obstacle& b)
{
    const int overlap = std::max(0, std::min(a.right, b.right) - std::max(a.left, b.left) + 1);
    const int union_width = (a.right - a.left + 1) + (b.right - b.left + 1) - overlap;
    return union_width <= 0 ? 0.0 : double(overlap) / double(union_width);
}

MatchResult matchObstacles(const std::vector<Obstacle>& detected,
                           const std::vector<Obstacle>& truth)
{
    std::vector<Candidate> candidates;
    for (std::size_t t = 0; t < truth.size(); ++t) {
        for (std::size_t d = 0; d < detected.size(); ++d) {
            const double iou = horizontalIou(detected[d], truth[t]);
            if (iou >= 0.3)
                candidates.push_back({-iou, d, t}); // the highest overlap is the nearest
        }
    }
    return greedyMatch(std::move(candidates), detected.size(), truth.size());
}

double fieldLineMatchCost(const FieldLine& a, const FieldLine& b)
{
    const double length_a = std::hypot(a.x2 - a.x1, a.y2 - a.y1);
    const double length_b = std::hypot(b.x2 - b.x1, b.y2 - b.y1);
    // Ties go to the first argument as the longer one: the rule is symmetric all the same.
    const FieldLine& longer = length_a >= length_b ? a : b;
    const FieldLine& shorter = length_a >= length_b ? b : a;
    const double length = std::max(length_a, length_b);
    const double limit = std::max(4.0, 0.05 * length);
    if (length < 1e-9) // two points
        return std::hypot(a.x1 - b.x1, a.y1 - b.y1) <= limit ? std::hypot(a.x1 - b.x1, a.y1 - b.y1)
                                                             : -1.0;
    const double ux = (longer.x2 - longer.x1) / length;
    const double uy = (longer.y2 - longer.y1) / length;
    // Along and across the longer segment, from its first end.
    const auto along = [&](double x, double y) {
        return (x - longer.x1) * ux + (y - longer.y1) * uy;
    };
    const auto across = [&](double x, double y) {
        return std::abs((x - longer.x1) * uy - (y - longer.y1) * ux);
    };
    const double d1 = across(shorter.x1, shorter.y1);
    const double d2 = across(shorter.x2, shorter.y2);
    if (d1 > limit || d2 > limit)
        return -1.0;
    const double t1 = along(shorter.x1, shorter.y1);
    const double t2 = along(shorter.x2, shorter.y2);
    const double lo = std::min(t1, t2);
    const double hi = std::max(t1, t2);
    const double overlap = std::min(hi, length) - std::max(lo, 0.0);
    // A point-like shorter segment must lie within the longer one's extent.
    const bool overlaps = hi - lo < 1e-9 ? lo >= 0 && lo <= length : overlap >= 0.5 * (hi - lo);
    return overlaps ? 0.5 * (d1 + d2) : -1.0;
}

MatchResult matchFieldLines(const std::vector<FieldLine>& detected,
                            const std::vector<FieldLine>& truth)
{
    std::vector<Candidate> candidates;
    for (std::size_t t = 0; t < truth.size(); ++t)
        for (std::size_t d = 0; d < detected.size(); ++d)
            if (const double cost = fieldLineMatchCost(detected[d], truth[t]); cost >= 0)
                candidates.push_back({cost, d, t});
    return greedyMatch(std::move(candidates), detected.size(), truth.size());
}

double polylineYAt(const std::vector<PointF>& polyline, double x)
{
    if (x <= polyline.front().x)
        return polyline.front().y;
    if (x >= polyline.back().x)
        return polyline.back().y;
    // The first vertex strictly right of x; the one before it is at or left of x.
    const auto right = std::upper_bound(polyline.begin(), polyline.end(), x,
                                        [](double value, const PointF& p) { return value < p.x; });
    const PointF& b = *right;
    const PointF& a = *(right - 1);
    if (b.x == a.x)
        return b.y;
    return a.y + (b.y - a.y) * (x - a.x) / (b.x - a.x);
}

double polylineMeanAbsDifference(const std::vector<PointF>& a, const std::vector<PointF>& b,
                                 int width)
{
    if (a.empty() || b.empty() || width <= 0)
        return -1.0;
    double sum = 0;
    for (int x = 0; x < width; ++x)
        sum += std::abs(polylineYAt(a, x) - polylineYAt(b, x));
    return sum / double(width);
}

const std::vector<const PerceptKind*>& scoredKinds()
{
    static const std::vector<const PerceptKind*> kinds{
        &perceptKind<Ball>(), &perceptKind<Goalpost>(), &perceptKind<Obstacle>(),
        &perceptKind<FieldLine>()};
    return kinds;
}

std::string scoredClassName(const PerceptKind& kind)
{
    const char* names[] = {"ball", "goalpost", "obstacle", "field_line"};
    const std::vector<const PerceptKind*>& kinds = scoredKinds();
    for (std::size_t k = 0; k < kinds.size(); ++k)
        if (kinds[k]->key == kind.key)
            return names[k];
    return std::string(kind.key);
}

const PerceptKind& boundaryKind()
{
    return perceptKind<FieldBoundary>();
}

namespace {

/// The rule of scoredKinds()[k] applied to the two sets' lists of that kind.
MatchResult matchKind(std::size_t k, const PerceptSet& detected, const PerceptSet& truth,
                      int height)
{
    switch (k) {
    case 0:
        return matchBalls(detected.list<Ball>(), truth.list<Ball>());
    case 1:
        return matchGoalposts(detected.list<Goalpost>(), truth.list<Goalpost>(), height);
    case 2:
        return matchObstacles(detected.list<Obstacle>(), truth.list<Obstacle>());
    default:
        return matchFieldLines(detected.list<FieldLine>(), truth.list<FieldLine>());
    }
}

std::size_t listSize(const PerceptSet& set, const PerceptKind& kind)
{
    const PerceptEntry* e = set.find(kind);
    return e && e->present() ? e->size() : 0;
}

/// matchFrame() with `marks` (null: every kind complete, no object concealed).
FrameMatch matchFrameWith(const PerceptSet& detected, const PerceptSet& truth,
                          const FrameAnnotation* marks, int width, int height)
{
    FrameMatch frame;
    const std::vector<const PerceptKind*>& kinds = scoredKinds();
    for (std::size_t k = 0; k < kinds.size(); ++k) {
        const PerceptKind& kind = *kinds[k];
        if (marks && !marks->complete(kind.truth_key))
            continue;
        const MatchResult match = matchKind(k, detected, truth, height);
        KindMatch m;
        m.kind = &kind;
        m.pairs = match.pairs;
        const std::size_t detected_count = listSize(detected, kind);
        const std::size_t truth_count = listSize(truth, kind);
        std::vector<bool> detection_used(detected_count, false);
        std::vector<bool> truth_used(truth_count, false);
        const auto concealed = [&](std::size_t t) {
            return marks && marks->flagsOf(kind.truth_key, t).concealed;
        };
        for (const MatchPair& pair : match.pairs) {
            detection_used[pair.detection] = true;
            truth_used[pair.truth] = true;
            ++(concealed(pair.truth) ? m.score.concealed_found : m.score.tp);
        }
        for (std::size_t d = 0; d < detected_count; ++d)
            if (!detection_used[d])
                m.false_detections.push_back(d);
        for (std::size_t t = 0; t < truth_count; ++t)
            if (!truth_used[t])
                (concealed(t) ? m.concealed_missed : m.missed).push_back(t);
        m.score.fp = int(m.false_detections.size());
        m.score.fn = int(m.missed.size());
        m.score.concealed_missed = int(m.concealed_missed.size());
        frame.kinds.push_back(std::move(m));
    }
    if (!marks || marks->complete(boundaryKind().truth_key))
        frame.boundary_error =
            polylineMeanAbsDifference(boundaryOf(detected), boundaryOf(truth), width);
    return frame;
}

} // namespace

bool FrameMatch::disagrees() const
{
    return std::any_of(kinds.begin(), kinds.end(), [](const KindMatch& k) {
        return !k.false_detections.empty() || !k.missed.empty();
    });
}

FrameMatch matchFrame(const PerceptSet& detected, const FrameAnnotation& truth, int width,
                      int height)
{
    return matchFrameWith(detected, truth.truth, &truth, width, height);
}

ClassScore* EvaluationScores::of(const PerceptKind& kind)
{
    return const_cast<ClassScore*>(std::as_const(*this).of(kind));
}

const ClassScore* EvaluationScores::of(const PerceptKind& kind) const
{
    const std::vector<const PerceptKind*>& kinds = scoredKinds();
    const ClassScore* scores[] = {&balls, &goalposts, &obstacles, &field_lines};
    for (std::size_t k = 0; k < kinds.size(); ++k)
        if (kinds[k]->key == kind.key)
            return scores[k];
    return nullptr;
}

std::vector<std::pair<const PerceptKind*, ClassScore>> EvaluationScores::classes() const
{
    std::vector<std::pair<const PerceptKind*, ClassScore>> out;
    for (const PerceptKind* kind : scoredKinds())
        out.emplace_back(kind, *of(*kind));
    return out;
}

void EvaluationScores::add(const FrameMatch& frame)
{
    for (const KindMatch& k : frame.kinds)
        *of(*k.kind) += k.score;
    if (frame.boundary_error >= 0) {
        boundary_error_sum += frame.boundary_error;
        ++boundary_frames;
    }
}

void scoreFrame(const PerceptSet& detected, const PerceptSet& truth, int width, int height,
                EvaluationScores& scores)
{
    ++scores.frames;
    scores.add(matchFrameWith(detected, truth, nullptr, width, height));
}

KindDelta DetectionDelta::of(std::string_view key) const
{
    for (const KindDelta& k : kinds)
        if (k.kind->key == key)
            return k;
    return {};
}

int DetectionDelta::appeared() const
{
    int n = 0;
    for (const KindDelta& k : kinds)
        n += k.appeared;
    return n;
}

int DetectionDelta::vanished() const
{
    int n = 0;
    for (const KindDelta& k : kinds)
        n += k.vanished;
    return n;
}

DetectionDelta& DetectionDelta::operator+=(const DetectionDelta& other)
{
    for (const KindDelta& o : other.kinds) {
        const auto it = std::find_if(kinds.begin(), kinds.end(), [&](const KindDelta& k) {
            return k.kind->key == o.kind->key;
        });
        if (it == kinds.end()) {
            kinds.push_back(o);
        } else {
            it->appeared += o.appeared;
            it->vanished += o.vanished;
        }
    }
    return *this;
}

bool operator==(const DetectionDelta& a, const DetectionDelta& b)
{
    const auto covers = [](const DetectionDelta& x, const DetectionDelta& y) {
        return std::all_of(x.kinds.begin(), x.kinds.end(), [&](const KindDelta& k) {
            const KindDelta other = y.of(k.kind->key);
            return k.appeared == other.appeared && k.vanished == other.vanished;
        });
    };
    return covers(a, b) && covers(b, a);
}

DetectionDelta compareDetections(const PerceptSet& before, const PerceptSet& after, int width,
                                 int height)
{
    // The run before plays the truth: a detection after the edit that nothing before matches
    // appeared (a false positive); one before that nothing after matches vanished (a miss).
    const FrameMatch match = matchFrameWith(after, before, nullptr, width, height);
    DetectionDelta delta;
    for (const KindMatch& k : match.kinds)
        delta.kinds.push_back({k.kind, k.score.fp, k.score.fn});
    return delta;
}

bool isScored(const FrameAnnotation& annotation)
{
    if (annotation.done)
        return true;
    for (const PerceptKind* kind : scoredKinds())
        if (annotation.complete(kind->truth_key))
            return true;
    return annotation.complete(boundaryKind().truth_key);
}

Evaluation evaluateFrames(const std::map<std::string, PerceptSet>& detected,
                          const Annotations& truth, int width, int height)
{
    Evaluation evaluation;
    EvaluationScores& scores = evaluation.scores;
    const PerceptSet nothing;
    for (const auto& [name, annotation] : truth.frames) {
        if (!annotation.done)
            ++scores.frames_not_done;
        if (!isScored(annotation))
            continue;
        ++(annotation.done ? scores.frames : scores.frames_reviewed);
        const auto it = detected.find(name);
        if (it == detected.end())
            ++scores.frames_missing;
        const FrameMatch match =
            matchFrame(it == detected.end() ? nothing : it->second, annotation, width, height);
        scores.add(match);
        for (const KindMatch& k : match.kinds)
            if (!k.false_detections.empty() || !k.missed.empty())
                evaluation.disagreements.push_back({name, k.kind, k.false_detections, k.missed});
    }
    return evaluation;
}

EvaluationScores evaluate(const std::map<std::string, PerceptSet>& detected,
                          const Annotations& truth, int width, int height)
{
    return evaluateFrames(detected, truth, width, height).scores;
}

} // namespace fieldsight
