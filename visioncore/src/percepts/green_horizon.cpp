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

void GreenHorizon::set(const std::vector<PointF>& hull, int width, int height)
{
    m_width = width;
    m_column_y.assign(std::size_t(width), height - 1);
    if (hull.empty() || width <= 0) {
        m_hull = {{0, double(height - 1)}, {double(width - 1), double(height - 1)}};
        return;
    }
    // Built in m_hull itself, so its memory is reused frame after frame.
    if (hull.size() == 1) {
        const double y = clampY(hull[0].y, height);
        m_hull = {{0, y}, {double(width - 1), y}};
    } else {
        m_hull.assign(hull.begin(), hull.end());
    }
    if (m_hull.front().x > 0) {
        const PointF start{0, clampY(extrapolate(m_hull[0], m_hull[1], 0), height)};
        m_hull.insert(m_hull.begin(), start);
    }
    const std::size_t n = m_hull.size();
    if (m_hull.back().x < width - 1) {
        const PointF end{double(width - 1),
                         clampY(extrapolate(m_hull[n - 2], m_hull[n - 1], width - 1), height)};
        m_hull.push_back(end);
    }
    std::size_t seg = 0;
    for (int x = 0; x < width; ++x) {
        while (seg + 2 < m_hull.size() && m_hull[seg + 1].x < x)
            ++seg;
        const double y = extrapolate(m_hull[seg], m_hull[seg + 1], x);
        m_column_y[std::size_t(x)] =
            int(clampY(y, height) + 0.5); // lround (a libm call) for y >= 0
    }
}

void GreenHorizon::setTopRow(int width, int height)
{
    m_width = width;
    m_column_y.assign(std::size_t(std::max(width, 0)), 0);
    m_hull = {{0, 0}, {double(width - 1), 0}};
    (void)height;
}

} // namespace fieldsight
