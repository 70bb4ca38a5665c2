// Ball (design note §2.7, fixed): the edge points of ball-coloured transitions below the green
// horizon are clustered and a circle is fitted to the largest cluster by RANSAC.
#pragma once

#include "visioncore/stage.h"

namespace fieldsight {

class BallDetector : public Stage
{
public:
    BallDetector();
    const StageInfo& info() const override;
    void run(Blackboard& bb) override;

private:
    double m_min_radius = 2.5;          // MIN_BALL_DIAMETER_PIXELS 5 in the original
    double m_min_orange_fraction = 0.2; // BALL_MIN_PERCENT_ORANGE
    double m_cluster_distance = 10;
    double m_max_fit_error = 1.5;
    double m_iterations = 100;
    double m_min_edge_support = 0.25;
    double m_seed = 1;
};

} // namespace fieldsight
