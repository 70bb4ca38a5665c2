// Green horizon (design note §2.1): where the field starts, as the upper convex hull of the first
// green run in evenly spaced columns scanned down from the kinematic horizon.
#pragma once

#include "visioncore/stage.h"

namespace fieldsight {

class GreenHorizonDetector : public Stage
{
public:
    GreenHorizonDetector();
    const StageInfo& info() const override;
    void run(Blackboard& bb) override;

private:
    double m_scan_spacing = 11;
    double m_min_green_pixels = 5;
    double m_max_gap = 3;
    double m_upper_threshold_mult = 2.5;
};

} // namespace fieldsight
