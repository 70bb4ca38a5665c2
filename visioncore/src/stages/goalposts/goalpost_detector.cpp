// Goalpost detection by RANSAC on post edges.
#include "stages/goalposts/goalpost_detector.h"

#include "stages/common/line_fit.h"
#include "stages/common/ransac.h"
#include "stages/common/stage_util.h"
#include "visioncore/framework/blackboard.h"
#include "visioncore/percepts/goalpost.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <numbers>
#include <stdexcept>

namespace fieldsight {

namespace {

/// One fitted post edge: its line, its end points (low = larger y) and how many points made it.
struct Edge
{
    ImageLine line;
    PointF low, high;
    std::size_t count = 0;
    double meanX() const { return (low.x + high.x) / 2; }
    double length() const { return std::hypot(low.x - high.x, low.y - high.y); }
};

std::vector<Edge> fitEdges(const std::vector<PointF>& points, const RansacParams& params,
                           int max_lines, RansacRng& rng)
{
    std::vector<Edge> edges;
    for (auto& r : ransacFindModels<ImageLine>(points, params, max_lines, rng)) {
        Edge e;
        e.line = fitLineTls(r.inliers);
        lineExtent(e.line, r.inliers, e.low, e.high);
        if (e.low.y < e.high.y)
            std::swap(e.low, e.high);
        e.count = r.inliers.size();
        edges.push_back(e);
    }
    return edges;
}

/// A post quad: bottom-left, top-left, top-right, bottom-right.
struct Quad
{
    PointF bl, tl, tr, br;
    double left() const { return std::min(bl.x, tl.x); }
    double right() const { return std::max(br.x, tr.x); }
    double top() const { return std::min(tl.y, tr.y); }
    double bottom() const { return std::max(bl.y, br.y); }
    double width() const { return (std::abs(br.x - bl.x) + std::abs(tr.x - tl.x)) / 2 + 1; }
    double height() const
    {
        return (std::hypot(bl.x - tl.x, bl.y - tl.y) + std::hypot(br.x - tr.x, br.y - tr.y)) / 2 +
               1;
    }
    PointF bottomCentre() const { return {(bl.x + br.x) / 2, (bl.y + br.y) / 2}; }
    PointF topCentre() const { return {(tl.x + tr.x) / 2, (tl.y + tr.y) / 2}; }
};

double meanEndDistance(const Edge& a, const Edge& b)
{
    const auto d = [](PointF p, PointF q) { return std::hypot(p.x - q.x, p.y - q.y); };
    return std::min(d(a.low, b.low) + d(a.high, b.high), d(a.low, b.high) + d(a.high, b.low)) / 2;
}

} // namespace

const StageInfo& GoalpostDetector::info() const
{
    static const StageInfo info{
        "goalposts",
        "Goalposts",
        "RANSAC lines through the left and right edges of goal-coloured runs, paired into posts.",
        true,
        {"transitions", "scan_lines", "kinematic_horizon", "green_horizon"},
        {},
        {&perceptKind<Goalpost>()},
        {{"goalposts.edge_lines", "Post edge lines (left cyan, right magenta)",
          debug_colour::kCyan},
         {"goalposts.rejected", "Rejected posts", debug_colour::kRejected}}};
    return info;
}

void GoalpostDetector::run(Blackboard& bb)
{
    std::vector<Goalpost>& goalposts = bb.percepts.output<Goalpost>();
    const auto& transitions = bb.horizontal_transitions[TransitionClass::Goal];
    if (transitions.empty())
        return;
    std::vector<PointF>& lefts = m_lefts;
    std::vector<PointF>& rights = m_rights;
    lefts.clear();
    rights.clear();
    const int w = bb.width();
    for (const ColourSegment& s : transitions) {
        // A run cut by the image border has no edge there.
        if (s.x0 > 0)
            lefts.push_back({s.x0 - 0.5, double(s.y0)});
        if (s.x1 < w)
            rights.push_back({s.x1 - 0.5, double(s.y0)});
    }
    const int hspacing = bb.horizontalScanSpacing();
    RansacRng rng{m_seed.value()};
    RansacParams params;
    params.max_error = m_max_error;
    params.min_points = m_min_points;
    params.iterations = m_iterations;
    const int max_lines = m_max_lines;
    std::vector<Edge> starts = fitEdges(lefts, params, max_lines, rng);
    std::vector<Edge> ends = fitEdges(rights, params, max_lines, rng);

    if (auto* d = bb.debug.layer("goalposts.edge_lines")) {
        for (const Edge& e : starts)
            d->add(lineShape(e.low, e.high, debug_colour::kCyan, 2));
        for (const Edge& e : ends)
            d->add(lineShape(e.low, e.high, debug_colour::kMagenta, 2));
    }

    // Pair each left edge with the nearest unused right edge that agrees in angle, length and
    // support, and lies to its right.
    const double tol = m_matching_tolerance;
    if (tol < 0 || tol > 1)
        throw std::invalid_argument("matching_tolerance must be in [0, 1]");
    DebugDrawing* rejected = bb.debug.layer("goalposts.rejected");
    const auto reject = [&](const Quad& q, const char* why) {
        if (rejected)
            addRejected(
                *rejected,
                DebugShape{ShapeKind::Polyline, {q.bl, q.tl, q.tr, q.br, q.bl}, {}, 1, false, 1},
                why);
    };
    std::vector<bool> used(ends.size(), false);
    std::vector<Quad> posts;
    std::vector<std::size_t> order;
    for (const Edge& s : starts) {
        order.clear();
        for (std::size_t i = 0; i < ends.size(); ++i)
            if (!used[i])
                order.push_back(i);
        std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
            return meanEndDistance(s, ends[a]) < meanEndDistance(s, ends[b]);
        });
        for (std::size_t i : order) {
            const Edge& e = ends[i];
            const double len_ratio =
                std::min(s.length(), e.length()) / std::max(1e-9, std::max(s.length(), e.length()));
            const double count_ratio =
                double(std::min(s.count, e.count)) / double(std::max(s.count, e.count));
            if (s.line.angleTo(e.line) > tol * std::numbers::pi / 2 ||
                len_ratio < m_min_support_ratio || count_ratio < m_min_support_ratio ||
                s.meanX() >= e.meanX())
                continue;
            used[i] = true;
            const Quad q{s.low, s.high, e.high, e.low};
            // Posts are tall: drop wide quads (crossbars, blobs) and narrow slivers.
            if (q.height() / q.width() < m_min_aspect || q.width() <= m_min_width) {
                reject(q, q.width() <= m_min_width ? "narrower than min_width"
                                                   : "too wide for its height (min_aspect)");
                break;
            }
            // A post stands roughly perpendicular to the horizon.
            const ImageLine axis{
                q.bottomCentre(),
                {q.topCentre().x - q.bottomCentre().x, q.topCentre().y - q.bottomCentre().y}};
            const double hx = double(w - 1),
                         hy = bb.kinematic_horizon.y_right - bb.kinematic_horizon.y_left;
            const double hl = std::hypot(hx, hy);
            const double al = std::hypot(axis.direction.x, axis.direction.y);
            const double cosang =
                std::abs(axis.direction.x * hx + axis.direction.y * hy) / std::max(1e-9, al * hl);
            if (std::acos(std::min(1.0, cosang)) >= 0.75 * std::numbers::pi / 2)
                posts.push_back(q);
            else
                reject(q, "not upright to the horizon");
            break;
        }
    }

    // A post cut by the image border has only its inner edge: most of the goal runs along that
    // edge (at least half: a tilted post leaves the border part-way) reach the border.
    const auto borderPost = [&](const Edge& e, bool left_border) {
        int touching = 0, near = 0;
        for (const ColourSegment& t : transitions) {
            const double edge_x = left_border ? t.x1 - 0.5 : t.x0 - 0.5;
            if (std::abs(e.line.xAtY(t.y0) - edge_x) > m_max_error || t.y0 < e.high.y - 1 ||
                t.y0 > e.low.y + 1)
                continue;
            ++near;
            touching += left_border ? t.x0 == 0 : t.x1 == w;
        }
        if (near == 0 || touching * 2 < near) // a tilted post leaves the border part-way
            return;
        const double bx = left_border ? -0.5 : w - 0.5;
        const Quad q = left_border ? Quad{{bx, e.low.y}, {bx, e.high.y}, e.high, e.low}
                                   : Quad{e.low, e.high, {bx, e.high.y}, {bx, e.low.y}};
        if (q.height() / q.width() >= m_min_aspect)
            posts.push_back(q);
    };
    for (std::size_t i = 0; i < ends.size(); ++i)
        if (!used[i])
            borderPost(ends[i], true);
    for (const Edge& s : starts)
        if (std::none_of(posts.begin(), posts.end(),
                         [&](const Quad& q) { return q.bl.x == s.low.x && q.tl.x == s.high.x; }))
            borderPost(s, false);

    // A sliver of a post at the image border is too thin for two edge lines: runs touching the
    // border on consecutive scan rows (and short, unlike a crossbar) make a post.
    const auto slivers = [&](bool left_border) {
        const double max_len = 16 * pixelScale();
        std::vector<const ColourSegment*> rows;
        for (const ColourSegment& t : transitions)
            if ((left_border ? t.x0 == 0 : t.x1 == w) && t.length() <= max_len)
                rows.push_back(&t);
        std::sort(rows.begin(), rows.end(),
                  [](const ColourSegment* a, const ColourSegment* b) { return a->y0 < b->y0; });
        for (std::size_t i = 0; i < rows.size();) {
            std::size_t j = i + 1;
            while (j < rows.size() && rows[j]->y0 - rows[j - 1]->y0 <= hspacing)
                ++j;
            if (j - i >= 2) {
                double inner = left_border ? 0 : w;
                for (std::size_t k = i; k < j; ++k)
                    inner = left_border ? std::max(inner, rows[k]->x1 - 0.5)
                                        : std::min(inner, rows[k]->x0 - 0.5);
                const double outer = left_border ? -0.5 : w - 0.5;
                const double top = rows[i]->y0, bottom = rows[j - 1]->y0;
                const Quad q =
                    left_border
                        ? Quad{{outer, bottom}, {outer, top}, {inner, top}, {inner, bottom}}
                        : Quad{{inner, bottom}, {inner, top}, {outer, top}, {outer, bottom}};
                const bool covered = std::any_of(posts.begin(), posts.end(), [&](const Quad& p) {
                    return p.left() <= q.right() && q.left() <= p.right();
                });
                if (!covered)
                    posts.push_back(q);
            }
            i = j;
        }
    };
    slivers(true);
    slivers(false);

    // Merge posts that overlap or stand within merge_widths of each other (outer envelope).
    for (std::size_t a = 0; a < posts.size(); ++a)
        for (std::size_t b = a + 1; b < posts.size();) {
            const Quad &p = posts[a], &q = posts[b];
            const bool overlap = p.left() <= q.right() && q.left() <= p.right();
            const double dx = std::abs(p.bottomCentre().x - q.bottomCentre().x);
            if (overlap || dx <= m_merge_widths * std::max(p.width(), q.width())) {
                Quad m;
                m.bl = {std::min(p.bl.x, q.bl.x), std::max(p.bl.y, q.bl.y)};
                m.tl = {std::min(p.tl.x, q.tl.x), std::min(p.tl.y, q.tl.y)};
                m.tr = {std::max(p.tr.x, q.tr.x), std::min(p.tr.y, q.tr.y)};
                m.br = {std::max(p.br.x, q.br.x), std::max(p.br.y, q.br.y)};
                posts[a] = m;
                posts.erase(posts.begin() + std::ptrdiff_t(b));
            } else {
                ++b;
            }
        }

    for (const Quad& q : posts) {
        Goalpost g;
        g.left = int(std::ceil(q.left())); // edges are at pixel borders (x - 0.5)
        g.right = int(std::floor(q.right()));
        g.top = int(std::lround(q.top()));
        g.base_x = q.bottomCentre().x;
        g.base_y = q.bottom();
        // The base is where vertical scans see the post end: refine it downwards.
        for (const ColourSegment& v : bb.vertical_transitions[TransitionClass::Goal]) {
            const PixelPoint last = v.last();
            if (last.x >= g.left && last.x <= g.right && last.y > g.base_y)
                g.base_y = last.y;
        }
        g.bottom = int(std::lround(g.base_y));
        // Above the kinematic horizon cannot be a post's foot; a post rises above the field's
        // edge but stands on the field.
        const auto reject_post = [&](const char* why) {
            if (rejected)
                addRejected(*rejected,
                            rectShape({double(g.left), double(g.top)},
                                      {double(g.right), double(g.bottom)}, {}),
                            why);
        };
        if (g.base_y < bb.kinematic_horizon.yAt(g.base_x, w)) {
            reject_post("foot above the kinematic horizon");
            continue;
        }
        if (m_max_foot_above_field >= 0 &&
            g.base_y < bb.green_horizon.yAt(int(std::lround(g.base_x))) - m_max_foot_above_field) {
            reject_post("foot above the field's edge (max_foot_above_field)");
            continue;
        }
        goalposts.push_back(g);
    }

    // Two posts far enough apart are the left and right post of one goal. The original dropped
    // both when they were closer; a distant goal's posts are, so we keep them as unknown.
    if (goalposts.size() == 2) {
        auto& a = goalposts[0];
        auto& b = goalposts[1];
        if (std::max(a.left, b.left) - std::min(a.right, b.right) >= m_min_separation) {
            const bool a_left = a.base_x < b.base_x;
            a.side = a_left ? GoalpostSide::Left : GoalpostSide::Right;
            b.side = a_left ? GoalpostSide::Right : GoalpostSide::Left;
        }
    }
}

} // namespace fieldsight
