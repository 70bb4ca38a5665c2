// Generic RANSAC (design note §2.11) with an explicit, seeded generator, so results are
// reproducible (the original used the unseeded global rand()).
#pragma once

#include "visioncore/geometry.h"

#include <cmath>
#include <cstdint>
#include <algorithm>
#include <random>
#include <vector>

namespace fieldsight {

enum class ConsensusSelection {
    Largest,     ///< keep the model with the most inliers (ties: lower mean error)
    BestFitting, ///< keep the model with the lowest mean inlier error among those with >= n
};

struct RansacParams
{
    double max_error = 5.0; ///< px, inlier distance
    int min_points = 6;     ///< inliers needed to accept a model
    int iterations = 100;   ///< samples per model, at most
    ConsensusSelection selection = ConsensusSelection::Largest;
    /// Stop sampling once a better model would have been drawn with this probability (adaptive
    /// termination, Hartley & Zisserman 4.7.1); 0 always draws `iterations` samples.
    double confidence = 0.99;
    /// When > 0, every sample point after the first is drawn within this many positions of the
    /// first in the input order (points in scan order are near each other in the image, so a
    /// sample lies on one model far more often than with independent draws).
    std::size_t locality = 0;
};

template <class Model> struct RansacResult
{
    Model model;
    std::vector<PointF> inliers;
    double mean_error = 0;
};

/// Draws an index in [0, n) from the raw engine output, so the sequence is the same on every
/// standard library (std::uniform_int_distribution is implementation-defined).
inline std::size_t drawIndex(std::mt19937& rng, std::size_t n)
{
    return std::size_t(rng() % n);
}

/// One model from `points`. Model needs: static constexpr int kSampleSize; bool fromSample(const
/// PointF* sample); double error(const PointF&) const. On success the inliers are moved out of
/// `points` (which keeps the outliers) and the model is returned.
template <class Model>
bool ransacFindModel(std::vector<PointF>& points, const RansacParams& params, std::mt19937& rng,
                     RansacResult<Model>& out)
{
    const std::size_t n = points.size();
    if (n < std::size_t(params.min_points) || n < std::size_t(Model::kSampleSize))
        return false;
    bool found = false;
    std::size_t best_count = 0;
    double best_error = 0;
    Model best{};
    PointF sample[Model::kSampleSize];
    int needed = params.iterations;
    for (int it = 0; it < needed; ++it) {
        std::size_t idx[Model::kSampleSize];
        for (int s = 0; s < Model::kSampleSize; ++s) {
            bool distinct = false;
            while (!distinct) {
                if (s == 0 || params.locality == 0) {
                    idx[s] = drawIndex(rng, n);
                } else {
                    const std::size_t lo = idx[0] > params.locality ? idx[0] - params.locality : 0;
                    const std::size_t hi = std::min(n - 1, idx[0] + params.locality);
                    idx[s] = lo + drawIndex(rng, hi - lo + 1);
                }
                distinct = true;
                for (int t = 0; t < s; ++t)
                    distinct = distinct && idx[t] != idx[s];
            }
            sample[s] = points[idx[s]];
        }
        Model model;
        if (!model.fromSample(sample))
            continue;
        // Branch-free, so the compiler can vectorise the hot loop of every RANSAC user. (Points
        // stay in scan order: a line's inliers come in runs; shuffling them for an early
        // bail-out cut instructions but cost more time in mispredicted branches.)
        std::size_t count = 0;
        double sum = 0;
        for (const PointF& p : points) {
            const double e = model.error(p);
            const bool inlier = e < params.max_error;
            count += inlier;
            sum += inlier ? e : 0.0;
        }
        if (count < std::size_t(params.min_points))
            continue;
        const double mean = sum / double(count);
        bool better = !found;
        if (found && params.selection == ConsensusSelection::Largest)
            better = count > best_count || (count == best_count && mean < best_error);
        if (found && params.selection == ConsensusSelection::BestFitting)
            better = mean < best_error;
        if (better) {
            found = true;
            best = model;
            best_count = count;
            best_error = mean;
            if (params.confidence > 0 && params.selection == ConsensusSelection::Largest) {
                const double w = double(count) / double(n);
                const double all_in = std::pow(w, Model::kSampleSize);
                if (all_in >= 1.0) {
                    needed = it + 1;
                } else {
                    const double k = std::log(1 - params.confidence) / std::log(1 - all_in);
                    needed = std::min(params.iterations, int(std::ceil(k)) + it + 1);
                }
            }
        }
    }
    if (!found)
        return false;
    out.model = best;
    out.mean_error = best_error;
    out.inliers.clear();
    std::vector<PointF> rest;
    rest.reserve(n - best_count);
    for (const PointF& p : points)
        (best.error(p) < params.max_error ? out.inliers : rest).push_back(p);
    points.swap(rest);
    return true;
}

/// Up to `max_models` models, each from what the previous ones left over.
template <class Model>
std::vector<RansacResult<Model>> ransacFindModels(std::vector<PointF> points,
                                                  const RansacParams& params, int max_models,
                                                  std::mt19937& rng)
{
    std::vector<RansacResult<Model>> found;
    RansacResult<Model> result;
    while (int(found.size()) < max_models && ransacFindModel(points, params, rng, result))
        found.push_back(result);
    return found;
}

} // namespace fieldsight
