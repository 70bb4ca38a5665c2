// Goalposts (design note §2.5, RANSAC edges): RANSAC lines through the left and right edges of
// goal-coloured horizontal transitions, paired into post quads, merged and assigned left/right.
#pragma once

#include "stages/common/stage_util.h"
#include "visioncore/framework/stage.h"

#include <cstdint>
#include <vector>

namespace fieldsight {

class GoalpostDetector : public Stage
{
public:
    const StageInfo& info() const override;
    void run(Blackboard& bb) override;

private:
    // Per-frame scratch, kept so a frame allocates nothing once they have grown.
    std::vector<PointF> m_lefts;
    std::vector<PointF> m_rights;

    Param<int> m_min_points{
        this, 6, {"min_points", "", 2, 100, 1, "Edge points needed for a post edge."}};
    Param<int> m_iterations{
        this,
        100,
        {"iterations", "", 1, 10000, 1, "RANSAC samples per edge line, at most.", true, +1}};
    Param<double> m_max_error{
        this,
        5,
        {"max_error", "px", 0.5, 50, 0.5, "How far an edge point may lie from its edge line."}};
    Param<int> m_max_lines{
        this,
        3,
        {"max_lines", "", 1, 10, 1, "Edge lines per side (left and right edges).", true, +1}};
    Param<double> m_matching_tolerance{
        this,
        0.2,
        {"matching_tolerance", "", 0, 1, 0.05,
         "How much a post's left and right edges may differ in angle, length and point count."}};
    Param<double> m_min_support_ratio{
        this,
        0.3,
        {"min_support_ratio", "", 0, 1, 0.05,
         "The shorter edge of a post needs this share of the longer one's length and points "
         "(low enough for a post half hidden by a robot)."}};
    Param<double> m_min_aspect{
        this,
        1.5,
        {"min_aspect", "", 0, 20, 0.1, "Posts must be this many times taller than wide."}};
    Param<double> m_min_width{
        this, 3, {"min_width", "px", 0, 100, 0.5, "Posts this narrow or narrower are ignored."}};
    Param<int> m_min_separation{this,
                                40,
                                {"min_separation", "px", 0, 1000, 1,
                                 "Two posts at least this far apart are labelled left and right."}};
    Param<double> m_merge_widths{
        this,
        1.5,
        {"merge_widths", "", 0, 10, 0.1, "Posts closer than this many post widths are merged."}};
    Param<double> m_max_foot_above_field{
        this,
        40,
        {"max_foot_above_field", "px", -1, 240, 1,
         "How far above the green horizon a post's foot may be (a post stands on the field; "
         "-1: off)."}};
    Param<std::uint32_t> m_seed{this, 1, kRansacSeed};
};

} // namespace fieldsight
