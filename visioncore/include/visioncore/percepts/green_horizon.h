// The green horizon: the upper convex hull of where the field starts, as a polyline and per column.
#pragma once

#include "visioncore/basics/geometry.h"

#include <vector>

namespace fieldsight {

class GreenHorizon
{
public:
    /// Sets the hull (x ascending, at least one point), extending it to x = 0 and x = width-1 and
    /// interpolating every column. The original truncated the interpolation to int and crashed
    /// with fewer than two hull points; we round and accept one point (a flat horizon).
    void set(const std::vector<PointF>& hull, int width, int height);
    /// The whole image is field: the horizon is the top row.
    void setTopRow(int width, int height);

    const std::vector<PointF>& hull() const { return m_hull; }
    /// px, the horizon's y at column x (clamped to the image).
    int yAt(int x) const
    {
        return m_column_y[std::size_t(x < 0 ? 0 : (x >= m_width ? m_width - 1 : x))];
    }
    bool isBelow(int x, int y) const { return y > yAt(x); }
    int width() const { return m_width; }

private:
    std::vector<PointF> m_hull;
    std::vector<int> m_column_y;
    int m_width = 0;
};

} // namespace fieldsight
