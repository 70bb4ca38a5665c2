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

    /// px, approximately: how far p lies from the outline, along the ray from the centre (exact
    /// on the axes and for a circle; good enough to tell a point on the outline from one a few px
    /// off).
    double distance(const PointF& p) const;
};

/// The least-squares ellipse through `points` (OpenCV's fitEllipse), or nothing with fewer than
/// 8 points, a semi-axis under 2 px or over `max_axis`, or a mean distance of the points from it
/// over `max_mean_error` px: points that lie on no ellipse.
std::optional<ImageEllipse> fitImageEllipse(const std::vector<PointF>& points, double max_axis,
                                            double max_mean_error);

} // namespace fieldsight
