// Field line detection. The original fitted lines in the ground plane (metres, through a camera
// model fed by the robot's joints); a pinhole camera maps straight field lines to straight image
// lines, so we fit in the image, where no kinematics are needed and errors are in px.
#include "stages/field_lines/field_line_detector.h"

#include "stages/common/ellipse_fit.h"
#include "stages/common/line_fit.h"
#include "stages/common/ransac.h"
#include "stages/common/stage_util.h"
#include "visioncore/framework/blackboard.h"
#include "visioncore/percepts/field_line.h"

#include <opencv2/core/mat.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <tuple>

namespace fieldsight {

namespace {

/// Models past max_lines that may still run while the circle's chords take none of its places:
/// a centre circle in view gives up to four.
constexpr int kChordModels = 4;

struct Fitted
{
    ImageLine line;
    std::vector<PointF> points;
};

/// Mean distance of each line's end points to the other line.
double averageDistance(const Fitted& a, const Fitted& b)
{
    PointF a1, a2, b1, b2;
    lineExtent(a.line, a.points, a1, a2);
    lineExtent(b.line, b.points, b1, b2);
    return (b.line.error(a1) + b.line.error(a2) + a.line.error(b1) + a.line.error(b2)) / 4;
}

/// Splits inliers where consecutive points along the line are further apart than max_gap, so one
/// model through two distant collinear pieces (or a chord through scattered points) does not
/// become one long line; keeps the pieces with enough points and returns how many, the points of
/// the others added to `short_pieces`. `sorted` is scratch.
std::size_t splitAtGaps(const Fitted& f, double max_gap, std::size_t min_points,
                        std::vector<Fitted>& out, std::vector<std::pair<double, PointF>>& sorted,
                        std::vector<PointF>& short_pieces)
{
    const std::size_t before = out.size();
    // Sorted by position along the line, computed once per point rather than per comparison.
    sorted.clear();
    for (const PointF& p : f.points)
        sorted.push_back({f.line.along(p), p});
    std::sort(sorted.begin(), sorted.end(),
              [](const auto& a, const auto& b) { return a.first < b.first; });
    std::size_t begin = 0;
    for (std::size_t i = 1; i <= sorted.size(); ++i) {
        if (i < sorted.size() && sorted[i].first - sorted[i - 1].first <= max_gap)
            continue;
        if (i - begin >= min_points) {
            Fitted piece;
            piece.points.reserve(i - begin);
            for (std::size_t k = begin; k < i; ++k)
                piece.points.push_back(sorted[k].second);
            piece.line = fitLineTls(piece.points);
            out.push_back(std::move(piece));
        } else {
            for (std::size_t k = begin; k < i; ++k)
                short_pieces.push_back(sorted[k].second);
        }
        begin = i;
    }
    return out.size() - before;
}

/// Whether field green borders scan[k] on both sides: the nearest segment each way, past pieces
/// of other colours no longer than `blend` px in all, is green. The image's border counts as
/// green (a line running out of the image); the start of a scan inside the image (a vertical scan
/// starts at the green horizon, perhaps inside a robot) does not.
bool greenBothSides(const Scan& scan, std::size_t k, int blend, int width, int height)
{
    const auto n = std::ptrdiff_t(scan.size());
    for (const std::ptrdiff_t step : {std::ptrdiff_t(-1), std::ptrdiff_t(1)}) {
        std::ptrdiff_t j = std::ptrdiff_t(k) + step;
        int skipped = 0;
        while (j >= 0 && j < n && scan[std::size_t(j)].colour != Colour::Green &&
               skipped + scan[std::size_t(j)].length() <= blend) {
            skipped += scan[std::size_t(j)].length();
            j += step;
        }
        if (j >= 0 && j < n) {
            if (scan[std::size_t(j)].colour != Colour::Green)
                return false;
            continue;
        }
        const ColourSegment& end = scan[std::size_t(j < 0 ? 0 : n - 1)];
        const bool at_border =
            j < 0 ? (end.x0 == 0 && end.x1 > end.x0) || (end.y0 == 0 && end.y1 > end.y0)
                  : end.x1 >= width || end.y1 >= height;
        if (!at_border)
            return false;
    }
    return true;
}

/// The scan of `region` that `s` was cut from and its index there, or nullptr. `scan_at` maps a
/// row (horizontal scans) or column (vertical) to its scan index; it is filled here once per
/// region.
const Scan* scanOf(const SegmentedRegion& region, const ColourSegment& s, std::vector<int>& scan_at,
                   std::size_t& index)
{
    const bool horizontal = region.direction == ScanDirection::Horizontal;
    const int key = horizontal ? s.y0 : s.x0;
    if (key < 0 || std::size_t(key) >= scan_at.size() || scan_at[std::size_t(key)] < 0)
        return nullptr;
    const Scan& scan = region[std::size_t(scan_at[std::size_t(key)])];
    const auto it = std::lower_bound(scan.begin(), scan.end(), s,
                                     [horizontal](const ColourSegment& a, const ColourSegment& b) {
                                         return horizontal ? a.x0 < b.x0 : a.y0 < b.y0;
                                     });
    if (it == scan.end() || it->x0 != s.x0 || it->y0 != s.y0)
        return nullptr;
    index = std::size_t(it - scan.begin());
    return &scan;
}

void indexScans(const SegmentedRegion& region, int extent, std::vector<int>& scan_at)
{
    scan_at.assign(std::size_t(std::max(0, extent)), -1);
    const bool horizontal = region.direction == ScanDirection::Horizontal;
    for (std::size_t i = 0; i < region.size(); ++i)
        if (!region[i].empty()) {
            const int key = horizontal ? region[i][0].y0 : region[i][0].x0;
            if (key >= 0 && key < extent)
                scan_at[std::size_t(key)] = int(i);
        }
}

/// Centres of the faint line runs of `raw` (the unfiltered scans): runs of unclassified and white
/// pixels, at most `max_width` px, between field green on both sides, whose brightest pixel is
/// `contrast` brighter (luma) than the green 2 px beyond either end. A run holding a white segment
/// of 2 px or more is left to the white transitions.
void addFaintPoints(const SegmentedRegion& raw, const cv::Mat& image, int max_width, int contrast,
                    std::vector<PointF>& points)
{
    const bool horizontal = raw.direction == ScanDirection::Horizontal;
    const auto luma = [&](int x, int y) { return int(image.ptr<std::uint8_t>(y)[3 * x]); };
    for (std::size_t i = 0; i < raw.size(); ++i) {
        const Scan& scan = raw[i];
        std::size_t k = 1;
        while (k + 1 < scan.size()) {
            if (scan[k - 1].colour != Colour::Green || scan[k].colour == Colour::Green) {
                ++k;
                continue;
            }
            // scan[k] starts a run after green: extend it over unclassified and white segments.
            std::size_t end = k;
            int length = 0;
            bool white = false;
            while (
                end < scan.size() &&
                (scan[end].colour == Colour::Unclassified || scan[end].colour == Colour::White) &&
                length <= max_width) {
                length += scan[end].length();
                white |= scan[end].colour == Colour::White && scan[end].length() >= 2;
                ++end;
            }
            if (end >= scan.size() || scan[end].colour != Colour::Green || length > max_width ||
                white) {
                k = end + 1;
                continue;
            }
            const ColourSegment& before = scan[k - 1];
            const ColourSegment& after = scan[end];
            const PixelPoint first = scan[k].first();
            const PixelPoint last = scan[end - 1].last();
            int brightest = 0;
            for (int j = 0; j < length; ++j)
                brightest = std::max(brightest, horizontal ? luma(first.x + j, first.y)
                                                           : luma(first.x, first.y + j));
            const PixelPoint g1 = horizontal
                                      ? PixelPoint{std::max<int>(before.x0, first.x - 2), first.y}
                                      : PixelPoint{first.x, std::max<int>(before.y0, first.y - 2)};
            const PixelPoint after_last = after.last();
            const PixelPoint g2 = horizontal
                                      ? PixelPoint{std::min<int>(after_last.x, last.x + 2), last.y}
                                      : PixelPoint{last.x, std::min<int>(after_last.y, last.y + 2)};
            if (brightest - luma(g1.x, g1.y) >= contrast &&
                brightest - luma(g2.x, g2.y) >= contrast)
                points.push_back({(first.x + last.x) * 0.5, (first.y + last.y) * 0.5});
            k = end + 1;
        }
    }
}

/// px: how far the mean of the middle third of `f`'s points (by position along the line) lies
/// across the line from the mean of the outer two thirds; 0 with fewer than 2 points in a third.
/// A straight line's points scatter about it evenly; an arc's middle bulges to one side.
double bow(const Fitted& f)
{
    double lo = std::numeric_limits<double>::infinity();
    double hi = -lo;
    for (const PointF& p : f.points) {
        lo = std::min(lo, f.line.along(p));
        hi = std::max(hi, f.line.along(p));
    }
    const double third = (hi - lo) / 3;
    if (!(third > 0))
        return 0;
    double sum[3] = {0, 0, 0};
    int count[3] = {0, 0, 0};
    for (const PointF& p : f.points) {
        const int part = std::clamp(int((f.line.along(p) - lo) / third), 0, 2);
        sum[part] += (p.x - f.line.point.x) * f.line.direction.y -
                     (p.y - f.line.point.y) * f.line.direction.x;
        ++count[part];
    }
    if (count[0] < 2 || count[1] < 2 || count[2] < 2)
        return 0;
    return std::abs(sum[1] / count[1] - 0.5 * (sum[0] / count[0] + sum[2] / count[2]));
}

/// Merges lines within `angle` of each other whose ends lie within `distance` of the other line,
/// while the line through all their points keeps them within `max_error` on average (0: any).
/// The original computed this and then discarded the result.
void mergeColinear(std::vector<Fitted>& lines, double angle, double distance, double max_error)
{
    std::vector<PointF> joint;
    bool merged = true;
    while (merged) {
        merged = false;
        for (std::size_t a = 0; a < lines.size() && !merged; ++a)
            for (std::size_t b = a + 1; b < lines.size() && !merged; ++b) {
                if (lines[a].line.angleTo(lines[b].line) > angle ||
                    averageDistance(lines[a], lines[b]) > distance)
                    continue;
                joint = lines[a].points;
                joint.insert(joint.end(), lines[b].points.begin(), lines[b].points.end());
                const ImageLine fit = fitLineTls(joint);
                if (max_error > 0) {
                    double sum = 0;
                    for (const PointF& p : joint)
                        sum += fit.error(p);
                    if (sum > max_error * double(joint.size()))
                        continue;
                }
                lines[a].points.swap(joint);
                lines[a].line = fit;
                lines.erase(lines.begin() + std::ptrdiff_t(b));
                merged = true;
            }
    }
}

/// The ellipses of the centre circle (the circle in perspective). The points of every bent line
/// but those on a straight one (the halfway line crosses the circle) give one ellipse, fitted
/// again, twice, to the points near it that no straight line took (`left`, and the bent lines'):
/// RANSAC cuts the one circle into several bent chords. When those points fit no ellipse, each
/// bent line's own points are tried alone. A straight line's points never move the fit, so a far
/// line that an ellipse happens to run along (the flat top of a large one) cannot pull it onto
/// itself; whether a straight line is one of the circle's chords is decided against the result.
std::vector<ImageEllipse> circleEllipses(const std::vector<Fitted>& lines,
                                         const std::vector<bool>& bent,
                                         const std::vector<PointF>& left, double near,
                                         double max_axis, double line_error)
{
    std::vector<PointF> close;
    const auto settle = [&](const std::vector<PointF>& seed, double seed_error) {
        std::optional<ImageEllipse> e = fitImageEllipse(seed, 2 * near, max_axis, seed_error);
        for (int refit = 0; e && refit < 2; ++refit) {
            close.clear();
            const auto gather = [&](const std::vector<PointF>& points) {
                for (const PointF& p : points)
                    if (e->distance(p) <= near)
                        close.push_back(p);
            };
            gather(left);
            for (std::size_t k = 0; k < lines.size(); ++k)
                if (bent[k])
                    gather(lines[k].points);
            const std::optional<ImageEllipse> again =
                fitImageEllipse(close, 2 * near, max_axis, 1.5);
            if (!again)
                break;
            e = again;
        }
        return e;
    };
    std::vector<PointF> seed;
    for (std::size_t i = 0; i < lines.size(); ++i)
        if (bent[i])
            for (const PointF& p : lines[i].points)
                if (std::none_of(lines.begin(), lines.end(), [&](const Fitted& f) {
                        return !bent[std::size_t(&f - lines.data())] &&
                               f.line.error(p) <= line_error;
                    }))
                    seed.push_back(p);
    std::vector<ImageEllipse> ellipses;
    if (const std::optional<ImageEllipse> e = settle(seed, 1.5)) {
        ellipses.push_back(*e);
        return ellipses;
    }
    for (std::size_t i = 0; i < lines.size(); ++i)
        if (bent[i])
            if (const std::optional<ImageEllipse> e = settle(lines[i].points, 1.0))
                ellipses.push_back(*e);
    return ellipses;
}

/// Whether an end of `f` (its extent `a`-`b`) lies within `reach` px of line `g`'s segment (its
/// extent, plus `reach` beyond each end) at an angle of at least 0.3 rad (17 degrees) to it.
bool meetsAtAnAngle(const Fitted& f, PointF a, PointF b, const Fitted& g, double reach)
{
    if (g.line.angleTo(f.line) < 0.3)
        return false;
    PointF c, d;
    lineExtent(g.line, g.points, c, d);
    const double lo = std::min(g.line.along(c), g.line.along(d)) - reach;
    const double hi = std::max(g.line.along(c), g.line.along(d)) + reach;
    for (const PointF& end : {a, b}) {
        const double t = g.line.along(end);
        if (g.line.error(end) <= reach && t >= lo && t <= hi)
            return true;
    }
    return false;
}

/// The second search's settings and scratch.
struct ShortSearch
{
    int min_points;
    double max_gap;
    double junction;
    double max_bow; ///< 0: none
    PointColumns& cols;
    std::vector<std::pair<double, PointF>>& sorted;
    std::vector<PointF>& pieces;
};

void addShortLines(std::vector<PointF>& points, RansacParams params, const ShortSearch& search,
                   RansacRng& rng, std::vector<Fitted>& lines)
{
    // Up to three lines of short_points or more, split where their points leave more than
    // short_gap (scan lines cross a line every few px, so a short line's points follow each other
    // closely; a model through scattered points does not), each kept only where an end meets one
    // of the long lines at a corner or a T: the field's short lines (the goal area's) join longer
    // ones, and the clutter that short_points would let in (a robot's foot, a mark, an arc) does
    // not. Half the bend a long line may have: an arc's bend grows with the square of its
    // length, so a short piece of the centre circle (where it meets the halfway line) bends
    // less than a long chord and would pass the long lines' test.
    params.min_points = search.min_points;
    const std::size_t long_count = lines.size();
    // The pieces too short even here are set aside until the search ends, so that the next try
    // does not find the same band again; they and the lines not kept go back to `points` (the
    // centre circle's fit reads them).
    std::vector<Fitted> found;
    std::vector<PointF> aside;
    RansacResult<ImageLine> r;
    for (int k = 0; k < 3 && ransacFindModel(points, params, rng, r, search.cols); ++k) {
        Fitted f{fitLineTls(r.inliers), std::move(r.inliers)};
        search.pieces.clear();
        splitAtGaps(f, search.max_gap, std::size_t(params.min_points), found, search.sorted,
                    search.pieces);
        aside.insert(aside.end(), search.pieces.begin(), search.pieces.end());
    }
    points.insert(points.end(), aside.begin(), aside.end());
    for (Fitted& f : found) {
        PointF a, b;
        lineExtent(f.line, f.points, a, b);
        const bool straight = search.max_bow <= 0 || bow(f) <= search.max_bow;
        if (straight && std::any_of(lines.begin(), lines.begin() + std::ptrdiff_t(long_count),
                                    [&](const Fitted& g) {
                                        return meetsAtAnAngle(f, a, b, g, search.junction);
                                    }))
            lines.push_back(std::move(f));
        else
            points.insert(points.end(), f.points.begin(), f.points.end());
    }
}

} // namespace

const StageInfo& FieldLineDetector::info() const
{
    static const StageInfo info{
        "field_lines",
        "Field lines",
        "RANSAC lines through the centres of white runs below the green horizon; colinear lines "
        "merged.",
        true,
        {"transitions", "filtered_segments", "green_horizon"},
        {},
        {&perceptKind<FieldLine>()},
        {{"field_lines.points", "Line points", debug_colour::kWhite},
         {"field_lines.rejected", "Rejected line points", debug_colour::kRejected}}};
    return info;
}

void FieldLineDetector::run(Blackboard& bb)
{
    std::vector<PointF> points;
    DebugDrawing* rejected = bb.debug.layer("field_lines.rejected");
    const auto reject = [&](PointF c, const char* why) {
        if (rejected)
            addRejected(*rejected, pointsShape(std::vector<PointF>{c}, {}, 3), why);
    };
    for (const auto& [t, region, extent] :
         {std::tuple{&bb.horizontal_transitions, &bb.horizontal_filtered, bb.height()},
          std::tuple{&bb.vertical_transitions, &bb.vertical_filtered, bb.width()}}) {
        if (m_green_sides)
            indexScans(*region, extent, m_scan_at);
        for (const ColourSegment& s : (*t)[TransitionClass::Line]) {
            const PointF c = s.centre();
            if (!bb.green_horizon.isBelow(int(c.x), int(c.y))) {
                reject(c, "above the field's edge");
                continue;
            }
            std::size_t k = 0;
            const Scan* scan = m_green_sides ? scanOf(*region, s, m_scan_at, k) : nullptr;
            if (scan && !greenBothSides(*scan, k, m_side_blend, bb.width(), bb.height())) {
                reject(c, "no field green on both sides");
                continue;
            }
            points.push_back(c);
        }
    }
    if (m_faint_width > 0) {
        const std::size_t white_points = points.size();
        for (const SegmentedRegion* raw : {&bb.horizontal_segments, &bb.vertical_segments})
            addFaintPoints(*raw, bb.image(), m_faint_width, m_faint_contrast, points);
        const auto below = [&](const PointF& c) {
            if (bb.green_horizon.isBelow(int(c.x), int(c.y)))
                return true;
            reject(c, "above the field's edge");
            return false;
        };
        points.erase(std::stable_partition(points.begin() + std::ptrdiff_t(white_points),
                                           points.end(), below),
                     points.end());
    }
    if (auto* d = bb.debug.layer("field_lines.points"))
        d->add(pointsShape(points, debug_colour::kWhite, 2));

    RansacRng rng{m_seed.value()};
    RansacParams params;
    params.max_error = m_max_error;
    params.min_points = m_min_points;
    params.iterations = m_iterations;
    params.locality = std::size_t(m_locality.value());
    std::vector<Fitted> lines;
    RansacResult<ImageLine> r;
    m_orphans.clear();
    // A model whose every piece is bent (a chord of the centre circle) takes no line's place:
    // the circle can give several, and a far line found after them was lost (rc2012, frames
    // 28-29). A few more models at most, so that a frame's cost stays bounded.
    const auto bends = [this](const Fitted& f) { return m_max_bow > 0 && bow(f) > m_max_bow; };
    const auto allBent = [&bends, &lines](std::size_t from) {
        return from < lines.size() &&
               std::all_of(lines.begin() + std::ptrdiff_t(from), lines.end(), bends);
    };
    for (int found = 0, models = 0; found < m_max_lines && models < m_max_lines + kChordModels &&
                                    ransacFindModel(points, params, rng, r, m_cols);
         ++models) {
        const std::size_t before = lines.size();
        Fitted f{fitLineTls(r.inliers), std::move(r.inliers)};
        m_short.clear();
        // A model that gave a line gives the points of its short pieces back: a far line's end
        // that another line's band took in is found again with the rest of its line.
        // A model that gave none gives them to the search for short lines: its band took a short
        // line's points along with scattered others.
        if (splitAtGaps(f, m_max_gap, std::size_t(params.min_points), lines, m_sorted, m_short) >
            0) {
            if (m_return_short)
                points.insert(points.end(), m_short.begin(), m_short.end());
        } else {
            m_orphans.insert(m_orphans.end(), m_short.begin(), m_short.end());
        }
        found += allBent(before) ? 0 : 1;
    }
    if (m_short_points > 0 && m_short_points < m_min_points) {
        points.insert(points.end(), m_orphans.begin(), m_orphans.end());
        addShortLines(
            points, params,
            {m_short_points, m_short_gap, m_junction, m_max_bow / 2, m_cols, m_sorted, m_short},
            rng, lines);
    }

    mergeColinear(lines, m_merge_angle, m_merge_distance, m_merge_error);

    std::vector<bool> bent(lines.size(), false);
    for (std::size_t i = 0; i < lines.size(); ++i)
        bent[i] = bends(lines[i]);
    const std::vector<ImageEllipse> circles =
        m_circle_distance > 0 ? circleEllipses(lines, bent, points, m_circle_distance,
                                               2.0 * std::max(bb.width(), bb.height()), m_max_error)
                              : std::vector<ImageEllipse>{};
    std::vector<FieldLine>& out = bb.percepts.output<FieldLine>();
    for (std::size_t i = 0; i < lines.size(); ++i) {
        const Fitted& f = lines[i];
        if (bent[i]) {
            if (rejected)
                addRejected(*rejected, pointsShape(f.points, {}, 3), "bent: a circle's chord");
            continue;
        }
        const bool chord = std::any_of(circles.begin(), circles.end(), [&](const ImageEllipse& e) {
            const auto on = std::count_if(f.points.begin(), f.points.end(), [&](const PointF& p) {
                return e.distance(p) <= m_circle_distance;
            });
            return 2 * std::size_t(on) >= f.points.size();
        });
        if (chord) {
            if (rejected)
                addRejected(*rejected, pointsShape(f.points, {}, 3),
                            "on the centre circle's ellipse: a chord");
            continue;
        }
        PointF a, b;
        lineExtent(f.line, f.points, a, b);
        out.push_back({a.x, a.y, b.x, b.y});
    }
}

} // namespace fieldsight
