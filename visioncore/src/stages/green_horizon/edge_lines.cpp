// The field's edge as one or two lines: exhaustive pairs, then least squares over the inliers.
#include "stages/green_horizon/edge_lines.h"

#include <cmath>
#include <optional>

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

/// The points within `tolerance` of `line`, those above, and the sum of the inliers' distances;
/// nullopt as soon as the line cannot reach `to_beat`'s merit even if every point left were an
/// inlier (it would not be chosen: the pairs' search scores n^2 lines over n points each, and
/// most fall behind within a few points).
std::optional<Fit> score(const std::vector<PixelPoint>& pool, const EdgeLine& line,
                         double tolerance, std::optional<double> to_beat)
{
    Fit f{line, 0, 0, 0};
    const int n = int(pool.size());
    for (int i = 0; i < n; ++i) {
        const PixelPoint& p = pool[std::size_t(i)];
        const double d = p.y - line.at(p.x);
        if (std::abs(d) <= tolerance) {
            ++f.support;
            f.residual += std::abs(d);
        } else if (d < 0) {
            ++f.above;
            if (to_beat && f.merit() + (n - 1 - i) < *to_beat)
                return std::nullopt;
        } else if (to_beat && f.merit() + (n - 1 - i) < *to_beat) {
            return std::nullopt;
        }
    }
    return f;
}

/// The line through two of `pool`'s points with the most merit (then the least residual) that
/// `allowed` accepts, refitted by least squares to its inliers.
template <class Allowed>
Fit bestLine(const std::vector<PixelPoint>& pool, double tolerance, Allowed allowed)
{
    Fit best;
    for (std::size_t i = 0; i < pool.size(); ++i)
        for (std::size_t j = i + 1; j < pool.size(); ++j) {
            if (pool[i].x == pool[j].x)
                continue;
            const double b = double(pool[j].y - pool[i].y) / double(pool[j].x - pool[i].x);
            const std::optional<Fit> f =
                score(pool, {pool[i].y - b * pool[i].x, b}, tolerance,
                      best.support > 0 ? std::optional<double>(best.merit()) : std::nullopt);
            if (!f || (best.support > 0 && !f->betterThan(best)) || !allowed(f->line))
                continue;
            best = *f;
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
    const Fit first = bestLine(points, tolerance, [](const EdgeLine&) { return true; });
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
    const Fit second = bestLine(below, tolerance, keepsFirst);
    if (second.support >= std::max(2, min_support))
        model.second = second.line;
    return model;
}

} // namespace fieldsight
