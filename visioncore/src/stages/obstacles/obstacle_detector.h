// Obstacles (design note §2.8, extended): robots and people standing on the field, found as runs of
// non-field colour on the vertical scan lines below the green horizon, grouped across neighbouring
// scan lines. A robot that breaks the green horizon (the original's only case) starts its run at
// the horizon; a robot in front of open field is found too (the original missed those).
#pragma once

#include "visioncore/basics/segments.h"
#include "visioncore/framework/stage.h"

#include <vector>

namespace fieldsight {

class ObstacleDetector : public Stage
{
public:
    const StageInfo& info() const override;
    void run(Blackboard& bb) override;

private:
    /// One scan line's obstacle run.
    struct Run
    {
        int x;
        int top;
        int bottom; ///< inclusive
    };
    /// Runs on neighbouring scan lines taken for one obstacle.
    struct Group
    {
        int first_x, last_x, top, bottom, columns;
        int last_top, last_bottom;
        bool far = false; ///< far behind the deepest foot beside it (behind_ratio)
    };
    /// Fills m_edge_depth (how far each vertical scan's first run of obstacle colour reaches) and
    /// m_usual_depth (where the field usually starts there; see edge_band).
    /// `at_post`: per scan, whether a goalpost stands there.
    /// kMaxBridged at the frame's size.
    int maxBridged() const;
    void measureEdge(const SegmentedRegion& region, unsigned mask, bool band, int spacing,
                     const std::vector<char>& at_post);

    // Per-frame scratch, kept so a frame allocates nothing once they have grown.
    std::vector<Run> m_runs;
    std::vector<Run> m_behind_runs;     ///< robots above nearer ones (behind_green)
    std::vector<Group> m_behind_groups; ///< their pieces, merged among themselves
    std::vector<int> m_edge_depth;
    std::vector<int> m_sorted_depth;
    std::vector<std::size_t> m_left_stop, m_right_stop; ///< measureEdge's window limits
    std::vector<Group> m_groups;
    std::vector<int> m_usual_depth;
    std::vector<char> m_at_post;

    Param<int> m_min_run{this,
                         6,
                         {"min_run", "px", 1, 240, 1,
                          "Shortest run of non-field colour on a vertical scan line that can be "
                          "an obstacle."}};
    Param<int> m_min_columns{
        this, 2, {"min_columns", "", 1, 100, 1, "Scan lines an obstacle must span."}};
    Param<int> m_max_column_gap{
        this,
        1,
        {"max_column_gap", "", 0, 10, 1, "Scan lines an obstacle may skip (a white stripe)."}};
    Param<int> m_min_distance_from_horizon{
        this,
        0,
        {"min_distance_from_horizon", "px", 0, 100, 1,
         "An obstacle's foot must be at least this far below the green horizon."}};
    Param<double> m_min_height_ratio{
        this,
        0.3,
        {"min_height_ratio", "", 0, 2, 0.05,
         "A run must be this tall, as a share of how far its foot is below the green horizon "
         "(things lying flat are not obstacles)."}};
    Param<int> m_max_foot_jump{
        this,
        4,
        {"max_foot_jump", "px", 0, 240, 1,
         "Neighbouring scan lines whose feet differ by more belong to different obstacles."}};
    Param<double> m_max_width_ratio{
        this,
        0.75,
        {"max_width_ratio", "", 0, 5, 0.05,
         "Pieces of one robot merge while the whole is at most this wide for its height."}};
    Param<double> m_cut_width_ratio{
        this,
        1.5,
        {"cut_width_ratio", "", 0, 5, 0.05,
         "A piece that does not reach up to the green horizon (field above it: an arm, a hand) "
         "beside something cut by the image's bottom row (a robot close to the camera, taller "
         "than it shows) is part of it while the whole is at most this wide for its seen "
         "height (with a horizontal scan line crossing between them); at most max_width_ratio: "
         "no wider than other pieces of one robot."}};
    Param<double> m_min_width_ratio{
        this,
        0,
        {"min_width_ratio", "", 0, 2, 0.05,
         "An obstacle must be at least this wide, as a share of how far its foot is below the "
         "horizon (the kinematic one where the stream has it, else the green horizon); 0: off."}};
    Param<double> m_robot_width{
        this,
        0,
        {"robot_width", "", 0, 3, 0.05,
         "Where the stream gives the camera's horizon: the widest one robot can be, as a share "
         "of how far its foot is below the horizon; pieces on about the same row within it are "
         "one robot (0: off)."}};
    Param<double> m_edge_robot_width{
        this,
        0.55,
        {"edge_robot_width", "", 0, 3, 0.05,
         "Where the stream gives the camera's horizon: neighbouring pieces that both reach up to "
         "the green horizon, on about the same row and together at most this share of their "
         "foot's depth "
         "below the horizon wide, are one robot going on above the edge, where nothing is "
         "scanned (a far robot's two legs); 0: off."}};
    Param<double> m_behind_ratio{
        this,
        0.45,
        {"behind_ratio", "", 0, 1, 0.01,
         "Where the stream gives the camera's horizon: a piece on two or more scan lines whose "
         "foot is under this share as far below the horizon as the deepest foot of the pieces "
         "next to each other around it stands further away, a robot behind the nearer one "
         "showing beside it (a hand ends about 0.6 of the way down); 0: off."}};
    Param<double> m_cut_reach{
        this,
        0,
        {"cut_reach", "", 0, 1, 0.05,
         "Where the stream gives the camera's horizon: an obstacle cut by the image's bottom row "
         "must reach up to within this share of the image below the horizon (a robot that close "
         "is taller than the camera is high; the observing robot's own body is not); 0: off."}};
    Param<double> m_max_ball_overlap{
        this,
        0.5,
        {"max_ball_overlap", "", 0, 1, 0.05,
         "An obstacle with more of its box inside a found ball's square than this share is the "
         "ball's own shading, not something standing (1: off)."}};
    Param<int> m_min_edge_dip{
        this,
        4,
        {"min_edge_dip", "px", 0, 50, 1,
         "A column starting this many more non-field pixels than the usual one is covered by "
         "something at the field edge (0: off)."}};
    Param<bool> m_edge_band{
        this,
        false,
        {"edge_band", "", 0, 1, 1,
         "The usual start of the field is taken along each column's stretch of the edge "
         "(edge_window), not over the whole image, and a run from the green horizon must reach "
         "min_edge_dip below it: less is the edge's own band (a wall strip, a goal's frame)."}};
    Param<int> m_edge_window{
        this,
        120,
        {"edge_window", "px", 10, 640, 5,
         "With edge_band: the stretch of the edge over which the usual start of the field is "
         "taken (not past a goalpost); a robot narrower than half of it stands out."}};
    Param<double> m_plain_above{
        this,
        0,
        {"plain_above", "", 0, 1, 0.01,
         "A box reaching up to the green horizon is the edge's band, not something standing, "
         "when one colour (with the goal's) covers more than this share of as much again above "
         "it (a plain wall, a goal's net and frame); 0: off."}};
    Param<bool> m_post_fringe{
        this,
        true,
        {"post_fringe", "", 0, 1, 1,
         "A box beside a goalpost, no wider than it and standing about where it stands (its "
         "foot within half the post's height of the post's base) is the post's blurred "
         "side, not a robot (a robot is several posts wide at the same distance)."}};
    Param<int> m_behind_green{
        this,
        0,
        {"behind_green", "px", 0, 100, 1,
         "A scan line also takes the standing run just above its nearest one when at least this "
         "much carpet lies between them: a robot further away, showing above a nearer one in "
         "the same columns (crowded venues; 0: the nearest run only)."}};
    Param<bool> m_white_robots{
        this,
        false,
        {"white_robots", "", 0, 1, 1,
         "Robots may be white: a scan line with no run of other obstacle colour takes one "
         "counting white, when it stands (not a field line); white also counts as obstacle "
         "colour for the edge's depth and for joining a robot's pieces."}};
};

} // namespace fieldsight
