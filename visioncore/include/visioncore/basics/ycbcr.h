// The one conversion between OpenCV's BGR images and the core's Y, Cb, Cr pixels (SPEC §2).
#pragma once

#include <opencv2/core/mat.hpp>

#include <array>

namespace fieldsight {

/// BT.601 full range, as JPEG and OpenCV's COLOR_BGR2YCrCb, with the channels in the core's
/// order Y, Cb, Cr. `bgr` is CV_8UC3.
cv::Mat bgrToYcbcr(const cv::Mat& bgr);
/// The inverse of bgrToYcbcr (exact up to rounding): CV_8UC3 Y, Cb, Cr to CV_8UC3 B, G, R.
cv::Mat ycbcrToBgr(const cv::Mat& ycbcr);
/// As ycbcrToBgr, with alpha 255, written into `bgra` (CV_8UC4, the size of `ycbcr`, kept):
/// one pass, without a frame-sized buffer in between.
void ycbcrToBgra(const cv::Mat& ycbcr, cv::Mat& bgra);

/// R, G, B of Y, Cb - 128 and Cr - 128 (BT.601 full range) in integers, the coefficients in
/// 1/256, rounded down: in levels for levels, in 1/256 levels for 1/256 levels (the light
/// tracker's samples, the input map's test for a clipped cell).
constexpr std::array<int, 3> rgbOfYcc(int y, int cb, int cr)
{
    return {y + ((359 * cr) >> 8), y - ((88 * cb + 183 * cr) >> 8), y + ((454 * cb) >> 8)};
}

} // namespace fieldsight
