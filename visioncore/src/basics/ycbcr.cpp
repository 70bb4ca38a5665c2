// BGR <-> Y, Cb, Cr through OpenCV's YCrCb conversion and a channel swap.
#include "visioncore/basics/ycbcr.h"

#include <opencv2/imgproc.hpp>

namespace fieldsight {

namespace {
/// OpenCV orders the chroma channels Cr, Cb; the core orders them Cb, Cr. The swap is its own
/// inverse.
cv::Mat swapChroma(const cv::Mat& in)
{
    cv::Mat out(in.size(), CV_8UC3);
    const int from_to[] = {0, 0, 1, 2, 2, 1};
    cv::mixChannels(&in, 1, &out, 1, from_to, 3);
    return out;
}
} // namespace

cv::Mat bgrToYcbcr(const cv::Mat& bgr)
{
    cv::Mat ycrcb;
    cv::cvtColor(bgr, ycrcb, cv::COLOR_BGR2YCrCb);
    return swapChroma(ycrcb);
}

cv::Mat ycbcrToBgr(const cv::Mat& ycbcr)
{
    cv::Mat bgr;
    cv::cvtColor(swapChroma(ycbcr), bgr, cv::COLOR_YCrCb2BGR);
    return bgr;
}

} // namespace fieldsight
