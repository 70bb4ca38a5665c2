// Per-frame state reset; containers keep their capacity so a frame allocates little.
#include "visioncore/framework/blackboard.h"

#include <cstdio>
#include <string>

namespace fieldsight {

void Blackboard::beginFrame(const cv::Mat& image, const ColourLut& lut, Horizon kinematic)
{
    m_image = &image;
    m_lut = &lut;
    const bool plausible = kinematic.isPlausible();
    kinematic_horizon = plausible ? kinematic : Horizon{};
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
    if (!plausible) {
        char text[96];
        std::snprintf(text, sizeof text, "(%.6g, %.6g) is not two rows within 1e6 px",
                      kinematic.y_left, kinematic.y_right);
        diagnostics.push_back(
            {"kinematic_horizon", std::string(text) + "; the whole image was searched"});
    }
}

} // namespace fieldsight
