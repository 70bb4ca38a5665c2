// Line model and total-least-squares fit, on Eigen's 2x2 symmetric eigen solver.
#include "stages/common/line_fit.h"

#include <Eigen/Eigenvalues>

#include <cmath>
#include <limits>

namespace fieldsight {

bool ImageLine::fromSample(const PointF* sample)
{
    const double dx = sample[1].x - sample[0].x;
    const double dy = sample[1].y - sample[0].y;
    const double len = std::sqrt(dx * dx + dy * dy);
    if (len < 1e-9)
        return false;
    point = sample[0];
    direction = {dx / len, dy / len};
    return true;
}

double ImageLine::xAtY(double y) const
{
    if (std::abs(direction.y) < 1e-12)
        return point.x;
    return point.x + (y - point.y) * direction.x / direction.y;
}

double ImageLine::angleTo(const ImageLine& other) const
{
    const double c = std::abs(direction.x * other.direction.x + direction.y * other.direction.y);
    return std::acos(std::min(1.0, c));
}

PointF meanOf(const std::vector<PointF>& points)
{
    if (points.empty())
        return {0, 0};
    double mx = 0, my = 0;
    for (const PointF& p : points) {
        mx += p.x;
        my += p.y;
    }
    return {mx / double(points.size()), my / double(points.size())};
}

ImageLine fitLineTls(const std::vector<PointF>& points)
{
    ImageLine line;
    if (points.empty())
        return line;
    const auto [mx, my] = meanOf(points);
    double sxx = 0, sxy = 0, syy = 0;
    for (const PointF& p : points) {
        sxx += (p.x - mx) * (p.x - mx);
        sxy += (p.x - mx) * (p.y - my);
        syy += (p.y - my) * (p.y - my);
    }
    Eigen::Matrix2d cov;
    cov << sxx, sxy, sxy, syy;
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> solver;
    solver.computeDirect(cov); // closed form for 2x2: a quarter of the iterative solver's cost
    const Eigen::Vector2d d = solver.eigenvectors().col(1); // largest eigenvalue
    line.point = {mx, my};
    line.direction = {d.x(), d.y()};
    return line;
}

void lineExtent(const ImageLine& line, const std::vector<PointF>& points, PointF& a, PointF& b)
{
    double lo = std::numeric_limits<double>::max();
    double hi = std::numeric_limits<double>::lowest();
    for (const PointF& p : points) {
        const double t = line.along(p);
        lo = std::min(lo, t);
        hi = std::max(hi, t);
    }
    if (points.empty())
        lo = hi = 0;
    a = line.at(lo);
    b = line.at(hi);
}

} // namespace fieldsight
