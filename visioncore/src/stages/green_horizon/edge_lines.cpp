// The field's edge as one or two lines: exhaustive pairs, then least squares over the inliers.
#include "stages/green_horizon/edge_lines.h"

#include <cmath>
#include <cstdint>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace fieldsight {

namespace {

struct Fit
{
    EdgeLine line;
    int support = 0; ///< points within the tolerance
    int above = 0;   ///< points further above
    double residual = 0;
    /// The field starts at its edge: green above a line counts against it (half a point each),
    /// so of two parallel lines with as many points (the edge and a strip below it) the upper
    /// one wins, and a line through clutter does not win by its points alone.
    double merit() const { return support - 0.5 * above; }
    bool betterThan(const Fit& o) const
    {
        return merit() > o.merit() || (merit() == o.merit() && residual < o.residual);
    }
};

/// The points within `tolerance` of `line`, those above, and the sum of the inliers' distances,
/// from the pool's x and y as doubles.
Fit score(const std::vector<double>& xs, const std::vector<double>& ys, const EdgeLine& line,
          double tolerance)
{
    Fit f{line, 0, 0, 0};
    for (std::size_t k = 0; k < xs.size(); ++k) {
        const double d = ys[k] - line.at(xs[k]);
        const double off = std::abs(d);
        const bool in = off <= tolerance;
        f.support += in;
        f.above += !in && d < 0;
        f.residual += in ? off : 0.0;
    }
    return f;
}

/// score()'s merit, and its residual summed in another order (so to within rounding): two points
/// a step where SSE2 is there, with the same products and sums, so the same inliers. The search
/// scores n^2 lines over n points and works the residual out exactly only for those that can
/// win.
struct QuickFit
{
    double merit;
    double residual;
};
QuickFit quickScore(const std::vector<double>& xs, const std::vector<double>& ys,
                    const EdgeLine& line, double tolerance)
{
    const std::size_t n = xs.size();
    std::size_t i = 0;
    std::int64_t support = 0, above = 0;
    double residual = 0;
#if defined(__SSE2__)
    const __m128d a = _mm_set1_pd(line.a), b = _mm_set1_pd(line.b);
    const __m128d tol = _mm_set1_pd(tolerance), below_tol = _mm_set1_pd(-tolerance);
    const __m128d magnitude = _mm_castsi128_pd(_mm_set1_epi64x(0x7FFFFFFFFFFFFFFFll));
    // All ones (-1) where true: subtracted, a count.
    __m128i in = _mm_setzero_si128(), up = _mm_setzero_si128();
    __m128d off_sum = _mm_setzero_pd();
    for (; i + 2 <= n; i += 2) {
        const __m128d at = _mm_add_pd(a, _mm_mul_pd(b, _mm_loadu_pd(xs.data() + i)));
        const __m128d d = _mm_sub_pd(_mm_loadu_pd(ys.data() + i), at);
        const __m128d off = _mm_and_pd(d, magnitude);
        const __m128d inside = _mm_cmple_pd(off, tol);
        in = _mm_sub_epi64(in, _mm_castpd_si128(inside));
        up = _mm_sub_epi64(up, _mm_castpd_si128(_mm_cmplt_pd(d, below_tol)));
        off_sum = _mm_add_pd(off_sum, _mm_and_pd(off, inside));
    }
    std::int64_t lanes[2];
    _mm_storeu_si128(reinterpret_cast<__m128i*>(lanes), in);
    support = lanes[0] + lanes[1];
    _mm_storeu_si128(reinterpret_cast<__m128i*>(lanes), up);
    above = lanes[0] + lanes[1];
    double sums[2];
    _mm_storeu_pd(sums, off_sum);
    residual = sums[0] + sums[1];
#endif
    for (; i < n; ++i) {
        const double d = ys[i] - line.at(xs[i]);
        if (std::abs(d) <= tolerance) {
            ++support;
            residual += std::abs(d);
        } else if (d < 0) {
            ++above;
        }
    }
    return {double(support) - 0.5 * double(above), residual};
}

/// The line through two of `pool`'s points with the most merit (then the least residual) that
/// `allowed` accepts, refitted by least squares to its inliers.
template <class Allowed>
Fit bestLine(const std::vector<PixelPoint>& pool, double tolerance, EdgeFitScratch& scratch,
             Allowed allowed)
{
    std::vector<double>& xs = scratch.xs;
    std::vector<double>& ys = scratch.ys;
    xs.resize(pool.size());
    ys.resize(pool.size());
    for (std::size_t k = 0; k < pool.size(); ++k) {
        xs[k] = pool[k].x;
        ys[k] = pool[k].y;
    }
    Fit best;
    for (std::size_t i = 0; i < pool.size(); ++i)
        for (std::size_t j = i + 1; j < pool.size(); ++j) {
            if (pool[i].x == pool[j].x)
                continue;
            const double b = double(pool[j].y - pool[i].y) / double(pool[j].x - pool[i].x);
            const EdgeLine line{pool[i].y - b * pool[i].x, b};
            if (best.support > 0) {
                const QuickFit quick = quickScore(xs, ys, line, tolerance);
                // Behind on merit, or level and behind on residual by more than rounding: the
                // exact score would not be better either.
                if (quick.merit < best.merit() ||
                    (quick.merit == best.merit() &&
                     quick.residual > best.residual + 1e-9 * (1 + best.residual)))
                    continue;
            }
            const Fit f = score(xs, ys, line, tolerance);
            if ((best.support > 0 && !f.betterThan(best)) || !allowed(f.line))
                continue;
            best = f;
        }
    if (best.support < 2)
        return best;
    // Least squares over the inliers: two points alone carry their own rounding.
    double n = 0, sx = 0, sy = 0, sxx = 0, sxy = 0;
    for (const PixelPoint& p : pool)
        if (std::abs(p.y - best.line.at(p.x)) <= tolerance) {
            n += 1;
            sx += p.x;
            sy += p.y;
            sxx += double(p.x) * p.x;
            sxy += double(p.x) * p.y;
        }
    const double det = n * sxx - sx * sx;
    if (det > 0) {
        const double b = (n * sxy - sx * sy) / det;
        const EdgeLine refit{(sy - b * sx) / n, b};
        if (allowed(refit))
            best.line = refit;
    }
    return best;
}

} // namespace

std::optional<EdgeModel> fitEdge(const std::vector<PixelPoint>& points, double tolerance,
                                 int min_support, EdgeFitScratch& scratch)
{
    const Fit first = bestLine(points, tolerance, scratch, [](const EdgeLine&) { return true; });
    if (first.support < std::max(2, min_support))
        return std::nullopt;
    EdgeModel model{first.line, std::nullopt};
    // Over a corner the far side's points lie below the first line. A line through them is the
    // edge's other side only if it leaves the first line's points on the edge (it passes above
    // them): a line through a robot's feet below the edge would cut the edge off.
    std::vector<PixelPoint>& on_first = scratch.on_first;
    std::vector<PixelPoint>& below = scratch.below;
    on_first.clear();
    below.clear();
    for (const PixelPoint& p : points) {
        const double d = p.y - first.line.at(p.x);
        if (std::abs(d) <= tolerance)
            on_first.push_back(p);
        else if (d > tolerance)
            below.push_back(p);
    }
    if (int(below.size()) < min_support)
        return model;
    const auto keepsFirst = [&](const EdgeLine& line) {
        return std::all_of(on_first.begin(), on_first.end(), [&](const PixelPoint& p) {
            return line.at(p.x) <= first.line.at(p.x) + tolerance;
        });
    };
    const Fit second = bestLine(below, tolerance, scratch, keepsFirst);
    if (second.support >= std::max(2, min_support))
        model.second = second.line;
    return model;
}

} // namespace fieldsight
