// Green horizon: column scan, upper outlier removal, upper convex hull.
#include "stages/green_horizon/green_horizon_detector.h"

#include "stages/common/stage_util.h"
#include "visioncore/framework/blackboard.h"
#include "visioncore/percepts/field_boundary.h"

#include <algorithm>
#include <cmath>

namespace fieldsight {

namespace {

/// The hull cannot bridge a dip at the image border (a robot standing at the edge of the view):
/// the border column's point ends the hull, low. Such an end point lies well below the extension
/// of the next hull segment and no other scan point supports its own segment; it is dropped, and
/// GreenHorizon::set extrapolates the field edge to the border instead.
void dropEndDips(std::vector<PointF>& hull, const std::vector<PixelPoint>& points, double margin,
                 double max_span)
{
    const auto supporters = [&](const PointF& a, const PointF& b) {
        int n = 0;
        for (const PixelPoint& p : points) {
            if (p.x < std::min(a.x, b.x) || p.x > std::max(a.x, b.x))
                continue;
            const double y = a.y + (b.y - a.y) * (p.x - a.x) / (b.x - a.x);
            n += std::abs(p.y - y) <= 1.5;
        }
        return n;
    };
    // A dip: a short end segment (a scan spacing or two) whose end lies below the extension of
    // the segment next to it.
    const auto dip = [&](const PointF& end, const PointF& next, const PointF& a, const PointF& b) {
        if (std::abs(next.x - end.x) > max_span || supporters(end, next) > 2)
            return false;
        const double y = a.y + (b.y - a.y) * (end.x - a.x) / (b.x - a.x);
        return end.y - y > margin;
    };
    while (hull.size() >= 3 && dip(hull[0], hull[1], hull[1], hull[2]))
        hull.erase(hull.begin());
    while (hull.size() >= 3) {
        const std::size_t n = hull.size();
        if (!dip(hull[n - 1], hull[n - 2], hull[n - 3], hull[n - 2]))
            break;
        hull.pop_back();
    }
}

} // namespace

const StageInfo& GreenHorizonDetector::info() const
{
    static const StageInfo info{
        "green_horizon",
        "Green horizon",
        "Where the field starts: the upper hull of the first green in evenly spaced columns.",
        false,
        {"image", "lut", "kinematic_horizon"},
        {"green_horizon"},
        {&perceptKind<FieldBoundary>()},
        {{"green_horizon.kinematic_horizon", "Kinematic horizon", debug_colour::kBlue},
         {"green_horizon.scan_points", "Scan points", debug_colour::kLime},
         {"green_horizon.thrown_points", "Thrown points", debug_colour::kGrey}}};
    return info;
}

void GreenHorizonDetector::run(Blackboard& bb)
{
    const int w = bb.width();
    const int h = bb.height();
    const int spacing = m_scan_spacing;
    const int min_green = m_min_green_pixels;
    const int max_gap = m_max_gap;

    auto& points = bb.gh_scan_points;
    const cv::Mat& image = bb.image();
    const ColourLut& lut = bb.lut();
    const std::ptrdiff_t step = std::ptrdiff_t(image.step[0]);
    for (int x = 0; x < w; x += spacing) {
        // Clamped as a double: the blackboard bounds the horizon, but a row is only an int here.
        const int y0 = int(std::clamp(bb.kinematic_horizon.yAt(x, w), 0.0, double(h - 1)));
        // A run starts on green and counts green pixels; it bridges gaps of up to max_gap pixels
        // (far lines and the thin strip beyond them blend into colours no class claims), like
        // the transition filter's field-noise rules. The original required min_green pixels of
        // uninterrupted green and so put the horizon below the far touch line.
        int green = 0;
        int gap = 0;
        int start = 0;
        // Walked by pointer: the image and LUT cannot change under the loop, but the compiler
        // cannot know that across the push_back below.
        const std::uint8_t* p = image.ptr<std::uint8_t>(y0) + 3 * x;
        for (int y = y0; y < h; ++y, p += step) {
            if (lut.classify(p[0], p[1], p[2]) == Colour::Green) {
                if (green == 0)
                    start = y;
                gap = 0;
                if (++green == min_green) {
                    points.push_back({x, start});
                    break;
                }
            } else if (green > 0 && ++gap > max_gap) {
                green = 0;
                gap = 0;
            }
        }
    }

    if (auto* d = bb.debug.layer("green_horizon.kinematic_horizon"))
        d->add(lineShape({0, bb.kinematic_horizon.y_left},
                         {double(w - 1), bb.kinematic_horizon.y_right}, debug_colour::kBlue));
    if (auto* d = bb.debug.layer("green_horizon.scan_points"))
        d->add(pointsShape(points, debug_colour::kLime, 3)); // not the boundary's magenta

    if (points.size() < 2) {
        // No field in view: the horizon is the bottom row (original behaviour; unlike the original
        // the scan points above are this frame's, never stale ones).
        bb.green_horizon.set({}, w, h);
        bb.percepts.output<FieldBoundary>().push_back({bb.green_horizon.hull()});
        return;
    }

    // Points unusually high in the image (green above the field: posters, shirts) are dropped.
    double mean = 0;
    for (const auto& p : points)
        mean += p.y;
    mean /= double(points.size());
    double var = 0;
    for (const auto& p : points)
        var += (p.y - mean) * (p.y - mean);
    const double sigma = std::sqrt(var / double(points.size()));
    const double threshold = mean - m_upper_threshold_mult * sigma;

    std::vector<PointF>& hull = m_hull;
    hull.clear();
    for (const auto& p : points) {
        if (p.y < threshold) {
            bb.gh_thrown_points.push_back(p);
            continue;
        }
        // Upper convex hull by Andrew's monotone chain: the envelope above every point, so dips
        // where a robot hides the field edge are bridged. Written here rather than with
        // cv::convexHull because the points already arrive sorted by x and only the upper chain
        // is wanted: one pass, no allocation, no conversion to cv::Point and back, and collinear
        // points dropped exactly as below (cv::convexHull would return the whole hull, to be cut).
        const PointF q{double(p.x), double(p.y)};
        while (hull.size() >= 2) {
            const PointF& o = hull[hull.size() - 2];
            const PointF& a = hull.back();
            const double cross = (a.x - o.x) * (q.y - o.y) - (a.y - o.y) * (q.x - o.x);
            if (cross > 0)
                break;
            hull.pop_back();
        }
        hull.push_back(q);
    }
    dropEndDips(hull, points, min_green, 2.0 * spacing);
    bb.green_horizon.set(hull, w, h);
    bb.percepts.output<FieldBoundary>().push_back({bb.green_horizon.hull()});

    if (auto* d = bb.debug.layer("green_horizon.thrown_points"))
        d->add(pointsShape(bb.gh_thrown_points, debug_colour::kGrey, 3));
}

} // namespace fieldsight
