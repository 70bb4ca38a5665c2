// The obstacle stage's field edge: how far below the green horizon the edge's own band of
// obstacle colour usually reaches along the image (edge_band), so a robot is what reaches further.
#include "stages/obstacles/obstacle_detector.h"

#include "stages/obstacles/obstacle_runs.h"

#include <algorithm>
#include <vector>

namespace fieldsight {

using obstacle_runs::bridged;
using obstacle_runs::inMask;

void ObstacleDetector::measureEdge(const SegmentedRegion& region, unsigned mask, bool band,
                                   int spacing, const std::vector<char>& post)
{
    const std::size_t n = region.size();
    // How far down each vertical scan's first run of obstacle colour reaches from the green
    // horizon (with edge_band, short field-coloured bits inside it included, as in a run).
    std::vector<int>& depth = m_edge_depth;
    depth.assign(n, 0);
    const int max_bridged = maxBridged();
    for (std::size_t i = 0; i < n; ++i) {
        const Scan& scan = region[i];
        std::size_t k = 0;
        while (k < scan.size() &&
               (!inMask(mask, scan[k].colour) || (band && bridged(scan, k, mask, max_bridged))))
            ++k;
        if (k > 0)
            depth[i] = scan[k - 1].y1 - scan[0].y0;
    }
    std::vector<int>& usual = m_usual_depth;
    std::vector<int>& nearby = m_sorted_depth;
    if (!band) {
        // The field edge's own blend band is about the same everywhere: the median over the image.
        nearby.assign(depth.begin(), depth.end());
        const auto mid = nearby.begin() + std::ptrdiff_t(n / 2);
        std::nth_element(nearby.begin(), mid, nearby.end());
        usual.assign(n, *mid);
        return;
    }
    // The band (the blend into the wall, the strip of wall or goal frame that the green horizon
    // left above the carpet) changes along the edge: the median over edge_window around each
    // column, leaving out goalposts (their colour starts no run) and not reaching past one (inside
    // a goal the edge is the goal's back). A robot narrower than half the window stands out.
    const std::size_t half = std::size_t(std::max(1, int(m_edge_window / (2 * spacing))));
    usual.assign(n, 0);
    // The window's depths kept sorted as it slides (from and to only grow, but past a post, where
    // it starts afresh): a few moves a column where a median of its own took a selection.
    nearby.clear();
    // The first column after the last post left of each column, and the last before the first
    // post right of it: how far a window may reach.
    std::vector<std::size_t>& left = m_left_stop;
    std::vector<std::size_t>& right = m_right_stop;
    left.resize(n);
    right.resize(n);
    for (std::size_t i = 0, stop = 0; i < n; ++i) {
        left[i] = stop;
        if (post[i])
            stop = i + 1;
    }
    for (std::size_t i = n, stop = n - 1; i-- > 0;) {
        right[i] = stop;
        if (post[i] && i > 0)
            stop = i - 1;
    }
    std::size_t held_from = 0, held_to = 0; // the window `nearby` holds: [held_from, held_to)
    for (std::size_t i = 0; i < n; ++i) {
        // 2 half + 1 columns: where a goalpost or the image's side stops one side, the other
        // side reaches further, so a robot beside a post still has field edge around it. (Up to
        // half to the left, then up to 2 half + 1 columns to the right, then further left.)
        std::size_t from = std::max(i >= half ? i - half : 0, left[i]);
        const std::size_t to = std::min(from + 2 * half, right[i]);
        if (to - from < 2 * half)
            from = std::max(to >= 2 * half ? to - 2 * half : 0, left[i]);
        if (from < held_from || to + 1 < held_to || from >= held_to) {
            nearby.clear();
            held_from = held_to = from;
        }
        for (; held_to <= to; ++held_to)
            if (!post[held_to])
                nearby.insert(std::upper_bound(nearby.begin(), nearby.end(), depth[held_to]),
                              depth[held_to]);
        for (; held_from < from; ++held_from)
            if (!post[held_from])
                nearby.erase(std::lower_bound(nearby.begin(), nearby.end(), depth[held_from]));
        if (nearby.empty())
            continue;
        usual[i] = nearby[nearby.size() / 2];
    }
}

} // namespace fieldsight
