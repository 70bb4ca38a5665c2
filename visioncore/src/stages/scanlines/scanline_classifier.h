// Scanline classifier (design note §2.2): run-length colour segments along horizontal lines over
// the whole image and vertical lines from the green horizon down.
#pragma once

#include "visioncore/stage.h"

#include <cstdint>
#include <vector>

namespace fieldsight {

class ScanlineClassifier : public Stage
{
public:
    ScanlineClassifier();
    const StageInfo& info() const override;
    void run(Blackboard& bb) override;

private:
    double m_horizontal_spacing = 4;
    double m_vertical_spacing = 4;
    std::vector<std::uint8_t> m_classes; ///< one scan line's classes (scratch, kept across frames)
};

} // namespace fieldsight
