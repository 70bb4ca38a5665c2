// Obstacle detection on the vertical segments.
#include "stages/obstacles/obstacle_detector.h"

#include "stages/common/stage_util.h"
#include "visioncore/blackboard.h"

#include <algorithm>
#include <cmath>

namespace fieldsight {

namespace {

/// Bit set of colours that belong to the field or to objects the other stages detect.
unsigned fieldColours(const Blackboard& bb)
{
    unsigned mask = 0;
    for (Colour c : {Colour::Green, Colour::White, Colour::Orange, Colour::Yellow,
                     Colour::YellowOrange, Colour::PinkOrange})
        mask |= 1u << unsigned(c);
    // The goal and ball colours are parameters of the transition filter (blue goals in 2009):
    // whatever colour their transitions have is not an obstacle.
    for (const Transitions* t : {&bb.horizontal_transitions, &bb.vertical_transitions})
        for (TransitionClass cls : {TransitionClass::Goal, TransitionClass::Ball})
            if (!(*t)[cls].empty())
                mask |= 1u << unsigned((*t)[cls].front().colour);
    return mask;
}

struct Run
{
    int x;
    int top;
    int bottom; ///< inclusive
};

struct Group
{
    int first_x, last_x, top, bottom, columns;
    int last_top, last_bottom;
};

} // namespace

ObstacleDetector::ObstacleDetector()
{
    addParam(m_min_run, {"min_run", "px", "shortest run of non-field colour on a scan line", 6, 1,
                         240});
    addParam(m_min_columns,
             {"min_columns", "", "scan lines an obstacle must span", 2, 1, 100});
    addParam(m_max_column_gap,
             {"max_column_gap", "", "scan lines an obstacle may skip (a white stripe)", 1, 0, 10});
    addParam(m_min_distance_from_horizon,
             {"min_distance_from_horizon", "px",
              "the run must reach this far below the green horizon", 0, 0, 100});
    addParam(m_min_height_ratio,
             {"min_height_ratio", "",
              "a run must be this tall (less min_run, for blur), as a fraction of its foot's "
              "distance below the green horizon",
              0.3, 0, 2});
    addParam(m_max_foot_jump,
             {"max_foot_jump", "px",
              "neighbouring scan lines whose feet differ more belong to different obstacles", 4, 0,
              240});
}

const StageInfo& ObstacleDetector::info() const
{
    static const StageInfo info{"obstacles",
                                "Obstacles",
                                true,
                                {"vertical_filtered", "horizontal_filtered", "green_horizon"},
                                {"obstacles", "obstacle_points"},
                                {{"obstacles.points", "Obstacle points"},
                                 {"obstacles.obstacles", "Obstacles"}}};
    return info;
}

void ObstacleDetector::run(Blackboard& bb)
{
    const int min_run = int(std::lround(m_min_run));
    const int h = bb.height();
    const auto& region = bb.vertical_filtered;
    if (region.size() == 0)
        return;
    const unsigned field_mask = fieldColours(bb);
    const auto isFieldColour = [field_mask](Colour c) { return (field_mask >> unsigned(c)) & 1u; };

    // One run per scan line at most: the lowest long run of non-field colour, i.e. the nearest
    // object (its bottom is where it stands).
    std::vector<Run> runs;
    int spacing = 1;
    if (bb.vertical_scan_starts.size() >= 2)
        spacing = std::max(1, bb.vertical_scan_starts[1].x - bb.vertical_scan_starts[0].x);
    for (std::size_t i = 0; i < region.size(); ++i) {
        const Scan& scan = region[i];
        bool have = false;
        Run best{};
        int top = -1;
        int bottom = -1;
        for (std::size_t k = 0; k <= scan.size(); ++k) {
            const bool field = k == scan.size() || isFieldColour(scan[k].colour);
            if (!field) {
                if (top < 0)
                    top = scan[k].y0;
                bottom = scan[k].y1 - 1;
                continue;
            }
            // A run ends at field colour; short field-coloured bits inside a robot (a white
            // marking) are part of it when the run continues right after.
            if (top >= 0 && k < scan.size() && scan[k].length() <= 3 && k + 1 < scan.size() &&
                !isFieldColour(scan[k + 1].colour))
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
            if (top >= 0 && bottom - top + 1 >= min_run && standing &&
                bottom - gh >= m_min_distance_from_horizon) {
                best = {scan[0].x0, top, bottom};
                have = true;
            }
            top = -1;
        }
        // A run reaching the image bottom has no visible foot: still an obstacle (very near).
        if (have) {
            runs.push_back(best);
            bb.obstacle_points.push_back({best.x, best.bottom});
        }
    }
    if (auto* d = bb.debug.layer("obstacles.points"))
        d->add(pointsShape(bb.obstacle_points, debug_colour::kCyan, 3));

    // Group runs on neighbouring scan lines that overlap vertically.
    const int max_step = spacing * (1 + int(std::lround(m_max_column_gap)));
    std::vector<Group> groups;
    for (const Run& r : runs) {
        if (!groups.empty()) {
            Group& g = groups.back();
            const bool adjacent = r.x - g.last_x <= max_step;
            const bool overlaps = r.top <= g.last_bottom && g.last_top <= r.bottom;
            // Robots side by side at different distances stand on different rows.
            const bool same_foot = std::abs(r.bottom - g.last_bottom) <= m_max_foot_jump ||
                                   r.bottom >= h - 1 || g.last_bottom >= h - 1;
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
        groups.push_back({r.x, r.x, r.top, r.bottom, 1, r.top, r.bottom});
    }

    // Widen each obstacle to the horizontal segment of non-field colour that its scan lines cross
    // near its foot (it ends somewhere between two scan lines).
    const auto& rows = bb.horizontal_scan_ys;
    for (const Group& g : groups) {
        if (g.columns < int(std::lround(m_min_columns)))
            continue;
        Obstacle o{std::max(0, g.first_x - spacing / 2), std::min(bb.width() - 1, g.last_x + spacing / 2),
                   g.top, std::min(g.bottom, h - 1)};
        for (std::size_t i = 0; i < rows.size() && i < bb.horizontal_filtered.size(); ++i) {
            const int y = rows[i];
            if (y > g.bottom || y < g.bottom - 3 * spacing - 2 || y < g.top)
                continue;
            for (const ColourSegment& s : bb.horizontal_filtered[i]) {
                if (isFieldColour(s.colour) || s.x1 <= g.first_x || s.x0 > g.last_x)
                    continue;
                o.left = std::min(o.left, std::max(int(s.x0), g.first_x - spacing));
                o.right = std::max(o.right, std::min(s.x1 - 1, g.last_x + spacing));
            }
        }
        bb.obstacles.push_back(o);
    }
    if (auto* d = bb.debug.layer("obstacles.obstacles"))
        for (const Obstacle& o : bb.obstacles)
            d->add(rectShape(o.left, o.top, o.right, o.bottom, debug_colour::kWhite, false, 2));
}

} // namespace fieldsight
