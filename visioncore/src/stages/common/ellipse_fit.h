// Ellipses in the image: the centre circle seen in perspective.
#pragma once

#include "visioncore/basics/geometry.h"

#include <optional>
#include <vector>

namespace fieldsight {

/// An ellipse with semi-axes `a` along the direction (cos_t, sin_t) and `b` across it.
struct ImageEllipse
{
    PointF centre;
    double a = 1;
    double b = 1;
    double cos_t = 1;
    double sin_t = 0;

    /// px, to first order: how far p lies from the outline, across it (exact on the outline's
    /// axes points and for a circle; within a quarter px for points 1 px off a 120 x 10 one).
    double distance(const PointF& p) const;
};

/// The least-squares ellipse through `points` (the conic A x^2 + B xy + C y^2 + D x + E y = 1
/// about their mean), or nothing with fewer than 8 points, a semi-axis under `min_axis` or over
/// `max_axis` px, or a mean distance of the points from it over `max_mean_error` px: points that
/// lie on no ellipse.
std::optional<ImageEllipse> fitImageEllipse(const std::vector<PointF>& points, double min_axis,
                                            double max_axis, double max_mean_error);

} // namespace fieldsight
