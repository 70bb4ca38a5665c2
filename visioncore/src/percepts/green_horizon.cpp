// The green horizon hull and its per-column interpolation.
#include "visioncore/percepts/green_horizon.h"

#include <algorithm>
#include <cmath>

namespace fieldsight {

namespace {
double clampY(double y, int height)
{
    return std::clamp(y, 0.0, double(height - 1));
}

double extrapolate(const PointF& a, const PointF& b, double x)
{
    if (b.x == a.x)
        return a.y;
    return a.y + (b.y - a.y) * (x - a.x) / (b.x - a.x);
}
} // namespace

void GreenHorizon::set(std::vector<PointF> hull, int width, int height)
{
    m_width = width;
    m_column_y.assign(std::size_t(width), height - 1);
    if (hull.empty() || width <= 0) {
        m_hull = {{0, double(height - 1)}, {double(width - 1), double(height - 1)}};
        return;
    }
    if (hull.size() == 1) {
        const double y = clampY(hull[0].y, height);
        hull = {{0, y}, {double(width - 1), y}};
    }
    if (hull.front().x > 0)
        hull.insert(hull.begin(), {0, clampY(extrapolate(hull[0], hull[1], 0), height)});
    const std::size_t n = hull.size();
    if (hull.back().x < width - 1)
        hull.push_back(
            {double(width - 1), clampY(extrapolate(hull[n - 2], hull[n - 1], width - 1), height)});
    std::size_t seg = 0;
    for (int x = 0; x < width; ++x) {
        while (seg + 2 < hull.size() && hull[seg + 1].x < x)
            ++seg;
        const double y = extrapolate(hull[seg], hull[seg + 1], x);
        m_column_y[std::size_t(x)] =
            int(clampY(y, height) + 0.5); // lround (a libm call) for y >= 0
    }
    m_hull = std::move(hull);
}

void GreenHorizon::setTopRow(int width, int height)
{
    m_width = width;
    m_column_y.assign(std::size_t(std::max(width, 0)), 0);
    m_hull = {{0, 0}, {double(width - 1), 0}};
    (void)height;
}

} // namespace fieldsight
