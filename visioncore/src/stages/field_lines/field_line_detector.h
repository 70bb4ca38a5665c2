// Field lines (design note §2.6): RANSAC lines through the centres of white transitions below the
// green horizon, then colinear lines merged.
#pragma once

#include "stages/common/ransac.h"
#include "stages/common/stage_util.h"
#include "visioncore/framework/stage.h"
#include "visioncore/basics/geometry.h"

#include <cstdint>
#include <utility>
#include <vector>

namespace fieldsight {

class FieldLineDetector : public Stage
{
public:
    const StageInfo& info() const override;
    void run(Blackboard& bb) override;

private:
    std::vector<std::pair<double, PointF>> m_sorted; ///< scratch of the gap split, kept
    std::vector<int> m_scan_at;    ///< scratch: the scan index of each row or column, or -1
    std::vector<PointF> m_short;   ///< scratch: the points of pieces too short to be lines
    std::vector<PointF> m_orphans; ///< scratch: the points of models that gave no line
    PointColumns m_cols;           ///< scratch of RANSAC

    Param<int> m_min_points{
        this, 12, {"min_points", "", 2, 1000, 1, "Line points needed for a field line."}};
    // With locality sampling 15 samples find what 40 independent ones did (B-Human log: 559 lines
    // in 160 frames against 558; 10 samples lost 7%), in half the time.
    Param<int> m_iterations{
        this, 15, {"iterations", "", 1, 10000, 1, "RANSAC samples per line, at most.", true, +1}};
    Param<double> m_max_error{
        this,
        2.5,
        {"max_error", "px", 0.5, 50, 0.5, "How far a line point may lie from its line."}};
    Param<int> m_max_lines{
        this, 6, {"max_lines", "", 1, 50, 1, "Most lines found per frame.", true, +1}};
    Param<double> m_merge_angle{
        this,
        0.1,
        {"merge_angle", "rad", 0, 1.6, 0.01,
         "Lines within this angle of each other (and close) are merged into one."}};
    Param<double> m_merge_distance{
        this,
        6,
        {"merge_distance", "px", 0, 100, 0.5,
         "Lines this close to each other (and parallel) are merged into one."}};
    Param<double> m_merge_error{
        this,
        1,
        {"merge_error", "px", 0, 50, 0.1,
         "Two such lines are merged only when the line through all their points stays this close "
         "to them on average: far lines a few px apart (a goal line and the goal area's) stay "
         "two. 0: any two."}};
    Param<double> m_max_gap{
        this,
        40,
        {"max_gap", "px", 1, 1000, 1, "A line is split where its points leave a longer gap."}};
    Param<int> m_locality{this,
                          8,
                          {"locality", "", 0, 1000, 1,
                           "The second RANSAC point is drawn within this many points (in scan "
                           "order) of the first; 0 draws it anywhere."}};
    Param<bool> m_green_sides{
        this,
        false,
        {"green_sides", "", 0, 1, 1,
         "A line point needs field green on both sides along its scan line (a line on the "
         "carpet, not a white robot, wall or goal)."}};
    Param<int> m_side_blend{
        this,
        4,
        {"side_blend", "px", 0, 50, 1,
         "Other colours this long between a line and the green beside it are the blur between "
         "them."}};
    Param<bool> m_return_short{
        this,
        true,
        {"return_short", "", 0, 1, 1,
         "The points of a RANSAC line's pieces too short to be lines (split at gaps) go back to "
         "be found again, when the line gave at least one piece."}};
    Param<int> m_faint_width{
        this,
        6,
        {"faint_width", "px", 0, 50, 1,
         "A run of unclassified (and white) pixels no longer than this between field green, "
         "brighter than the green beside it, is a line point too: a far, thin or blurred line "
         "the colour table does not call white, which the transition filter paints green. 0: "
         "white runs only."}};
    Param<int> m_faint_contrast{
        this,
        10,
        {"faint_contrast", "", 0, 255, 1,
         "How much brighter (luma) than the green on both sides a faint run's brightest pixel "
         "must be."}};
    Param<int> m_short_points{
        this,
        8,
        {"short_points", "", 0, 1000, 1,
         "After the lines of min_points, up to three lines of this many points or more that meet "
         "a longer line at a corner or a T (the goal area's lines far away or cut by a robot). 0 "
         "(or min_points and more): none."}};
    Param<double> m_short_gap{
        this,
        12,
        {"short_gap", "px", 1, 1000, 1,
         "A short line is split where its points leave a longer gap (max_gap for the others)."}};
    Param<double> m_junction{
        this,
        6,
        {"junction", "px", 0, 100, 0.5,
         "How close a short line's end must come to a longer line, at 17 degrees or more to it."}};
    Param<double> m_max_bow{
        this,
        0.7,
        {"max_bow", "px", 0, 50, 0.1,
         "A line whose middle third of points lies further than this from its outer thirds "
         "(across the line) bends: a chord of the centre circle, not a field line. 0 keeps "
         "bent lines."}};
    Param<double> m_circle_distance{
        this,
        3,
        {"circle_distance", "px", 0, 50, 0.5,
         "The bent lines' points give an ellipse (the centre circle seen in perspective, no "
         "semi-axis under twice this); a line with half its points or more this close to it is "
         "a chord of the circle, not a field line. 0: no ellipse."}};
    Param<std::uint32_t> m_seed{this, 1, kRansacSeed};
};

} // namespace fieldsight
