// Scanline classifier (design note §2.2): run-length colour segments along horizontal lines over
// the whole image and vertical lines from the green horizon down.
#pragma once

#include "visioncore/framework/stage.h"

#include <cstdint>
#include <vector>

namespace fieldsight {

/// One scan line's scratch, kept across frames.
struct ScanlineBuffers
{
    std::vector<std::uint8_t> classes; ///< the class of every pixel on the line
    std::vector<int> ends;             ///< where each segment ends (exclusive), along the line
};

class ScanlineClassifier : public Stage
{
public:
    const StageInfo& info() const override;
    void run(Blackboard& bb) override;

private:
    Param<int> m_horizontal_spacing{
        this,
        4,
        {"horizontal_spacing", "px", 1, 64, 1, "Rows between horizontal scan lines.", true, -1}};
    Param<int> m_vertical_spacing{
        this,
        4,
        {"vertical_spacing", "px", 1, 64, 1, "Columns between vertical scan lines.", true, -1}};
    ScanlineBuffers m_buffers;
};

} // namespace fieldsight
