// Obstacles (design note §2.8, extended): robots and people standing on the field, found as runs of
// non-field colour on the vertical scan lines below the green horizon, grouped across neighbouring
// scan lines. A robot that breaks the green horizon (the original's only case) starts its run at
// the horizon; a robot in front of open field is found too (the original missed those).
#pragma once

#include "visioncore/stage.h"

namespace fieldsight {

class ObstacleDetector : public Stage
{
public:
    ObstacleDetector();
    const StageInfo& info() const override;
    void run(Blackboard& bb) override;

private:
    double m_min_run = 6;
    double m_min_columns = 2;
    double m_max_column_gap = 1;
    double m_min_distance_from_horizon = 0;
    double m_min_height_ratio = 0.3;
    double m_max_foot_jump = 4;
    double m_max_width_ratio = 0.75;
    double m_min_edge_dip = 4;
};

} // namespace fieldsight
