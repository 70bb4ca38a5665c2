// Per-frame state reset; containers keep their capacity so a frame allocates little.
#include "visioncore/framework/blackboard.h"

namespace fieldsight {

void Blackboard::beginFrame(const cv::Mat& image, const ColourLut& lut, Horizon kinematic)
{
    m_image = &image;
    m_lut = &lut;
    kinematic_horizon = kinematic;
    green_horizon.setTopRow(image.cols, image.rows);
    gh_scan_points.clear();
    gh_thrown_points.clear();
    horizontal_scan_ys.clear();
    vertical_scan_starts.clear();
    horizontal_segments.reset();
    vertical_segments.reset();
    horizontal_filtered.reset();
    vertical_filtered.reset();
    horizontal_transitions.clear();
    vertical_transitions.clear();
    percepts.clear();
    obstacle_points.clear();
    diagnostics.clear();
    debug.clear();
}

} // namespace fieldsight
