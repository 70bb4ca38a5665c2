// Field lines (design note §2.6): RANSAC lines through the centres of white transitions below the
// green horizon, then colinear lines merged.
#pragma once

#include "visioncore/stage.h"

namespace fieldsight {

class FieldLineDetector : public Stage
{
public:
    FieldLineDetector();
    const StageInfo& info() const override;
    void run(Blackboard& bb) override;

private:
    double m_min_points = 12;
    double m_iterations = 15;
    double m_max_error = 2.5;
    double m_max_lines = 10;
    double m_merge_angle = 0.1;
    double m_merge_distance = 6;
    double m_max_gap = 40;
    double m_locality = 8;
    double m_seed = 1;
};

} // namespace fieldsight
