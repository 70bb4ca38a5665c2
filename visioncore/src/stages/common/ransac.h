// Generic RANSAC (design note §2.11) with an explicit, seeded generator, so results are
// reproducible (the original used the unseeded global rand()).
#pragma once

#include "visioncore/basics/geometry.h"
#include "visioncore/basics/splitmix.h"

#include <cmath>
#include <cstdint>
#include <algorithm>
#include <random>
#if defined(__SSE2__)
#include <emmintrin.h>
#endif
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

/// The RANSAC random engine: the same sequence everywhere, and seeding it is free (std::mt19937
/// spent ~15k instructions a frame filling its 624-word state for the stages' per-frame seeds).
using RansacRng = SplitMix64;

/// Draws an index in [0, n) from the raw engine output, so the sequence is the same on every
/// standard library (std::uniform_int_distribution is implementation-defined).
inline std::size_t drawIndex(RansacRng& rng, std::size_t n)
{
    return std::size_t(rng() % n);
}

/// Per-lane counters for `Lanes`.
struct LaneCounts
{
#if defined(__SSE2__)
    __m128i v = _mm_setzero_si128();
    std::size_t total() const
    {
        alignas(16) std::uint32_t c[4];
        _mm_store_si128(reinterpret_cast<__m128i*>(c), v);
        return std::size_t(c[0]) + c[1] + c[2] + c[3];
    }
#else
    std::uint32_t v[4] = {0, 0, 0, 0};
    std::size_t total() const
    {
        return std::size_t(v[0]) + v[1] + v[2] + v[3];
    }
#endif
};

/// Four floats at once (SSE2 on x86-64, plain arrays elsewhere), for the consensus loop: a model's
/// `errorOf` is written once as a template and runs on `float`, `double` and `Lanes`.
struct Lanes
{
#if defined(__SSE2__)
    __m128 v;
    Lanes() = default;
    Lanes(__m128 x) : v(x) {}
    explicit Lanes(float f) : v(_mm_set1_ps(f)) {}
    explicit Lanes(double d) : Lanes(float(d)) {}
    static Lanes load(const float* p)
    {
        return {_mm_loadu_ps(p)};
    }
    friend Lanes operator+(Lanes a, Lanes b)
    {
        return {_mm_add_ps(a.v, b.v)};
    }
    friend Lanes operator-(Lanes a, Lanes b)
    {
        return {_mm_sub_ps(a.v, b.v)};
    }
    friend Lanes operator*(Lanes a, Lanes b)
    {
        return {_mm_mul_ps(a.v, b.v)};
    }
    friend Lanes absOf(Lanes a)
    {
        return {_mm_andnot_ps(_mm_set1_ps(-0.0f), a.v)};
    }
    friend Lanes sqrtOf(Lanes a)
    {
        return {_mm_sqrt_ps(a.v)};
    }
    /// Lanes where a < b keep `a`, the others become 0; `counts` counts such lanes, per lane.
    friend Lanes keepBelow(Lanes a, Lanes b, LaneCounts& counts)
    {
        const __m128 below = _mm_cmplt_ps(a.v, b.v);
        counts.v = _mm_sub_epi32(counts.v, _mm_castps_si128(below)); // a true lane is -1
        return {_mm_and_ps(below, a.v)};
    }
    float sum() const
    {
        alignas(16) float f[4];
        _mm_store_ps(f, v);
        return (f[0] + f[1]) + (f[2] + f[3]);
    }
#else
    float v[4];
    Lanes() = default;
    Lanes(float a, float b, float c, float d) : v{a, b, c, d} {}
    explicit Lanes(float f) : v{f, f, f, f} {}
    explicit Lanes(double d) : Lanes(float(d)) {}
    static Lanes load(const float* p)
    {
        return {p[0], p[1], p[2], p[3]};
    }
    template <class Op> static Lanes map(Lanes a, Lanes b, Op op)
    {
        return {op(a.v[0], b.v[0]), op(a.v[1], b.v[1]), op(a.v[2], b.v[2]), op(a.v[3], b.v[3])};
    }
    friend Lanes operator+(Lanes a, Lanes b)
    {
        return map(a, b, [](float x, float y) { return x + y; });
    }
    friend Lanes operator-(Lanes a, Lanes b)
    {
        return map(a, b, [](float x, float y) { return x - y; });
    }
    friend Lanes operator*(Lanes a, Lanes b)
    {
        return map(a, b, [](float x, float y) { return x * y; });
    }
    friend Lanes absOf(Lanes a)
    {
        return map(a, a, [](float x, float) { return std::abs(x); });
    }
    friend Lanes sqrtOf(Lanes a)
    {
        return map(a, a, [](float x, float) { return std::sqrt(x); });
    }
    friend Lanes keepBelow(Lanes a, Lanes b, LaneCounts& counts)
    {
        for (int i = 0; i < 4; ++i) {
            const bool below = a.v[i] < b.v[i];
            counts.v[i] += std::uint32_t(below);
            a.v[i] = below ? a.v[i] : 0.0f;
        }
        return a;
    }
    float sum() const
    {
        return (v[0] + v[1]) + (v[2] + v[3]);
    }
#endif
};

inline float absOf(float f)
{
    return std::abs(f);
}
inline double absOf(double d)
{
    return std::abs(d);
}
inline float sqrtOf(float f)
{
    return std::sqrt(f);
}
inline double sqrtOf(double d)
{
    return std::sqrt(d);
}

/// The points as float columns padded to a multiple of four, for `countInliers`.
struct PointColumns
{
    std::vector<float> x, y;
    std::size_t n = 0;

    void assign(const std::vector<PointF>& points)
    {
        n = points.size();
        const std::size_t padded = (n + 3) / 4 * 4;
        x.assign(padded, 0.0f);
        y.assign(padded, 0.0f);
        for (std::size_t i = 0; i < n; ++i) {
            x[i] = float(points[i].x);
            y[i] = float(points[i].y);
        }
    }
};

/// Inliers of `model` (error below `max_error`) among `cols`, and the sum of their errors, four
/// points at a time. Branch-free: points stay in scan order, so a line's inliers come in runs;
/// shuffling them for an early bail-out cut instructions but cost more in mispredicted branches.
template <class Model>
std::size_t countInliers(const Model& model, const PointColumns& cols, float max_error, float& sum)
{
    const std::size_t full = cols.n / 4 * 4;
    const Lanes limit = Lanes(max_error);
    Lanes sums = Lanes(0.0f);
    LaneCounts counts;
    for (std::size_t i = 0; i < full; i += 4)
        sums = sums + keepBelow(model.errorOf(Lanes::load(&cols.x[i]), Lanes::load(&cols.y[i])),
                                limit, counts);
    std::size_t count = counts.total();
    sum = sums.sum();
    for (std::size_t i = full; i < cols.n; ++i) {
        const float e = model.errorOf(cols.x[i], cols.y[i]);
        if (e < max_error) {
            ++count;
            sum += e;
        }
    }
    return count;
}

/// One model from `points`. Model needs: static constexpr int kSampleSize; bool fromSample(const
/// PointF* sample); template <class V> V errorOf(V x, V y) const (V is float, double or Lanes;
/// built from +, -, *, absOf and sqrtOf, constants through V(...) for scalars). On success the
/// inliers are moved out of `points` (which keeps the outliers) and the model is returned.
template <class Model>
bool ransacFindModel(std::vector<PointF>& points, const RansacParams& params, RansacRng& rng,
                     RansacResult<Model>& out, PointColumns& cols)
{
    const std::size_t n = points.size();
    if (n < std::size_t(params.min_points) || n < std::size_t(Model::kSampleSize))
        return false;
    cols.assign(points);
    const float max_error = float(params.max_error);
    bool found = false;
    std::size_t best_count = 0;
    double best_error = 0;
    Model best{};
    PointF sample[Model::kSampleSize];
    // Samples needed to draw an all-inlier sample with probability `confidence` when the inlier
    // share is w (Hartley & Zisserman 4.7.1).
    const auto samplesFor = [&](double w) {
        const double all_in = std::pow(w, Model::kSampleSize);
        if (all_in >= 1.0)
            return 1;
        const double k = std::log(1 - params.confidence) / std::log(1 - all_in);
        return int(std::min(double(params.iterations), std::ceil(k)));
    };
    const bool adaptive = params.confidence > 0 && params.selection == ConsensusSelection::Largest;
    // Until a model is found, assume the smallest acceptable one: if even that would have been
    // drawn by now, there is none (a search that finds nothing no longer runs every iteration).
    int needed = adaptive ? samplesFor(double(params.min_points) / double(n)) : params.iterations;
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
        float sum = 0;
        const std::size_t count = countInliers(model, cols, max_error, sum);
        if (count < std::size_t(params.min_points))
            continue;
        const double mean = double(sum) / double(count);
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
            if (adaptive)
                needed =
                    std::min(params.iterations, samplesFor(double(count) / double(n)) + it + 1);
        }
    }
    if (!found)
        return false;
    out.model = best;
    out.mean_error = best_error;
    out.inliers.clear();
    // Split with the same float errors the count used, so inliers.size() == the count.
    std::size_t kept = 0;
    for (std::size_t i = 0; i < n; ++i) {
        if (best.errorOf(cols.x[i], cols.y[i]) < max_error)
            out.inliers.push_back(points[i]);
        else
            points[kept++] = points[i];
    }
    points.resize(kept);
    return true;
}

template <class Model>
bool ransacFindModel(std::vector<PointF>& points, const RansacParams& params, RansacRng& rng,
                     RansacResult<Model>& out)
{
    PointColumns cols;
    return ransacFindModel(points, params, rng, out, cols);
}

/// Up to `max_models` models, each from what the previous ones left over.
template <class Model>
std::vector<RansacResult<Model>> ransacFindModels(std::vector<PointF> points,
                                                  const RansacParams& params, int max_models,
                                                  RansacRng& rng)
{
    std::vector<RansacResult<Model>> found;
    RansacResult<Model> result;
    PointColumns cols;
    while (int(found.size()) < max_models && ransacFindModel(points, params, rng, result, cols))
        found.push_back(result);
    return found;
}

} // namespace fieldsight
