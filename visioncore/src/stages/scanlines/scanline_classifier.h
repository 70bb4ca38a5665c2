// Scanline classifier (design note §2.2): run-length colour segments along horizontal lines over
// the whole image and vertical lines from the green horizon down.
#pragma once

#include "visioncore/stage.h"

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
    ScanlineClassifier();
    const StageInfo& info() const override;
    void run(Blackboard& bb) override;

private:
    double m_horizontal_spacing = 4;
    double m_vertical_spacing = 4;
    ScanlineBuffers m_buffers;
};

} // namespace fieldsight
