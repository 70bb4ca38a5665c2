// One camera frame as the core sees it: YCbCr bytes plus what the source knows about it.
#pragma once

#include "visioncore/basics/geometry.h"

#include <opencv2/core/mat.hpp>

#include <optional>
#include <string>

namespace fieldsight {

struct Frame
{
    cv::Mat ycbcr;                  ///< CV_8UC3, channels Y, Cb, Cr; top-left origin
    std::string name;               ///< file name in the stream, or "frame_N" for .strm/video
    double timestamp_ms = 0;        ///< ms, from the source (0 when unknown)
    std::optional<Horizon> horizon; ///< kinematic horizon from the stream, if it has one
};

} // namespace fieldsight
