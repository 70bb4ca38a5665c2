// Goalposts (design note §2.5, RANSAC edges): RANSAC lines through the left and right edges of
// goal-coloured horizontal transitions, paired into post quads, merged and assigned left/right.
#pragma once

#include "visioncore/stage.h"

namespace fieldsight {

class GoalpostDetector : public Stage
{
public:
    GoalpostDetector();
    const StageInfo& info() const override;
    void run(Blackboard& bb) override;

private:
    double m_min_points = 6; // 25 / HORIZONTAL_SCANLINE_SPACING in the original
    double m_iterations = 100;
    double m_max_error = 5;
    double m_max_lines = 3;
    double m_matching_tolerance = 0.2;
    double m_min_support_ratio = 0.3;
    double m_min_aspect = 1.5;
    double m_min_width = 3;
    double m_min_separation = 40;
    double m_merge_widths = 1.5;
    double m_seed = 1;
};

} // namespace fieldsight
