// The field's edge as one straight line, or two meeting at a corner, fitted to the green horizon's
// scan points: the carpet's edge is straight in the world, so green that lies above the line(s)
// most columns agree on is something behind the field (a wall or a seat the table calls green in
// places), however many columns it spans.
#pragma once

#include "visioncore/basics/geometry.h"

#include <algorithm>
#include <optional>
#include <vector>

namespace fieldsight {

/// y = a + b x, in image rows (y down).
struct EdgeLine
{
    double a = 0;
    double b = 0;
    double at(double x) const { return a + b * x; }
};

/// The edge: a line, or seen over a corner two, the lower of the two in the image at each column
/// (the corner is the farthest point, so the highest: y(x) is the larger of the two rows).
struct EdgeModel
{
    EdgeLine first;
    std::optional<EdgeLine> second;
    double at(double x) const
    {
        return second ? std::max(first.at(x), second->at(x)) : first.at(x);
    }
};

/// Scratch the fit reuses from frame to frame, so a frame allocates nothing once it has grown.
struct EdgeFitScratch
{
    std::vector<PixelPoint> on_first, below;
    std::vector<double> xs, ys; ///< a pool's points as doubles
};

/// The line through the most points within `tolerance` rows; a second line through at least
/// `min_support` of the points below it, where that leaves every point on the first line on the
/// edge (a corner, not a robot's feet). None with fewer than `min_support` points on a line.
/// Deterministic: every pair of points is tried (a frame has a few dozen).
std::optional<EdgeModel> fitEdge(const std::vector<PixelPoint>& points, double tolerance,
                                 int min_support, EdgeFitScratch& scratch);

} // namespace fieldsight
