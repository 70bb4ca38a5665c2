// Small geometric value types shared by the core: image points and the kinematic horizon.
#pragma once

#include <cmath>

namespace fieldsight {

/// An image pixel position: origin top-left, x right, y down.
struct PixelPoint
{
    int x = 0; ///< px
    int y = 0; ///< px
    friend bool operator==(const PixelPoint&, const PixelPoint&) = default;
};

struct PointF
{
    double x = 0; ///< px
    double y = 0; ///< px
    friend bool operator==(const PointF&, const PointF&) = default;
};

/// The kinematic horizon as image y at x = 0 and at x = width-1 (SPEC §4). Everything above it is
/// sky; the default (0, 0) is the top row, meaning "search the whole image".
struct Horizon
{
    double y_left = 0;  ///< px, image y at x = 0
    double y_right = 0; ///< px, image y at x = width-1

    /// The largest |y| a horizon end may have: a million rows, far beyond any camera's tilt, and
    /// small enough that a row computed from it fits an int.
    static constexpr double kMaxRows = 1e6;

    double yAt(double x, int width) const
    {
        if (width <= 1)
            return y_left;
        return y_left + (y_right - y_left) * x / double(width - 1);
    }
    /// Both ends finite and within kMaxRows. Readers refuse other horizons at the file; the
    /// blackboard replaces one that still arrives (a DataWrapper of another source) by the top
    /// row and says so.
    bool isPlausible() const
    {
        return std::isfinite(y_left) && std::isfinite(y_right) && std::abs(y_left) <= kMaxRows &&
               std::abs(y_right) <= kMaxRows;
    }
    /// SPEC §4: a stream without a horizon gives the top row, (0, 0).
    bool known() const { return y_left != 0 || y_right != 0; }
    friend bool operator==(const Horizon&, const Horizon&) = default;
};

} // namespace fieldsight
