// Obstacle detection on the vertical segments.
#include "stages/obstacles/obstacle_detector.h"

#include "stages/obstacles/obstacle_runs.h"

#include "stages/common/stage_util.h"
#include "visioncore/framework/blackboard.h"
#include "visioncore/percepts/ball.h"
#include "visioncore/percepts/goalpost.h"
#include "visioncore/percepts/obstacle.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>

namespace fieldsight {

using obstacle_runs::bridged;
using obstacle_runs::inMask;
using obstacle_runs::kMaxBridged;

namespace {

/// The colour of a class of transitions, if any were seen (the goal's and the ball's are
/// parameters of the transition filter: blue goals in 2009).
std::optional<Colour> transitionColour(const Blackboard& bb, TransitionClass cls)
{
    for (const Transitions* t : {&bb.horizontal_transitions, &bb.vertical_transitions})
        if (!(*t)[cls].empty())
            return (*t)[cls].front().colour;
    return std::nullopt;
}

/// Bit set of colours that belong to the field or to objects the other stages detect.
unsigned fieldColours(const Blackboard& bb)
{
    unsigned mask = 0;
    for (Colour c : {Colour::Green, Colour::White, Colour::Orange, Colour::Yellow,
                     Colour::YellowOrange, Colour::PinkOrange})
        mask |= 1u << unsigned(c);
    // Whatever colour the goal's and the ball's transitions have is not an obstacle.
    for (TransitionClass cls : {TransitionClass::Goal, TransitionClass::Ball})
        if (const std::optional<Colour> c = transitionColour(bb, cls))
            mask |= 1u << unsigned(*c);
    return mask;
}

/// The colour covering most of the image's rows y0..y1 (clipped) over columns x0..x1, and its
/// share of them together with `also` (another background colour; 0 when the rectangle is
/// empty).
std::pair<Colour, double> plainestColour(const Blackboard& bb, int x0, int x1, int y0, int y1,
                                         std::optional<Colour> also)
{
    y0 = std::max(0, y0);
    x0 = std::max(0, x0);
    x1 = std::min(bb.width() - 1, x1);
    std::array<int, kColourCount> count{};
    int n = 0;
    for (int y = y0; y <= y1; ++y)
        for (int x = x0; x <= x1; ++x, ++n)
            ++count[std::size_t(bb.classify(x, y))];
    const auto most = std::max_element(count.begin(), count.end());
    const Colour plainest = Colour(most - count.begin());
    const int extra = also && *also != plainest ? count[std::size_t(*also)] : 0;
    return {plainest, n > 0 ? double(*most + extra) / n : 0.0};
}

} // namespace

const StageInfo& ObstacleDetector::info() const
{
    static const StageInfo info{
        "obstacles",
        "Obstacles",
        "Robots and people standing on the field: runs of non-field colour on the vertical scan "
        "lines, grouped across neighbouring lines.",
        true,
        {"filtered_segments", "transitions", "scan_lines", "green_horizon", "goalposts", "balls"},
        {"obstacle_points"},
        {&perceptKind<Obstacle>()},
        {{"obstacles.points", "Obstacle feet", debug_colour::kPink},
         {"obstacles.rejected", "Rejected obstacles", debug_colour::kRejected}}};
    return info;
}

int ObstacleDetector::maxBridged() const
{
    return int(std::lround(kMaxBridged * pixelScale()));
}

void ObstacleDetector::run(Blackboard& bb)
{
    std::vector<Obstacle>& obstacles = bb.percepts.output<Obstacle>();
    const std::vector<Goalpost>& goalposts = bb.percepts.list<Goalpost>();
    const int min_run = m_min_run;
    const int h = bb.height();
    const auto& region = bb.vertical_filtered;
    if (region.size() == 0)
        return;
    const unsigned field_mask = fieldColours(bb);

    // One run per scan line at most: the lowest long run of non-field colour, i.e. the nearest
    // object (its bottom is where it stands).
    std::vector<Run>& runs = m_runs;
    runs.clear();
    std::vector<Run>& behind_runs = m_behind_runs;
    behind_runs.clear();
    DebugDrawing* rejected = bb.debug.layer("obstacles.rejected");
    const int spacing = std::max(1, bb.verticalScanSpacing(1));
    // White robots (white_robots): white is field colour to the runs below, so a white robot
    // leaves none; a column without another run then takes one counting white as obstacle colour.
    const bool white_robots = m_white_robots;
    const unsigned white_mask = field_mask & ~(1u << unsigned(Colour::White));
    const bool band = m_edge_band;
    const auto atPost = [&](const Scan& scan) {
        return !scan.empty() &&
               std::any_of(goalposts.begin(), goalposts.end(), [&](const Goalpost& g) {
                   return scan[0].x0 >= g.left - spacing && scan[0].x0 <= g.right + spacing;
               });
    };
    // Where goalposts stand: for every column when the edge's band is measured along its
    // stretches, else only where a column has no run of its own (below).
    std::vector<char>& at_post = m_at_post;
    if (band) {
        at_post.resize(region.size());
        for (std::size_t i = 0; i < region.size(); ++i)
            at_post[i] = atPost(region[i]);
    }
    measureEdge(region, white_robots ? white_mask : field_mask, band, spacing, at_post);
    const std::vector<int>& edge_depth = m_edge_depth;
    const std::vector<int>& usual_depth = m_usual_depth;
    const int min_edge_dip = m_min_edge_dip;

    // The lowest run of obstacle colour on a scan that is long enough and stands (see below),
    // and in `behind` (x -1: none) the standing run just above it when at least behind_green px
    // of carpet lie between them: a robot further away, showing above a nearer one.
    const int behind_green = m_behind_green;
    const int max_bridged = maxBridged();
    const auto lowestRun = [&](const Scan& scan, unsigned mask, bool report, Run& best,
                               Run& behind) {
        bool have = false;
        int top = -1;
        int bottom = -1;
        int green = 0; // px of carpet since the last standing run
        behind.x = -1;
        for (std::size_t k = 0; k <= scan.size(); ++k) {
            if (k < scan.size() && !inMask(mask, scan[k].colour)) {
                if (top < 0)
                    top = scan[k].y0;
                bottom = scan[k].y1 - 1;
                continue;
            }
            // A run ends at field colour; short field-coloured bits inside a robot (a white
            // marking) are part of it when the run continues right after.
            if (top >= 0 && k < scan.size() && bridged(scan, k, mask, max_bridged))
                continue;
            // Something standing on the field as tall as the camera reaches the horizon, so its run
            // is tall for how far below the green horizon its foot is (a robot breaking the
            // horizon runs all the way up to it). Things lying on the field (a blurred distant
            // line) are flat.
            const int x = scan.empty() ? 0 : scan[0].x0;
            const int gh = bb.green_horizon.yAt(x);
            // Depth of the foot below the green horizon: the field edge lies below the true
            // horizon, so this works whether or not the stream knows its kinematic horizon.
            const double foot_depth = bottom - gh;
            // (min_run of the height is allowed for blur, which flattens nothing real.)
            const bool standing = bottom - top + 1 - min_run >= m_min_height_ratio * foot_depth;
            if (top >= 0 && bottom - top + 1 >= min_run) {
                if (standing && bottom - gh >= m_min_distance_from_horizon) {
                    if (have && behind_green > 0 && green >= behind_green)
                        behind = best;
                    best = {x, top, bottom};
                    have = true;
                    green = 0;
                } else if (report && rejected) {
                    addRejected(
                        *rejected,
                        lineShape({double(x), double(top)}, {double(x), double(bottom)}, {}),
                        standing ? "foot closer to the green horizon than "
                                   "min_distance_from_horizon"
                                 : "run too short for how far below the green horizon "
                                   "its foot is (lying flat, min_height_ratio)");
                }
            }
            top = -1;
            if (k < scan.size() && scan[k].colour == Colour::Green)
                green += scan[k].y1 - scan[k].y0;
        }
        return have;
    };

    for (std::size_t i = 0; i < region.size(); ++i) {
        const Scan& scan = region[i];
        Run best{};
        Run behind_best{};
        // (With white robots the second look sees every run the first does: it alone reports.)
        bool have = lowestRun(scan, field_mask, !white_robots, best, behind_best);
        if (!have && white_robots)
            have = lowestRun(scan, white_mask, true, best, behind_best);
        const int dip = edge_depth[i] - usual_depth[i];
        // A run from the green horizon that ends about where the field usually starts along this
        // stretch is the edge's own band, not something standing on the field.
        if (have && band && min_edge_dip > 0 && best.top - scan[0].y0 <= max_bridged &&
            dip < min_edge_dip) {
            have = false;
            if (rejected)
                addRejected(*rejected,
                            lineShape({double(best.x), double(best.top)},
                                      {double(best.x), double(best.bottom)}, {}),
                            "from the green horizon to " + std::to_string(std::max(0, dip)) +
                                " px below where the field usually starts (min_edge_dip)");
        }
        // A goalpost covers the field edge too.
        if (!have && !scan.empty() && min_edge_dip > 0 && edge_depth[i] > 0 &&
            dip >= min_edge_dip && !(band ? at_post[i] : atPost(scan))) {
            best = {scan[0].x0, scan[0].y0, scan[0].y0 + edge_depth[i] - 1};
            have = true;
        }
        if (have) {
            runs.push_back(best);
            bb.obstacle_points.push_back({best.x, best.bottom});
            if (behind_best.x >= 0)
                behind_runs.push_back(behind_best);
        }
    }
    if (auto* d = bb.debug.layer("obstacles.points"))
        d->add(pointsShape(bb.obstacle_points, debug_colour::kPink, 3));

    // Group runs on neighbouring scan lines that overlap vertically.
    const int max_step = spacing * (1 + m_max_column_gap);
    std::vector<Group>& groups = m_groups;
    // With the camera's horizon, how far a foot is below it goes with one over the distance: a foot
    // much higher than its neighbour's (behind_ratio of its depth) is a robot further away showing
    // beside the nearer one; a part of the nearer robot ends lower (a hand about 0.6 of the way
    // down to its foot).
    const Horizon& camera = bb.kinematic_horizon;
    const auto behind = [&](int foot, int other_foot, double x) {
        if (m_behind_ratio <= 0 || !camera.known() ||
            std::abs(foot - other_foot) <= m_max_foot_jump)
            return false;
        const double hz = camera.yAt(x, bb.width());
        const double near = std::max(foot, other_foot) - hz, far = std::min(foot, other_foot) - hz;
        return far > 0 && far < m_behind_ratio * near;
    };
    // Runs on neighbouring scan lines into groups, in `out`.
    const auto groupRuns = [&](const std::vector<Run>& rs, std::vector<Group>& out) {
        out.clear();
        for (const Run& r : rs) {
            if (!out.empty()) {
                Group& g = out.back();
                const bool adjacent = r.x - g.last_x <= max_step;
                const bool overlaps = r.top <= g.last_bottom && g.last_top <= r.bottom;
                // Robots side by side at different distances stand on different rows; beside one
                // cut by the image's bottom, only one much further away is told apart.
                const bool same_foot = std::abs(r.bottom - g.last_bottom) <= m_max_foot_jump ||
                                       ((r.bottom >= h - 1 || g.last_bottom >= h - 1) &&
                                        !behind(r.bottom, g.last_bottom, r.x));
                if (adjacent && overlaps && same_foot) {
                    g.last_x = r.x;
                    g.top = std::min(g.top, r.top);
                    g.bottom = std::max(g.bottom, r.bottom);
                    g.last_top = r.top;
                    g.last_bottom = r.bottom;
                    ++g.columns;
                    continue;
                }
            }
            out.push_back({r.x, r.x, r.top, r.bottom, 1, r.top, r.bottom});
        }
    };
    groupRuns(runs, groups);
    // Robots showing above nearer ones (behind_green) make pieces of their own, which are merged
    // among themselves only: between a near robot's pieces they would keep them apart.
    std::vector<Group>& behind_groups = m_behind_groups;
    groupRuns(behind_runs, behind_groups);
    for (Group& g : behind_groups)
        g.far = true;
    // Which pieces stand far behind the deepest foot among the pieces next to each other around
    // them (the nearer robot, whichever side of it they are on and whatever lies between).
    for (std::size_t i = 0; i < groups.size();) {
        std::size_t end = i + 1;
        int deepest = groups[i].bottom;
        while (end < groups.size() && groups[end].first_x - groups[end - 1].last_x <= max_step)
            deepest = std::max(deepest, groups[end++].bottom);
        for (; i < end; ++i)
            groups[i].far =
                behind(groups[i].bottom, deepest, 0.5 * (groups[i].first_x + groups[i].last_x));
    }

    // Pieces of one robot (arms ending above the legs, the gap between the legs) are split by the
    // foot rule; neighbouring pieces merge while the union is still shaped like something
    // standing (narrower than max_width_ratio of its height) and some horizontal scan line crosses
    // from one to the other without seeing field (the torso). Two robots side by side are not.
    const auto& rows = bb.horizontal_scan_ys;
    const unsigned join_mask = white_robots ? white_mask : field_mask;
    const auto joined = [&](int x0, int x1, int top, int bottom) {
        for (std::size_t i = 0; i < rows.size() && i < bb.horizontal_filtered.size(); ++i) {
            if (rows[i] < top || rows[i] > bottom)
                continue;
            bool open = false;
            for (const ColourSegment& s : bb.horizontal_filtered[i])
                open = open || (s.x1 > x0 && s.x0 <= x1 && inMask(join_mask, s.colour));
            if (!open)
                return true;
        }
        return false;
    };
    // The highest the green horizon reaches over columns x0..x1 (at their ends and middle).
    const auto topOfField = [&](int x0, int x1) {
        const auto& gh = bb.green_horizon;
        return std::min({gh.yAt(x0), gh.yAt((x0 + x1) / 2), gh.yAt(x1)});
    };
    const auto mergePieces = [&](std::vector<Group>& pieces) {
        for (std::size_t i = 0; i + 1 < pieces.size();) {
            Group& a = pieces[i];
            const Group& b = pieces[i + 1];
            const int top = std::min(a.top, b.top), bottom = std::max(a.bottom, b.bottom);
            const int width = b.last_x - a.first_x + spacing;
            // With the camera's horizon, one robot's width in the image goes with how far its foot
            // is below it: pieces on about the same row that fit in one robot's width (robot_width)
            // are one robot, whether or not a scan line crosses between them; with
            // edge_robot_width, only pieces that both reach up to the green horizon: the robot goes
            // on above the edge, where nothing is scanned (a far robot's two legs).
            const bool neighbours = b.first_x - a.last_x <= max_step;
            bool one_robot = false;
            if (camera.known()) {
                const double depth = bottom - camera.yAt(0.5 * (a.first_x + b.last_x), bb.width());
                const auto atEdge = [&](const Group& g) {
                    return g.top <= topOfField(g.first_x, g.last_x) + max_bridged;
                };
                one_robot =
                    depth > 0 && std::abs(a.bottom - b.bottom) <= 0.25 * depth &&
                    (width <= m_robot_width * depth ||
                     (neighbours && width <= m_edge_robot_width * depth && atEdge(a) && atEdge(b)));
            }
            // A piece on two or more scan lines standing far behind is its own robot.
            const bool apart = a.far != b.far && (a.far ? a : b).columns >= 2;
            // Something cut by the image's bottom row is close and taller than it shows, and a
            // piece beside it that does not reach up to the green horizon (field above it) is no
            // robot standing there but a part of the close one (an arm, a hand): their union's seen
            // height bounds its width less (cut_width_ratio).
            const auto hangs = [&](const Group& g) {
                return g.bottom < h - 1 && g.top > topOfField(g.first_x, g.last_x) + max_bridged;
            };
            const bool close_part =
                (a.bottom >= h - 1 && hangs(b)) || (b.bottom >= h - 1 && hangs(a));
            const double width_ratio = close_part
                                           ? std::max<double>(m_max_width_ratio, m_cut_width_ratio)
                                           : m_max_width_ratio;
            if (!apart && (one_robot || (neighbours && width <= width_ratio * (bottom - top + 1) &&
                                         joined(a.last_x, b.first_x, std::max(a.top, b.top),
                                                std::min(a.bottom, b.bottom))))) {
                a.last_x = b.last_x;
                a.top = top;
                a.bottom = bottom;
                a.columns += b.columns;
                a.far = a.far && b.far;
                pieces.erase(pieces.begin() + std::ptrdiff_t(i) + 1);
            } else {
                ++i;
            }
        }
    };
    mergePieces(groups);
    mergePieces(behind_groups);
    groups.insert(groups.end(), behind_groups.begin(), behind_groups.end());

    // Widen each obstacle to the horizontal segment of non-field colour that its scan lines cross
    // near its foot (it ends somewhere between two scan lines).
    const std::vector<Ball>& balls = bb.percepts.list<Ball>();
    // A box thrown away, on the rejected layer if it is drawn; the note is put in words only then.
    const auto rejectBox = [&](int left, int top, int right, int bottom, const auto& why) {
        if (rejected)
            addRejected(*rejected,
                        rectShape({double(left), double(top)}, {double(right), double(bottom)}, {}),
                        why());
    };
    const std::optional<Colour> goal = transitionColour(bb, TransitionClass::Goal);
    for (const Group& g : groups) {
        if (g.columns < m_min_columns) {
            rejectBox(g.first_x, g.top, g.last_x, g.bottom, [&] {
                return "on " + std::to_string(g.columns) + " scan line(s), under min_columns";
            });
            continue;
        }
        Obstacle o{std::max(0, g.first_x - spacing / 2),
                   std::min(bb.width() - 1, g.last_x + spacing / 2), g.top,
                   std::min(g.bottom, h - 1)};
        for (std::size_t i = 0; i < rows.size() && i < bb.horizontal_filtered.size(); ++i) {
            const int y = rows[i];
            if (y > g.bottom || y < g.bottom - 3 * spacing - 2 || y < g.top)
                continue;
            for (const ColourSegment& s : bb.horizontal_filtered[i]) {
                if (inMask(field_mask, s.colour) || s.x1 <= g.first_x || s.x0 > g.last_x)
                    continue;
                o.left = std::min(o.left, std::max(int(s.x0), g.first_x - spacing));
                o.right = std::max(o.right, std::min(s.x1 - 1, g.last_x + spacing));
            }
        }
        // The horizon above the box: the camera's where the stream gives it, else the green one.
        const double cx = 0.5 * (o.left + o.right);
        const double horizon =
            camera.known() ? camera.yAt(cx, bb.width()) : double(bb.green_horizon.yAt(int(cx)));
        // Something standing is about as wide as half its height, and its height in the image
        // is how far its foot is below the horizon (a robot is about as tall as the camera is
        // high): pieces much narrower are a robot's part or the wall's, not a robot.
        const double wanted = m_min_width_ratio * (o.bottom - horizon);
        if (m_min_width_ratio > 0 && o.right - o.left + 1 < wanted) {
            rejectBox(o.left, o.top, o.right, o.bottom, [&] {
                return std::to_string(o.right - o.left + 1) + " px wide, under the " +
                       oneDecimal(wanted) +
                       " px its foot's depth below the horizon wants (min_width_ratio)";
            });
            continue;
        }
        // Cut by the image's bottom row, the foot is out of view: something close to the camera.
        // A robot that close is taller than the camera is high, so it reaches up to about the
        // horizon; the observing robot's own shoulder or foot, low in the view, does not.
        const double reach = horizon + m_cut_reach * (h - 1 - horizon);
        if (m_cut_reach > 0 && camera.known() && g.bottom >= h - 1 && o.top > reach) {
            rejectBox(o.left, o.top, o.right, o.bottom, [&] {
                return "cut by the image's bottom but reaching only to row " +
                       std::to_string(o.top) + ", not up to row " + oneDecimal(reach) +
                       " (the robot's own body? cut_reach)";
            });
            continue;
        }
        // A post's sides blur into what stands behind it: a box beside a post and no wider than
        // it is that fringe, not a robot (a robot is several posts wide at the same distance).
        // The fringe ends about where the post stands: a box whose foot is half the post's
        // height above or below its base stands elsewhere (a far robot beside a close post).
        const auto fringe = [&](const Goalpost& p) {
            const int width = p.right - p.left + 1;
            const int foot_reach = std::max<int>(m_max_foot_jump, (p.bottom - p.top + 1) / 2);
            return o.right - o.left + 1 <= width && o.left <= p.right + spacing + width &&
                   o.right >= p.left - spacing - width &&
                   std::abs(o.bottom - p.bottom) <= foot_reach;
        };
        if (m_post_fringe && std::any_of(goalposts.begin(), goalposts.end(), fringe)) {
            rejectBox(o.left, o.top, o.right, o.bottom, [] {
                return std::string(
                    "beside a goalpost and no wider: its blurred side (post_fringe)");
            });
            continue;
        }
        // A ball's shading and highlights leave runs of other colours inside it.
        const double area = double(o.right - o.left + 1) * double(o.bottom - o.top + 1);
        const auto inside = [&](const Ball& b) {
            const double across =
                std::min(o.right + 0.5, b.x + b.radius) - std::max(o.left - 0.5, b.x - b.radius);
            const double down =
                std::min(o.bottom + 0.5, b.y + b.radius) - std::max(o.top - 0.5, b.y - b.radius);
            return across > 0 && down > 0 && across * down > m_max_ball_overlap * area;
        };
        if (m_max_ball_overlap < 1 && std::any_of(balls.begin(), balls.end(), inside)) {
            rejectBox(o.left, o.top, o.right, o.bottom,
                      [] { return std::string("inside the ball (max_ball_overlap)"); });
            continue;
        }
        // A box up to the green horizon may be the edge's band: something standing rises above
        // the edge and shows itself there (a white robot in front of a white wall its joints and
        // markers); one colour over nearly all of as much again above the box (with the goal's
        // colour, its frame standing right behind a strip inside the goal) is the wall or the
        // goal's net behind the band.
        if (m_plain_above > 0 && o.top <= topOfField(o.left, o.right) + max_bridged) {
            const auto [colour, share] = plainestColour(
                bb, o.left, o.right, o.top - (o.bottom - o.top + 1), o.top - 1, goal);
            if (share > m_plain_above) {
                rejectBox(o.left, o.top, o.right, o.bottom, [&, c = colour, sh = share] {
                    return std::to_string(int(std::lround(100 * sh))) + "% " +
                           std::string(colourName(c)) +
                           (goal && *goal != c ? " and " + std::string(colourName(*goal)) : "") +
                           " above it, nothing standing (plain_above)";
                });
                continue;
            }
        }
        obstacles.push_back(o);
    }
}

} // namespace fieldsight
