// Transition (segment) filter (design note §2.4): replacement rules clean noise out of the
// segments, then segments of the object colours become that object's "transitions".
#pragma once

#include "visioncore/colour.h"
#include "visioncore/segments.h"
#include "visioncore/stage.h"

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
    TransitionFilter();
    const StageInfo& info() const override;
    void run(Blackboard& bb) override;

private:
    void filterRegion(const SegmentedRegion& in, SegmentedRegion& out) const;
    void matchTransitions(const SegmentedRegion& region, Transitions& out) const;

    double m_goal_colour = double(Colour::Yellow);
    double m_ball_colour = double(Colour::Orange);
    double m_min_ball_length = 3;
    double m_min_goal_length = 2;
    double m_min_line_length = 2;
    double m_min_team_length = 2;
    double m_max_team_length = 50;
};

} // namespace fieldsight
