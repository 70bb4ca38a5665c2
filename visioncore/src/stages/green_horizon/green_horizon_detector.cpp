// Green horizon: column scan, upper outlier removal, upper convex hull.
#include "stages/green_horizon/green_horizon_detector.h"

#include "stages/common/stage_util.h"
#include "visioncore/framework/blackboard.h"
#include "visioncore/percepts/field_boundary.h"

#include <algorithm>
#include <cmath>
#include <iterator>

namespace fieldsight {

namespace {

/// The hull cannot bridge a dip at the image border (a robot standing at the edge of the view):
/// the border column's point ends the hull, low. Such an end point lies well below the extension
/// of the next hull segment and no other scan point supports its own segment; it is dropped, and
/// GreenHorizon::set extrapolates the field edge to the border instead.
void dropEndDips(std::vector<PointF>& hull, const std::vector<PixelPoint>& points, double margin,
                 double max_span, double pixel_scale)
{
    const auto supporters = [&](const PointF& a, const PointF& b) {
        int n = 0;
        for (const PixelPoint& p : points) {
            if (p.x < std::min(a.x, b.x) || p.x > std::max(a.x, b.x))
                continue;
            const double y = a.y + (b.y - a.y) * (p.x - a.x) / (b.x - a.x);
            n += std::abs(p.y - y) <= 1.5 * pixel_scale;
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

std::optional<int> GreenHorizonDetector::fieldStart(Blackboard& bb, int x, int y0,
                                                    std::optional<double> horizon)
{
    const int h = bb.height();
    const int min_green = m_min_green_pixels;
    const int max_gap = m_max_gap;
    const double density = m_min_density;
    const cv::Mat& image = bb.image();
    const ColourLut& lut = bb.lut();
    const std::ptrdiff_t step = std::ptrdiff_t(image.step[0]);
    // Every run of the column that is green enough, top to bottom. A run bridges gaps of up to
    // max_gap pixels (far lines and the thin strip beyond them blend into colours no class
    // claims), like the transition filter's field-noise rules (the original required min_green
    // pixels of uninterrupted green and so put the horizon below the far touch line). Its front
    // moves down while it is sparser than min_green_density: speckle on a wall never gathers
    // enough dense green.
    std::vector<Span>& runs = m_runs;
    runs.clear();
    std::vector<int>& rows = m_run_rows;
    rows.clear();
    std::size_t front = 0;
    int gap = 0;
    const auto close = [&] {
        if (int(rows.size() - front) >= min_green)
            runs.push_back({rows[front], rows.back()});
        rows.clear();
        front = 0;
        gap = 0;
    };
    const bool first_run = m_max_field_gap <= 0;
    const bool any_row_thins = density > 1;
    // Walked by pointer: the image and LUT cannot change under the loop.
    const std::uint8_t* p = image.ptr<std::uint8_t>(y0) + 3 * x;
    for (int y = y0; y < h; ++y, p += step) {
        if (lut.classify(p[0], p[1], p[2]) == Colour::Green) {
            // Only a gap (rows since the run's last green) can thin the run below the density: a
            // green row after a green row adds one to both the run's green and its length, and a
            // share of at most 1 that held for the one holds for the other.
            const bool after_gap = gap > 0;
            rows.push_back(y);
            gap = 0;
            while ((after_gap || any_row_thins) && rows.size() - front > 1 &&
                   double(rows.size() - front) < density * double(y - rows[front] + 1))
                ++front;
            if (first_run && int(rows.size() - front) >= min_green)
                return rows[front]; // the first run is the field's (the original rule)
        } else if (rows.size() > front && ++gap > max_gap) {
            close();
        }
    }
    close();
    if (runs.empty())
        return std::nullopt;
    // The field is the run nearest the camera and the runs above it that a gap no wider than a
    // field line there separates (a line's height in the image grows with the square of its
    // depth below the horizon, up to max_field_gap at the bottom row). A green run above a wider
    // gap (a wall behind the field that the table calls green in places) is not the field.
    // Without a kinematic horizon the depth is unknown: any gap up to max_field_gap is bridged.
    const double depth = horizon ? std::max(1.0, double(h) - *horizon) : 1.0;
    std::size_t top = runs.size() - 1;
    while (top > 0) {
        const int below = runs[top].first;
        const double t = horizon ? std::clamp((double(below) - *horizon) / depth, 0.0, 1.0) : 1.0;
        const double allowed = std::max(double(max_gap), m_max_field_gap * t * t);
        if (double(below - runs[top - 1].second - 1) > allowed)
            break;
        --top;
    }
    for (std::size_t i = 0; i < top; ++i)
        bb.gh_thrown_points.push_back({x, runs[i].first});
    return runs[top].first;
}

void GreenHorizonDetector::run(Blackboard& bb)
{
    const int w = bb.width();
    const int h = bb.height();
    const int spacing = m_scan_spacing;
    auto& points = bb.gh_scan_points;
    const Horizon& k = bb.kinematic_horizon;
    const bool known = k.known();
    for (int x = 0; x < w; x += spacing) {
        // Clamped as a double: the blackboard bounds the horizon, but a row is only an int here.
        const int y0 = int(std::clamp(k.yAt(x, w), 0.0, double(h - 1)));
        const std::optional<double> horizon =
            known ? std::optional<double>(std::min(k.yAt(x, w), double(h - 1))) : std::nullopt;
        if (const auto start = fieldStart(bb, x, y0, horizon))
            points.push_back({x, *start});
    }
    // The thrown points so far are green runs above a gap; then those above the edge's lines;
    // those added last are outliers.
    const std::size_t above_gaps = bb.gh_thrown_points.size();
    throwAboveEdge(bb);
    const std::size_t above_edge = bb.gh_thrown_points.size();

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
        drawThrown(bb, above_gaps, above_edge);
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
    dropEndDips(hull, points, int(m_min_green_pixels), 2.0 * spacing, pixelScale());
    bb.green_horizon.set(hull, w, h);
    bb.percepts.output<FieldBoundary>().push_back({bb.green_horizon.hull()});

    drawThrown(bb, above_gaps, above_edge);
}

void GreenHorizonDetector::throwAboveEdge(Blackboard& bb)
{
    const double tolerance = m_edge_lines;
    std::vector<PixelPoint>& points = bb.gh_scan_points;
    // A line needs a few columns' agreement: two points make any line.
    constexpr int kMinSupport = 4;
    constexpr double kDeepDip = 0.25;
    if (tolerance <= 0)
        return;
    const std::optional<EdgeModel> edge = fitEdge(points, tolerance, kMinSupport, m_edge_scratch);
    if (!edge)
        return;
    const auto above = [&](const PixelPoint& p) { return p.y < edge->at(p.x) - tolerance; };
    std::copy_if(points.begin(), points.end(), std::back_inserter(bb.gh_thrown_points), above);
    points.erase(std::remove_if(points.begin(), points.end(), above), points.end());
    // Where something hides the edge at the image's side (a robot, the camera's own shoulder),
    // the edge goes on as the lines say: a side column's point deep below them (more than a
    // quarter of the way down to the bottom row), or none, is put on them, and the hull bridges
    // the dip. A shallower dip is the edge curving away (a corner's far side, the lens).
    const int last = (bb.width() - 1) / m_scan_spacing * m_scan_spacing; // the last column scanned
    for (const int x : {0, last}) {
        const int y = int(std::lround(std::clamp(edge->at(x), 0.0, double(bb.height() - 1))));
        const bool left = x == 0;
        PixelPoint* end = points.empty() ? nullptr : left ? &points.front() : &points.back();
        if (end && end->x == x) {
            if (end->y > y + std::max(tolerance, kDeepDip * (bb.height() - y)))
                end->y = y;
        } else {
            points.insert(left ? points.begin() : points.end(), PixelPoint{x, y});
        }
    }
}

void GreenHorizonDetector::drawThrown(Blackboard& bb, std::size_t above_gaps,
                                      std::size_t above_edge) const
{
    DebugDrawing* d = bb.debug.layer("green_horizon.thrown_points");
    if (!d)
        return;
    // One shape for each reason, its note saying which (the inspector shows it).
    const std::vector<PixelPoint>& thrown = bb.gh_thrown_points;
    const auto at = [&](std::size_t i) {
        return thrown.begin() + std::ptrdiff_t(std::min(i, thrown.size()));
    };
    const std::vector<PixelPoint> gaps(thrown.begin(), at(above_gaps)),
        edge(at(above_gaps), at(above_edge)), high(at(above_edge), thrown.end());
    if (!gaps.empty())
        d->add(pointsShape(gaps, debug_colour::kGrey, 3),
               "green above a gap wider than a field line there (max_field_gap): a wall, not "
               "the field");
    if (!edge.empty())
        d->add(pointsShape(edge, debug_colour::kGrey, 3),
               "more than " + oneDecimal(m_edge_lines) +
                   " px above the straight edge most columns agree on (edge_lines): green "
                   "behind the field");
    if (!high.empty())
        d->add(pointsShape(high, debug_colour::kGrey, 3),
               "more than " + oneDecimal(m_upper_threshold_mult) +
                   " standard deviations above the other columns' field start "
                   "(upper_threshold_mult)");
}

} // namespace fieldsight
