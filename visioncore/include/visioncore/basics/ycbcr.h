// The one conversion between OpenCV's BGR images and the core's Y, Cb, Cr pixels (SPEC §2).
#pragma once

#include <opencv2/core/mat.hpp>

namespace fieldsight {

/// BT.601 full range, as JPEG and OpenCV's COLOR_BGR2YCrCb, with the channels in the core's
/// order Y, Cb, Cr. `bgr` is CV_8UC3.
cv::Mat bgrToYcbcr(const cv::Mat& bgr);
/// The inverse of bgrToYcbcr (exact up to rounding): CV_8UC3 Y, Cb, Cr to CV_8UC3 B, G, R.
cv::Mat ycbcrToBgr(const cv::Mat& ycbcr);
/// As ycbcrToBgr, with alpha 255, written into `bgra` (CV_8UC4, the size of `ycbcr`, kept):
/// one pass, without a frame-sized buffer in between.
void ycbcrToBgra(const cv::Mat& ycbcr, cv::Mat& bgra);

} // namespace fieldsight
