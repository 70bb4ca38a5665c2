// Straight lines in the image: the two-point RANSAC model and the total-least-squares fit.
#pragma once

#include "stages/common/ransac.h"
#include "visioncore/basics/geometry.h"

#include <vector>

namespace fieldsight {

/// A line through `point` along the unit vector `direction`.
struct ImageLine
{
    PointF point;
    PointF direction{1, 0};

    static constexpr int kSampleSize = 2;
    bool fromSample(const PointF* sample);
    /// px, perpendicular distance of (x, y); V is float, double or RANSAC's Lanes (four points).
    template <class V> V errorOf(V x, V y) const
    {
        return absOf((x - V(point.x)) * V(direction.y) - (y - V(point.y)) * V(direction.x));
    }
    double error(const PointF& p) const { return errorOf(p.x, p.y); }
    /// Position of p's projection along the line.
    double along(const PointF& p) const
    {
        return (p.x - point.x) * direction.x + (p.y - point.y) * direction.y;
    }
    PointF at(double t) const { return {point.x + t * direction.x, point.y + t * direction.y}; }
    /// x where the line crosses row y (the line's point x when it is horizontal).
    double xAtY(double y) const;
    /// rad in [0, pi/2]: the angle between the two lines.
    double angleTo(const ImageLine& other) const;
};

/// The points' mean; (0, 0) for none.
PointF meanOf(const std::vector<PointF>& points);

/// Total least squares (the line minimising perpendicular distances), as the original's
/// LSFittedLine. Needs >= 2 distinct points.
ImageLine fitLineTls(const std::vector<PointF>& points);

/// The end points of `points` projected onto `line`: the two extremes along it.
void lineExtent(const ImageLine& line, const std::vector<PointF>& points, PointF& a, PointF& b);

} // namespace fieldsight
