// Scoring detections against annotations (SPEC §5.3): greedy one-to-one matching, nearest first.
#include "visioncore/services/evaluation.h"

#include "visioncore/percepts/field_boundary.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
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

void scoreFrame(const PerceptSet& detected, const PerceptSet& truth, int width, int height,
                EvaluationScores& scores)
{
    ++scores.frames;
    scores.balls += matchBalls(detected.list<Ball>(), truth.list<Ball>()).score;
    scores.goalposts +=
        matchGoalposts(detected.list<Goalpost>(), truth.list<Goalpost>(), height).score;
    scores.obstacles += matchObstacles(detected.list<Obstacle>(), truth.list<Obstacle>()).score;
    const double boundary =
        polylineMeanAbsDifference(boundaryOf(detected), boundaryOf(truth), width);
    if (boundary >= 0) {
        scores.boundary_error_sum += boundary;
        ++scores.boundary_frames;
    }
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
    EvaluationScores scores;
    scoreFrame(after, before, width, height, scores);
    DetectionDelta delta;
    // A false positive is a detection after the edit that nothing before matches: it appeared.
    for (const auto& [kind, score] : {std::pair{&perceptKind<Ball>(), scores.balls},
                                      std::pair{&perceptKind<Goalpost>(), scores.goalposts},
                                      std::pair{&perceptKind<Obstacle>(), scores.obstacles}})
        delta.kinds.push_back({kind, score.fp, score.fn});
    return delta;
}

EvaluationScores evaluate(const std::map<std::string, PerceptSet>& detected,
                          const Annotations& truth, int width, int height)
{
    EvaluationScores scores;
    const PerceptSet nothing;
    for (const auto& [name, annotation] : truth.frames) {
        if (!annotation.done) {
            ++scores.frames_not_done;
            continue;
        }
        const auto it = detected.find(name);
        if (it == detected.end())
            ++scores.frames_missing;
        scoreFrame(it == detected.end() ? nothing : it->second, annotation.truth, width, height,
                   scores);
    }
    return scores;
}

std::string defaultTruthPath(const std::string& stream)
{
    return besideStream(stream, "annotations.json");
}

namespace {

/// The stream index of every done frame of `truth`, by name, else by name without extension.
Result<std::map<std::string, std::size_t>>
doneFrameIndices(const StreamInput& input, const Annotations& truth, const std::string& truth_path)
{
    std::map<std::string, std::size_t> by_name;
    std::map<std::string, std::size_t> by_stem;
    for (std::size_t i = 0; i < input.info().frame_count; ++i) {
        const std::string name = input.reader->frameName(i);
        by_name.emplace(name, i);
        by_stem.emplace(frameStem(name), i);
    }
    std::map<std::string, std::size_t> indices;
    for (const auto& [name, annotation] : truth.frames) {
        if (!annotation.done)
            continue;
        if (auto it = by_name.find(name); it != by_name.end()) {
            indices.emplace(name, it->second);
        } else if (auto st = by_stem.find(frameStem(name)); st != by_stem.end()) {
            indices.emplace(name, st->second);
        } else {
            return Error{truth_path + ": frame '" + name + "' is marked done but " + input.stream +
                         " has no such frame"};
        }
    }
    return indices;
}

} // namespace

Result<EvalReport> evaluateStream(StreamInput& input, const Annotations& truth,
                                  const std::string& truth_path, int threads, const RunHooks& hooks)
{
    auto names = doneFrameIndices(input, truth, truth_path);
    if (!names)
        return names.error();
    std::vector<std::size_t> indices;
    for (const auto& [name, index] : names.value())
        indices.push_back(index);
    std::sort(indices.begin(), indices.end());
    indices.erase(std::unique(indices.begin(), indices.end()), indices.end());

    auto run = runStream(input, indices, threads, hooks);
    if (!run)
        return run.error();
    if (run.value().cancelled)
        return Error{input.stream + ": evaluation cancelled"};
    std::map<std::size_t, const FrameResult*> by_index;
    for (const FrameResult& f : run.value().frames)
        by_index.emplace(f.index, &f);
    std::map<std::string, PerceptSet> detected;
    for (const auto& [name, index] : names.value())
        detected.emplace(name, by_index.at(index)->percepts);

    EvalReport report;
    report.stream = input.stream;
    report.lut_path = input.lut_path;
    report.truth_path = truth_path;
    report.scores = evaluate(detected, truth, input.info().width, input.info().height);
    return report;
}

} // namespace fieldsight
