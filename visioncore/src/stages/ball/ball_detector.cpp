// Ball detection. The original (BallDetectorShannon, "BROKEN" in its own comment) removed every
// edge point outside a 1-sigma box around the mean, which on a clean ball discards the ball's own
// edges, then walked from a geometric mean; it found about half the visible balls. Here the edge
// points (at sub-pixel pixel borders) are clustered, and a circle is fitted to a cluster with
// RANSAC, so edges against an occluding robot or the image border do not pull the fit.
#include "stages/ball/ball_detector.h"

#include "stages/common/ransac.h"
#include "stages/common/stage_util.h"
#include "visioncore/framework/blackboard.h"
#include "visioncore/percepts/ball.h"

#include <Eigen/Dense>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numeric>

namespace fieldsight {

namespace {

struct Circle
{
    PointF centre;
    double radius = 0;

    static constexpr int kSampleSize = 3;
    bool fromSample(const PointF* s)
    {
        // Circumcircle of three points.
        const double ax = s[0].x, ay = s[0].y, bx = s[1].x, by = s[1].y, cx = s[2].x, cy = s[2].y;
        const double d = 2 * (ax * (by - cy) + bx * (cy - ay) + cx * (ay - by));
        if (std::abs(d) < 1e-6)
            return false;
        const double a2 = ax * ax + ay * ay, b2 = bx * bx + by * by, c2 = cx * cx + cy * cy;
        centre = {(a2 * (by - cy) + b2 * (cy - ay) + c2 * (ay - by)) / d,
                  (a2 * (cx - bx) + b2 * (ax - cx) + c2 * (bx - ax)) / d};
        radius = std::hypot(ax - centre.x, ay - centre.y);
        return std::isfinite(radius);
    }
    /// px, distance from the outline; V is float, double or RANSAC's Lanes (four points).
    template <class V> V errorOf(V x, V y) const
    {
        const V dx = x - V(centre.x), dy = y - V(centre.y);
        return absOf(sqrtOf(dx * dx + dy * dy) - V(radius));
    }
    double error(const PointF& p) const { return errorOf(p.x, p.y); }
};

/// Algebraic least-squares circle (Kasa): x^2 + y^2 + D x + E y + F = 0.
bool fitCircle(const std::vector<PointF>& pts, Circle& out)
{
    if (pts.size() < 3)
        return false;
    Eigen::Matrix3d a = Eigen::Matrix3d::Zero();
    Eigen::Vector3d b = Eigen::Vector3d::Zero();
    for (const PointF& p : pts) {
        const Eigen::Vector3d row(p.x, p.y, 1.0);
        a += row * row.transpose();
        b -= row * (p.x * p.x + p.y * p.y);
    }
    const Eigen::FullPivLU<Eigen::Matrix3d> lu(a);
    if (lu.rank() < 3)
        return false;
    const Eigen::Vector3d s = lu.solve(b);
    out.centre = {-s[0] / 2, -s[1] / 2};
    const double r2 = out.centre.x * out.centre.x + out.centre.y * out.centre.y - s[2];
    if (!(r2 > 0))
        return false;
    out.radius = std::sqrt(r2);
    return true;
}

/// Connected groups of points closer than `link` to some other member, largest first. A small
/// union-find rather than cv::partition: the same O(n^2) pairing, but no conversion of the points,
/// and groups numbered by first member, so the order of equal-sized groups (which decides which
/// cluster is tried first) is fixed by the scan order, not by cv::partition's labelling.
/// `parent` and `slot` are scratch.
std::vector<std::vector<PointF>> cluster(const std::vector<PointF>& pts, double link,
                                         std::vector<std::size_t>& parent, std::vector<int>& slot)
{
    parent.resize(pts.size());
    std::iota(parent.begin(), parent.end(), 0);
    const auto find = [&](std::size_t i) {
        while (parent[i] != i)
            i = parent[i] = parent[parent[i]];
        return i;
    };
    const double l2 = link * link;
    for (std::size_t i = 0; i < pts.size(); ++i)
        for (std::size_t j = i + 1; j < pts.size(); ++j) {
            const double dx = pts[i].x - pts[j].x, dy = pts[i].y - pts[j].y;
            if (dx * dx + dy * dy <= l2)
                parent[find(i)] = find(j);
        }
    std::vector<std::vector<PointF>> groups;
    slot.assign(pts.size(), -1);
    for (std::size_t i = 0; i < pts.size(); ++i) {
        const std::size_t r = find(i);
        if (slot[r] < 0) {
            slot[r] = int(groups.size());
            groups.emplace_back();
        }
        groups[std::size_t(slot[r])].push_back(pts[i]);
    }
    std::stable_sort(groups.begin(), groups.end(),
                     [](const auto& a, const auto& b) { return a.size() > b.size(); });
    return groups;
}

/// Fraction of carpet and line pixels on two rings just outside the circle (at r + 2 and
/// 1.5 r + 3 px), of those in the image; 1 when fewer than 8 are.
double fieldAround(const Blackboard& bb, const Circle& c)
{
    constexpr int kAngles = 32;
    static const auto directions = [] {
        std::array<PointF, kAngles> d{};
        for (int a = 0; a < kAngles; ++a)
            d[std::size_t(a)] = {std::cos(2 * 3.14159265358979 * a / kAngles),
                                 std::sin(2 * 3.14159265358979 * a / kAngles)};
        return d;
    }();
    int total = 0, field = 0;
    for (const double r : {c.radius + 2, 1.5 * c.radius + 3})
        for (const PointF& d : directions) {
            const int x = int(std::lround(c.centre.x + r * d.x));
            const int y = int(std::lround(c.centre.y + r * d.y));
            if (x < 0 || y < 0 || x >= bb.width() || y >= bb.height())
                continue;
            ++total;
            const Colour colour = bb.classify(x, y);
            field += colour == Colour::Green || colour == Colour::White;
        }
    return total < 8 ? 1.0 : double(field) / total;
}

/// Fraction of ball-coloured pixels in the square inscribed in the circle.
double colourFraction(const Blackboard& bb, const Circle& c, Colour colour)
{
    const double half = c.radius / std::sqrt(2.0);
    const int x0 = std::max(0, int(std::ceil(c.centre.x - half)));
    const int x1 = std::min(bb.width() - 1, int(std::floor(c.centre.x + half)));
    const int y0 = std::max(0, int(std::ceil(c.centre.y - half)));
    const int y1 = std::min(bb.height() - 1, int(std::floor(c.centre.y + half)));
    const int step = std::max(1, int(half / 4));
    int total = 0, hits = 0;
    for (int y = y0; y <= y1; y += step)
        for (int x = x0; x <= x1; x += step) {
            ++total;
            hits += bb.classify(x, y) == colour;
        }
    return total ? double(hits) / total : 0.0;
}

/// How far the ball colour reaches across the circle's vertical diameter against across its
/// horizontal one, or the inverse, whichever is at most 1: from its first to its last pixel of
/// the colour, over the diameter's pixels in the image (1 when a diameter has fewer than 3
/// there). A ball is a disc of its colour, as wide one way as the other however sparsely the
/// table covers it; a rim or a highlight band that the table calls ball colour is thin one way.
double diameterBalance(const Blackboard& bb, const Circle& c, Colour colour)
{
    const int r = int(std::floor(c.radius));
    const int cx = int(std::lround(c.centre.x)), cy = int(std::lround(c.centre.y));
    std::array<double, 2> reach{};
    for (std::size_t axis = 0; axis < 2; ++axis) {
        int total = 0, first = -1, last = -1;
        for (int t = -r; t <= r; ++t) {
            const int x = cx + (axis == 0 ? t : 0), y = cy + (axis == 1 ? t : 0);
            if (x < 0 || y < 0 || x >= bb.width() || y >= bb.height())
                continue;
            if (bb.classify(x, y) == colour) {
                if (first < 0)
                    first = total;
                last = total;
            }
            ++total;
        }
        if (total < 3)
            return 1.0;
        reach[axis] = first < 0 ? 0.0 : double(last - first + 1) / total;
    }
    const double most = std::max(reach[0], reach[1]);
    return most > 0 ? std::min(reach[0], reach[1]) / most : 0.0;
}

} // namespace

const StageInfo& BallDetector::info() const
{
    static const StageInfo info{
        "ball",
        "Ball",
        "Clusters the edges of ball-coloured runs below the green horizon and fits a circle to "
        "them.",
        true,
        {"transitions", "scan_lines", "green_horizon", "image", "lut"},
        {},
        {&perceptKind<Ball>()},
        {{"ball.edge_points", "Ball edge points", debug_colour::kSkyBlue},
         {"ball.rejected", "Rejected balls", debug_colour::kRejected}}};
    return info;
}

bool BallDetector::rejects(const Blackboard& bb, PointF centre, double radius, Colour colour,
                           std::string* why) const
{
    const int w = bb.width(), h = bb.height();
    // The reason is put in words only when asked for: `why ? say(...) : true`.
    const auto say = [why](std::string reason) {
        *why = std::move(reason);
        return true;
    };
    if (radius < m_min_radius)
        return why ? say("radius " + oneDecimal(radius) + " px, under min_radius") : true;
    if (radius > m_max_radius * h)
        return why ? say("radius " + oneDecimal(radius) + " px, over max_radius of the image")
                   : true;
    if (centre.x < 0 || centre.y < 0 || centre.x > w - 1 || centre.y > h - 1)
        return why ? say("centre outside the image") : true;
    // With the camera's horizon, the angle below it sets the distance along the ground and so the
    // radius: r = radius_at_nadir * sin(angle), the angle from the focal length.
    const Horizon& k = bb.kinematic_horizon;
    if (m_focal_length > 0 && k.known()) {
        const double depth = centre.y - k.yAt(centre.x, w);
        if (depth <= 0)
            return why ? say("above the kinematic horizon") : true;
        const double expected = m_radius_at_nadir * std::sin(std::atan(depth / m_focal_length));
        const double lo = expected * (1 - m_radius_tolerance) - m_radius_slack;
        const double hi = expected * (1 + m_radius_tolerance) + m_radius_slack;
        if (radius < lo || radius > hi)
            return why ? say("radius " + oneDecimal(radius) + " px, not " +
                             oneDecimal(std::max(0.0, lo)) + "-" + oneDecimal(hi) +
                             " px as its distance wants")
                       : true;
    }
    const double orange = colourFraction(bb, {centre, radius}, colour);
    if (orange < m_min_orange_fraction)
        return why ? say("ball colour " + oneDecimal(100 * orange) +
                         " %, under min_orange_fraction")
                   : true;
    if (m_min_diameter_balance > 0) {
        const double balance = diameterBalance(bb, {centre, radius}, colour);
        if (balance < m_min_diameter_balance)
            return why ? say("ball colour reaches across one way " + oneDecimal(100 * balance) +
                             " % as far as the other, under min_diameter_balance")
                       : true;
    }
    if (m_min_field_around > 0) {
        const double field = fieldAround(bb, {centre, radius});
        if (field < m_min_field_around)
            return why ? say("carpet or line " + oneDecimal(100 * field) +
                             " % around it, under min_field_around")
                       : true;
    }
    return false;
}

void BallDetector::run(Blackboard& bb)
{
    const auto& hs = bb.horizontal_transitions[TransitionClass::Ball];
    const auto& vs = bb.vertical_transitions[TransitionClass::Ball];
    if (hs.empty() && vs.empty())
        return;
    const int w = bb.width(), h = bb.height();
    const GreenHorizon& gh = bb.green_horizon;
    const Colour colour = !hs.empty() ? hs.front().colour : vs.front().colour;

    // Edge points sit on pixel borders: half a pixel outside the run. Ends at the image border or
    // at the top of a vertical scan are not ball edges.
    std::vector<PointF>& edges = m_edges;
    std::vector<const ColourSegment*>& chords = m_chords;
    edges.clear();
    chords.clear();
    for (const ColourSegment& s : hs) {
        const PointF c = s.centre();
        if (!gh.isBelow(int(c.x), int(c.y)))
            continue;
        if (s.x0 > 0 && s.x1 < w) // a chord cut by the border is no diameter
            chords.push_back(&s);
        if (s.x0 > 0)
            edges.push_back({s.x0 - 0.5, double(s.y0)});
        if (s.x1 < w)
            edges.push_back({s.x1 - 0.5, double(s.y0)});
    }
    for (const ColourSegment& s : vs) {
        if (s.y0 > gh.yAt(s.x0))
            edges.push_back({double(s.x0), s.y0 - 0.5});
        if (s.y1 < h)
            edges.push_back({double(s.x0), s.y1 - 0.5});
    }
    if (auto* d = bb.debug.layer("ball.edge_points"))
        d->add(pointsShape(edges, debug_colour::kSkyBlue, 2));

    const double spacing = bb.horizontalScanSpacing();
    RansacRng rng{m_seed.value()};
    RansacParams params;
    params.max_error = m_max_fit_error;
    params.iterations = m_iterations;
    DebugDrawing* rejected = bb.debug.layer("ball.rejected");
    std::string why;
    const auto accept = [&](const Circle& c) {
        if (!rejects(bb, c.centre, c.radius, colour, rejected ? &why : nullptr))
            return true;
        if (rejected)
            addRejected(*rejected, circleShape(c.centre, c.radius, {}), why);
        return false;
    };

    bool found = false;
    Circle ball;
    for (auto& group : cluster(edges, m_cluster_distance, m_parent, m_slot)) {
        if (group.size() < 3)
            break;
        Circle c;
        if (!fitCircle(group, c))
            continue;
        // A clean ball: the least-squares fit explains every edge point. Otherwise (an occluding
        // robot, the image border) RANSAC finds the points that lie on one circle.
        const bool clean = std::all_of(group.begin(), group.end(), [&](const PointF& p) {
            return c.error(p) < m_max_fit_error;
        });
        if (!clean && group.size() >= 5) {
            // Shading and highlights break a real ball's colour into pieces, so the cluster also
            // holds edges inside the ball: judge a circle by how much of its own outline the scan
            // lines confirm (about 8 r / spacing edge points), not by the share of the cluster.
            params.min_points = 4;
            RansacResult<Circle> r;
            std::vector<PointF> pts = group;
            if (!ransacFindModel(pts, params, rng, r) || !fitCircle(r.inliers, c))
                continue;
            const double expected = 8 * c.radius / spacing;
            if (double(r.inliers.size()) < std::max(4.0, m_min_edge_support * expected)) {
                if (rejected)
                    addRejected(*rejected, circleShape(c.centre, c.radius, {}),
                                std::to_string(r.inliers.size()) +
                                    " edge points on the outline, under min_edge_support");
                continue;
            }
        }
        if (accept(c)) {
            ball = c;
            found = true;
            break;
        }
    }
    if (!found && !chords.empty()) {
        // A ball too small for three edge points: the longest chord stands for its diameter. A
        // ball wider than a few scan lines' spacing crosses enough of them to give a cluster of
        // edge points, so a longer chord is no ball's (a robot's red arm): the longest within.
        const double widest =
            m_max_chord_spacings > 0
                ? m_max_chord_spacings * std::max(spacing, double(bb.verticalScanSpacing()))
                : std::numeric_limits<double>::infinity();
        const ColourSegment* longest = nullptr;
        for (const ColourSegment* s : chords) {
            if (s->length() > widest) {
                if (rejected)
                    addRejected(*rejected,
                                circleShape({(s->x0 + s->x1 - 1) / 2.0, double(s->y0)},
                                            s->length() / 2.0, {}),
                                "a chord of " + std::to_string(s->length()) +
                                    " px, over max_chord_spacings");
            } else if (!longest || s->length() > longest->length()) {
                longest = s;
            }
        }
        if (longest) {
            const Circle c{{(longest->x0 + longest->x1 - 1) / 2.0, double(longest->y0)},
                           longest->length() / 2.0};
            if (accept(c)) {
                ball = c;
                found = true;
            }
        }
    }
    if (found)
        bb.percepts.output<Ball>().push_back({ball.centre.x, ball.centre.y, ball.radius});
}

} // namespace fieldsight
