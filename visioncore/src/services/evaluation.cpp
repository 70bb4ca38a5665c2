// Scoring detections against annotations (SPEC §5.3 and docs/formats.md): greedy one-to-one
// matching, nearest first, and the one path every scorer goes through, matchFrame().
#include "visioncore/services/evaluation.h"

#include "visioncore/framework/controller.h"
#include "visioncore/percepts/field_boundary.h"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <optional>
#include <tuple>
#include <utility>

namespace fieldsight {
namespace {

/// Accepts candidates nearest first, each detection and each true object at most once. Ties go
/// to the lower truth index, then the lower detection index, so the result is deterministic.
/// `concealed` (empty: none) marks the true objects that take a detection only after every plain
/// one has had its pick: a robot mostly hidden behind another takes no detection from the one in
/// front.
MatchResult greedyMatch(std::vector<MatchCandidate> candidates, std::size_t detected_count,
                        std::size_t truth_count, const std::vector<bool>& concealed = {})
{
    const auto later = [&concealed](const MatchCandidate& c) {
        return c.truth < concealed.size() && concealed[c.truth];
    };
    std::sort(candidates.begin(), candidates.end(),
              [&later](const MatchCandidate& a, const MatchCandidate& b) {
                  return std::make_tuple(later(a), a.cost, a.truth, a.detection) <
                         std::make_tuple(later(b), b.cost, b.truth, b.detection);
              });
    std::vector<bool> detection_used(detected_count, false);
    std::vector<bool> truth_used(truth_count, false);
    MatchResult result;
    for (const MatchCandidate& c : candidates) {
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

/// Kind P's rule (PerceptTraits<P>::matchCost) over two lists of it.
template <class P>
MatchResult matchLists(const std::vector<P>& detected, const std::vector<P>& truth, int height)
{
    return greedyMatch(matchCandidates(detected, truth, 0, height), detected.size(), truth.size());
}

} // namespace

MatchResult matchBalls(const std::vector<Ball>& detected, const std::vector<Ball>& truth)
{
    return matchLists(detected, truth, 0);
}

MatchResult matchGoalposts(const std::vector<Goalpost>& detected,
                           const std::vector<Goalpost>& truth, int image_height)
{
    return matchLists(detected, truth, image_height);
}

MatchResult matchObstacles(const std::vector<Obstacle>& detected,
                           const std::vector<Obstacle>& truth)
{
    return matchLists(detected, truth, 0);
}

MatchResult matchFieldLines(const std::vector<FieldLine>& detected,
                            const std::vector<FieldLine>& truth)
{
    return matchLists(detected, truth, 0);
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

std::vector<const PerceptKind*> scoredKinds(const std::vector<const PerceptKind*>& kinds)
{
    std::vector<const PerceptKind*> scored;
    std::copy_if(kinds.begin(), kinds.end(), std::back_inserter(scored),
                 [](const PerceptKind* kind) { return kind->match != nullptr; });
    std::stable_sort(scored.begin(), scored.end(), [](const PerceptKind* a, const PerceptKind* b) {
        return a->class_order < b->class_order;
    });
    return scored;
}

const std::vector<const PerceptKind*>& scoredKinds()
{
    static const std::vector<const PerceptKind*> kinds =
        scoredKinds(Pipeline::standard().perceptKinds());
    return kinds;
}

std::string scoredClassName(const PerceptKind& kind)
{
    return std::string(kind.match ? kind.class_name : kind.key);
}

std::string scoredClassText(const PerceptKind& kind)
{
    std::string text = scoredClassName(kind);
    std::replace(text.begin(), text.end(), '_', ' ');
    return text;
}

const PerceptKind& boundaryKind()
{
    return perceptKind<FieldBoundary>();
}

namespace {

/// The list of `kind` in `set`; null when absent.
const PerceptEntry* listOf(const PerceptSet& set, const PerceptKind& kind)
{
    const PerceptEntry* e = set.find(kind);
    return e && e->present() ? e : nullptr;
}

/// The centre of a circle, box or segment; nothing for another form.
std::optional<PointF> centreOf(ShapeForm form, const EditShape& shape)
{
    if (form == ShapeForm::Circle && shape.points.size() == 1)
        return shape.points[0];
    if ((form == ShapeForm::Box || form == ShapeForm::Segment) && shape.points.size() == 2)
        return PointF{(shape.points[0].x + shape.points[1].x) / 2,
                      (shape.points[0].y + shape.points[1].y) / 2};
    return std::nullopt;
}

/// Whether `p` lies inside a circle's disc or a box (inclusive pixels).
bool inside(ShapeForm form, const EditShape& shape, PointF p)
{
    if (form == ShapeForm::Circle && shape.points.size() == 1)
        return std::hypot(p.x - shape.points[0].x, p.y - shape.points[0].y) <= shape.radius;
    if (form == ShapeForm::Box && shape.points.size() == 2) {
        const PointF& a = shape.points[0];
        const PointF& b = shape.points[1];
        return p.x >= std::min(a.x, b.x) - 0.5 && p.x <= std::max(a.x, b.x) + 0.5 &&
               p.y >= std::min(a.y, b.y) - 0.5 && p.y <= std::max(a.y, b.y) + 0.5;
    }
    return false;
}

/// Pairs the kind's rule leaves out that a concealed true object takes: a detection of what is
/// seen of it (the visible half of a ball behind a robot) is placed off its true centre, so its
/// centre inside the object's outline is enough. They cost more than any pair of the rule.
void addConcealedPairs(const PerceptEntry* detected, const PerceptEntry* truth,
                       const std::vector<bool>& concealed, std::vector<MatchCandidate>& candidates)
{
    if (!detected || !truth ||
        std::find(concealed.begin(), concealed.end(), true) == concealed.end())
        return;
    const ShapeForm form = truth->kind().form;
    const std::vector<EditShape> found = detected->shapes();
    const std::vector<EditShape> true_shapes = truth->shapes();
    constexpr double kAfterTheRule = 1e6;
    for (std::size_t t = 0; t < true_shapes.size() && t < concealed.size(); ++t) {
        if (!concealed[t])
            continue;
        const auto true_centre = centreOf(form, true_shapes[t]);
        for (std::size_t d = 0; d < found.size() && true_centre; ++d) {
            const auto centre = centreOf(form, found[d]);
            const bool paired =
                std::any_of(candidates.begin(), candidates.end(), [&](const MatchCandidate& c) {
                    return c.detection == d && c.truth == t;
                });
            if (centre && !paired && inside(form, true_shapes[t], *centre))
                candidates.push_back({kAfterTheRule + std::hypot(centre->x - true_centre->x,
                                                                 centre->y - true_centre->y),
                                      d, t});
        }
    }
}

/// matchFrame() with `marks` (null: every kind complete, no object concealed).
FrameMatch matchFrameWith(const PerceptSet& detected, const PerceptSet& truth,
                          const FrameAnnotation* marks, int width, int height,
                          const std::vector<const PerceptKind*>& kinds)
{
    FrameMatch frame;
    for (const PerceptKind* scored : kinds) {
        const PerceptKind& kind = *scored;
        if (marks && !marks->complete(kind.truth_key))
            continue;
        const PerceptEntry* detected_list = listOf(detected, kind);
        const PerceptEntry* truth_list = listOf(truth, kind);
        const std::size_t detected_count = detected_list ? detected_list->size() : 0;
        const std::size_t truth_count = truth_list ? truth_list->size() : 0;
        std::vector<bool> concealed_truth(truth_count, false);
        for (std::size_t t = 0; marks && t < truth_count; ++t)
            concealed_truth[t] = marks->flagsOf(kind.truth_key, t).concealed;
        std::vector<MatchCandidate> candidates =
            kind.match(detected_list, truth_list, width, height);
        addConcealedPairs(detected_list, truth_list, concealed_truth, candidates);
        const MatchResult match =
            greedyMatch(std::move(candidates), detected_count, truth_count, concealed_truth);
        KindMatch m;
        m.kind = &kind;
        m.pairs = match.pairs;
        std::vector<bool> detection_used(detected_count, false);
        std::vector<bool> truth_used(truth_count, false);
        const auto concealed = [&](std::size_t t) { return bool(concealed_truth[t]); };
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
                      int height, const std::vector<const PerceptKind*>& kinds)
{
    return matchFrameWith(detected, truth.truth, &truth, width, height, kinds);
}

EvaluationScores::EvaluationScores() : EvaluationScores(scoredKinds()) {}

EvaluationScores::EvaluationScores(const std::vector<const PerceptKind*>& kinds)
{
    for (const PerceptKind* kind : kinds)
        m_classes.emplace_back(kind, ClassScore{});
}

const ClassScore* EvaluationScores::find(const PerceptKind& kind) const
{
    for (const auto& c : m_classes)
        if (c.first->key == kind.key)
            return &c.second;
    return nullptr;
}

ClassScore& EvaluationScores::operator[](const PerceptKind& kind)
{
    if (const ClassScore* c = std::as_const(*this).find(kind))
        return const_cast<ClassScore&>(*c);
    return m_classes.emplace_back(&kind, ClassScore{}).second;
}

const ClassScore& EvaluationScores::of(const PerceptKind& kind) const
{
    static const ClassScore none;
    const ClassScore* c = find(kind);
    return c ? *c : none;
}

void EvaluationScores::add(const FrameMatch& frame)
{
    for (const KindMatch& k : frame.kinds)
        (*this)[*k.kind] += k.score;
    if (frame.boundary_error >= 0) {
        boundary_error_sum += frame.boundary_error;
        ++boundary_frames;
    }
}

void scoreFrame(const PerceptSet& detected, const PerceptSet& truth, int width, int height,
                EvaluationScores& scores, const std::vector<const PerceptKind*>& kinds)
{
    ++scores.frames;
    scores.add(matchFrameWith(detected, truth, nullptr, width, height, kinds));
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
                                 int height, const std::vector<const PerceptKind*>& kinds)
{
    // The run before plays the truth: a detection after the edit that nothing before matches
    // appeared (a false positive); one before that nothing after matches vanished (a miss).
    const FrameMatch match = matchFrameWith(after, before, nullptr, width, height, kinds);
    DetectionDelta delta;
    for (const KindMatch& k : match.kinds)
        delta.kinds.push_back({k.kind, k.score.fp, k.score.fn});
    return delta;
}

bool isScored(const FrameAnnotation& annotation, const std::vector<const PerceptKind*>& kinds)
{
    if (annotation.done)
        return true;
    for (const PerceptKind* kind : kinds)
        if (annotation.complete(kind->truth_key))
            return true;
    return annotation.complete(boundaryKind().truth_key);
}

Evaluation evaluateFrames(const std::map<std::string, PerceptSet>& detected,
                          const Annotations& truth, int width, int height,
                          const std::vector<const PerceptKind*>& kinds)
{
    Evaluation evaluation{EvaluationScores(kinds), {}};
    EvaluationScores& scores = evaluation.scores;
    const PerceptSet nothing;
    for (const auto& [name, annotation] : truth.frames) {
        if (!annotation.done)
            ++scores.frames_not_done;
        if (!isScored(annotation, kinds))
            continue;
        ++(annotation.done ? scores.frames : scores.frames_reviewed);
        const auto it = detected.find(name);
        if (it == detected.end())
            ++scores.frames_missing;
        const FrameMatch match = matchFrame(it == detected.end() ? nothing : it->second, annotation,
                                            width, height, kinds);
        scores.add(match);
        for (const KindMatch& k : match.kinds)
            if (!k.false_detections.empty() || !k.missed.empty())
                evaluation.disagreements.push_back({name, k.kind, k.false_detections, k.missed});
    }
    return evaluation;
}

EvaluationScores evaluate(const std::map<std::string, PerceptSet>& detected,
                          const Annotations& truth, int width, int height,
                          const std::vector<const PerceptKind*>& kinds)
{
    return evaluateFrames(detected, truth, width, height, kinds).scores;
}

} // namespace fieldsight
