#include "stages/common/ellipse_fit.h"

#include "stages/common/line_fit.h"

#include <Eigen/Cholesky>

#include <algorithm>
#include <cmath>

namespace fieldsight {

double ImageEllipse::distance(const PointF& p) const
{
    const double dx = p.x - centre.x;
    const double dy = p.y - centre.y;
    const double u = (dx * cos_t + dy * sin_t) / a;
    const double v = (dy * cos_t - dx * sin_t) / b;
    const double rho = std::sqrt(u * u + v * v); // 1 on the outline
    // rho - 1 over its gradient's length: to first order the distance across the outline (the
    // distance along the ray from the centre overstates it on a flat ellipse, 5.8 px for 1 px
    // off a 120 x 10 one).
    const double gradient = std::sqrt(u * u / (a * a) + v * v / (b * b));
    if (rho < 1e-9 || gradient < 1e-12)
        return std::min(a, b);
    return std::abs(rho - 1) * rho / gradient;
}

std::optional<ImageEllipse> fitImageEllipse(const std::vector<PointF>& points, double min_axis,
                                            double max_axis, double max_mean_error)
{
    if (points.size() < 8)
        return std::nullopt;
    // The conic A x^2 + B xy + C y^2 + D x + E y = 1 nearest the points in the algebraic sense,
    // in coordinates about the points' mean (inside any ellipse an arc of it gives, so the
    // conic's value there is never 0) scaled to a mean distance of 1: one 5 x 5 solve, as
    // OpenCV's fitEllipse starts (which spent some 60 k instructions a call). On a short, flat
    // arc of the centre circle it keeps the arc's curvature, where the "direct" fit of
    // Fitzgibbon et al. shrinks the ellipse towards the chord.
    const auto [mx, my] = meanOf(points);
    double spread = 0;
    for (const PointF& p : points)
        spread += std::sqrt((p.x - mx) * (p.x - mx) + (p.y - my) * (p.y - my));
    spread /= double(points.size());
    if (spread < 1e-6)
        return std::nullopt;
    Eigen::Matrix<double, 5, 5> normal = Eigen::Matrix<double, 5, 5>::Zero();
    Eigen::Matrix<double, 5, 1> rhs = Eigen::Matrix<double, 5, 1>::Zero();
    for (const PointF& p : points) {
        const double x = (p.x - mx) / spread;
        const double y = (p.y - my) / spread;
        Eigen::Matrix<double, 5, 1> row;
        row << x * x, x * y, y * y, x, y;
        normal.selfadjointView<Eigen::Lower>().rankUpdate(row);
        rhs += row;
    }
    const Eigen::Matrix<double, 5, 1> k = normal.selfadjointView<Eigen::Lower>().ldlt().solve(rhs);
    const double A = k[0], B = k[1], C = k[2], D = k[3], E = k[4], F = -1;
    const double det = 4 * A * C - B * B;
    if (!(det > 1e-12))
        return std::nullopt; // a parabola or hyperbola: no ellipse
    const double x0 = (B * E - 2 * C * D) / det;
    const double y0 = (B * D - 2 * A * E) / det;
    const double f0 = F + 0.5 * (D * x0 + E * y0); // the conic's value at its centre
    // Axes: the eigenvectors of [[A, B/2], [B/2, C]]; semi-axis sqrt(-f0 / eigenvalue).
    const double half_sum = 0.5 * (A + C);
    const double root = std::hypot(0.5 * (A - C), 0.5 * B);
    const double l1 = half_sum - root;
    const double l2 = half_sum + root;
    if (!(-f0 / l1 > 0 && -f0 / l2 > 0))
        return std::nullopt; // an empty conic
    ImageEllipse e;
    e.centre = {mx + x0 * spread, my + y0 * spread};
    e.a = std::sqrt(-f0 / l1) * spread;
    e.b = std::sqrt(-f0 / l2) * spread;
    // The eigenvector of l1 is (B/2, l1 - A) and (l1 - C, B/2): the longer is the exact one.
    const bool first = std::hypot(0.5 * B, l1 - A) >= std::hypot(l1 - C, 0.5 * B);
    const double angle = first ? std::atan2(l1 - A, 0.5 * B) : std::atan2(0.5 * B, l1 - C);
    e.cos_t = std::cos(angle);
    e.sin_t = std::sin(angle);
    if (!(e.a >= min_axis && e.b >= min_axis && e.a <= max_axis && e.b <= max_axis))
        return std::nullopt;
    double sum = 0;
    for (const PointF& p : points)
        sum += e.distance(p);
    if (sum > max_mean_error * double(points.size()))
        return std::nullopt;
    return e;
}

} // namespace fieldsight
