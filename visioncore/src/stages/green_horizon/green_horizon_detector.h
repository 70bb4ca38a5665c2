// Green horizon (design note §2.1): where the field starts, as the upper convex hull of the first
// green run in evenly spaced columns scanned down from the kinematic horizon.
#pragma once

#include "visioncore/framework/stage.h"
#include "visioncore/basics/geometry.h"

#include <vector>

namespace fieldsight {

class GreenHorizonDetector : public Stage
{
public:
    const StageInfo& info() const override;
    void run(Blackboard& bb) override;

private:
    std::vector<PointF> m_hull; ///< per-frame scratch, kept so a frame allocates nothing

    Param<int> m_scan_spacing{
        this,
        11,
        {"scan_spacing", "px", 1, 64, 1, "Distance between the columns scanned for green."}};
    Param<int> m_min_green_pixels{
        this,
        5,
        {"min_green_pixels", "px", 1, 50, 1,
         "How many green pixels in a column (gaps bridged) mark the start of the field."}};
    Param<int> m_max_gap{this,
                         3,
                         {"max_gap", "px", 0, 20, 1,
                          "Non-green pixels (a field line, noise) a green run may bridge."}};
    Param<double> m_upper_threshold_mult{
        this,
        2.5,
        {"upper_threshold_mult", "sigma", 0, 10, 0.1,
         "Scan points more than this many standard deviations above the mean are thrown out "
         "(green above the field: posters, shirts)."}};
};

} // namespace fieldsight
