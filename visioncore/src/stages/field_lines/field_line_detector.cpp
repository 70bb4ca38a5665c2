// Field line detection. The original fitted lines in the ground plane (metres, through a camera
// model fed by the robot's joints); a pinhole camera maps straight field lines to straight image
// lines, so we fit in the image, where no kinematics are needed and errors are in px.
#include "stages/field_lines/field_line_detector.h"

#include "stages/common/line_fit.h"
#include "stages/common/ransac.h"
#include "stages/common/stage_util.h"
#include "visioncore/framework/blackboard.h"
#include "visioncore/percepts/field_line.h"

#include <algorithm>
#include <cmath>

namespace fieldsight {

namespace {

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
/// become one long line; keeps the pieces with enough points.
/// `sorted` is scratch.
void splitAtGaps(const Fitted& f, double max_gap, std::size_t min_points, std::vector<Fitted>& out,
                 std::vector<std::pair<double, PointF>>& sorted)
{
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
        }
        begin = i;
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
        {"transitions", "green_horizon"},
        {},
        {&perceptKind<FieldLine>()},
        {{"field_lines.points", "Line points", debug_colour::kWhite}}};
    return info;
}

void FieldLineDetector::run(Blackboard& bb)
{
    std::vector<PointF> points;
    for (const Transitions* t : {&bb.horizontal_transitions, &bb.vertical_transitions})
        for (const ColourSegment& s : (*t)[TransitionClass::Line]) {
            const PointF c = s.centre();
            if (bb.green_horizon.isBelow(int(c.x), int(c.y)))
                points.push_back(c);
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
    for (auto& r : ransacFindModels<ImageLine>(std::move(points), params, m_max_lines, rng)) {
        Fitted f{fitLineTls(r.inliers), std::move(r.inliers)};
        splitAtGaps(f, m_max_gap, std::size_t(params.min_points), lines, m_sorted);
    }

    // Merge colinear lines (the original computed this and then discarded the result).
    bool merged = true;
    while (merged) {
        merged = false;
        for (std::size_t a = 0; a < lines.size() && !merged; ++a)
            for (std::size_t b = a + 1; b < lines.size() && !merged; ++b) {
                if (lines[a].line.angleTo(lines[b].line) > m_merge_angle ||
                    averageDistance(lines[a], lines[b]) > m_merge_distance)
                    continue;
                lines[a].points.insert(lines[a].points.end(), lines[b].points.begin(),
                                       lines[b].points.end());
                lines[a].line = fitLineTls(lines[a].points);
                lines.erase(lines.begin() + std::ptrdiff_t(b));
                merged = true;
            }
    }

    std::vector<FieldLine>& out = bb.percepts.output<FieldLine>();
    for (const Fitted& f : lines) {
        PointF a, b;
        lineExtent(f.line, f.points, a, b);
        out.push_back({a.x, a.y, b.x, b.y});
    }
}

} // namespace fieldsight
