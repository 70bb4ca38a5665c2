// Blackboard: one frame's state, shared by the stages of one controller. Not a singleton: every
// ControlWrapper owns its own, so several cores run side by side. The working slots below are
// named in the stages' StageInfo::reads and writes (by the names in the comments); the
// percepts are the frame's output.
#pragma once

#include "visioncore/basics/colour_lut.h"
#include "visioncore/basics/debug_drawing.h"
#include "visioncore/basics/geometry.h"
#include "visioncore/percepts/green_horizon.h"
#include "visioncore/percepts/percept_set.h"
#include "visioncore/basics/segments.h"

#include <opencv2/core/mat.hpp>

#include <cstdlib>
#include <string>
#include <vector>

namespace fieldsight {

/// A problem in one frame that did not stop the frame (a stage threw, a stage was starved).
struct Diagnostic
{
    std::string stage; ///< stage id, or the input the problem came from ("kinematic_horizon")
    std::string message;
};

class Blackboard
{
public:
    /// Clears every per-frame field and takes the inputs of the new frame (kept by reference: the
    /// DataWrapper guarantees they outlive the frame).
    void beginFrame(const cv::Mat& image, const ColourLut& lut, Horizon kinematic_horizon);

    // Inputs (the DataWrapper's snapshot for this frame).
    const cv::Mat& image() const { return *m_image; }
    const ColourLut& lut() const { return *m_lut; }
    int width() const { return m_image->cols; }
    int height() const { return m_image->rows; }
    Colour classify(int x, int y) const
    {
        const auto* p = m_image->ptr<std::uint8_t>(y) + 3 * x;
        return m_lut->classify(p[0], p[1], p[2]);
    }
    Horizon kinematic_horizon; ///< slot "kinematic_horizon" (an input)

    // Slot "green_horizon" (the green horizon stage).
    GreenHorizon green_horizon;
    std::vector<PixelPoint> gh_scan_points;   ///< first green run per column
    std::vector<PixelPoint> gh_thrown_points; ///< scan points dropped as outliers

    // Slot "scan_lines" (the scanline classifier).
    std::vector<int> horizontal_scan_ys;          ///< px, y of every horizontal scan line
    std::vector<PixelPoint> vertical_scan_starts; ///< px, top of every vertical scan line
    /// px between neighbouring scan lines (`fallback` before the scanline stage has run).
    int horizontalScanSpacing(int fallback = 4) const
    {
        return horizontal_scan_ys.size() >= 2
                   ? std::abs(horizontal_scan_ys[0] - horizontal_scan_ys[1])
                   : fallback;
    }
    int verticalScanSpacing(int fallback = 4) const
    {
        return vertical_scan_starts.size() >= 2
                   ? std::abs(vertical_scan_starts[1].x - vertical_scan_starts[0].x)
                   : fallback;
    }
    // Slot "segments" (the scanline classifier).
    SegmentedRegion horizontal_segments{ScanDirection::Horizontal, {}, 0};
    SegmentedRegion vertical_segments{ScanDirection::Vertical, {}, 0};

    // Slot "filtered_segments" (the transition filter).
    SegmentedRegion horizontal_filtered{ScanDirection::Horizontal, {}, 0};
    SegmentedRegion vertical_filtered{ScanDirection::Vertical, {}, 0};
    // Slot "transitions" (the transition filter).
    Transitions horizontal_transitions;
    Transitions vertical_transitions;

    // Slot "obstacle_points" (the obstacle stage).
    std::vector<PixelPoint> obstacle_points; ///< px, foot of every obstacle run

    /// What the stages found, the frame's output: each list is also a slot, by its key
    /// ("balls", "goalposts", "green_horizon", ...).
    PerceptSet percepts;

    std::vector<Diagnostic> diagnostics;
    DebugCanvas debug;

private:
    const cv::Mat* m_image = nullptr;
    const ColourLut* m_lut = nullptr;
};

} // namespace fieldsight
