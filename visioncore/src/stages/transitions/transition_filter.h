// Transition (segment) filter (design note §2.4): replacement rules clean noise out of the
// segments, then segments of the object colours become that object's "transitions".
#pragma once

#include "visioncore/basics/colour.h"
#include "visioncore/basics/segments.h"
#include "visioncore/framework/stage.h"

#include <vector>

namespace fieldsight {

/// A replacement rule: a short middle segment between matching neighbours takes their colour.
/// Lengths in px; max < 0 means unbounded. Rules match in either direction along the scan.
struct ReplacementRule
{
    enum class Method { Before, After, Split };
    struct Part
    {
        int min = 0;
        int max = -1;
        std::vector<Colour> colours; ///< must be non-empty for the middle
    };
    const char* name;
    Part before, middle, after;
    Method method;
};

/// The original's nine default replacement rules (Darwin/Config/*/Rules/ReplacementRules.txt),
/// plus two that mend noise inside distant goalposts.
const std::vector<ReplacementRule>& defaultReplacementRules();

class TransitionFilter : public Stage
{
public:
    const StageInfo& info() const override;
    void run(Blackboard& bb) override;

private:
    void filterRegion(const SegmentedRegion& in, SegmentedRegion& out) const;
    void matchTransitions(const SegmentedRegion& region, Transitions& out) const;

    Param<Colour> m_goal_colour{
        this,
        Colour::Yellow,
        {"goal_colour", "", 0, 0, 1, "Colour class of the goalposts (blue for B-Human logs)."}};
    Param<Colour> m_ball_colour{
        this, Colour::Orange, {"ball_colour", "", 0, 0, 1, "Colour class of the ball."}};
    Param<int> m_min_ball_length{
        this, 3, {"min_ball_length", "px", 1, 100, 1, "Shorter ball-coloured runs are ignored."}};
    Param<int> m_min_goal_length{
        this,
        2,
        {"min_goal_length", "px", 1, 100, 1,
         "Shorter goal-coloured runs are ignored (a far post is 2 px wide)."}};
    Param<int> m_min_line_length{
        this, 2, {"min_line_length", "px", 1, 100, 1, "Shorter white runs are ignored."}};
    Param<int> m_min_team_length{
        this, 2, {"min_team_length", "px", 1, 100, 1, "Shorter team-marker runs are ignored."}};
    Param<int> m_max_team_length{
        this, 50, {"max_team_length", "px", 1, 1000, 1, "Longer team-marker runs are ignored."}};
};

} // namespace fieldsight
