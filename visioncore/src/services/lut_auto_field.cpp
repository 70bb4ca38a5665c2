// The automatic table's field (lut_auto_evidence.h): where the carpet's far edge is, and which
// bright pixels lie in thin runs on it (the lines).
#include "lut_auto_evidence.h"

#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cmath>

namespace fieldsight::autolut {
namespace {

/// The field: the largest patch of carpet (lines closed over) reaching the lower half. A green
/// poster or board on the wall is a patch of its own.
cv::Mat fieldPatch(const cv::Mat& green, double scale)
{
    cv::Mat closed;
    const int k = 2 * std::max(1, int(std::lround(2 * scale))) + 1;
    cv::morphologyEx(green, closed, cv::MORPH_CLOSE,
                     cv::getStructuringElement(cv::MORPH_RECT, cv::Size(k, k)));
    cv::Mat labels, stats, centroids;
    const int n = cv::connectedComponentsWithStats(closed, labels, stats, centroids, 8, CV_32S);
    int best = 0;
    for (int i = 1; i < n; ++i) {
        const int bottom = stats.at<int>(i, cv::CC_STAT_TOP) + stats.at<int>(i, cv::CC_STAT_HEIGHT);
        if (bottom > green.rows / 2 && (best == 0 || stats.at<int>(i, cv::CC_STAT_AREA) >
                                                         stats.at<int>(best, cv::CC_STAT_AREA)))
            best = i;
    }
    cv::Mat patch = labels == best;
    if (best == 0)
        patch.setTo(0);
    return patch;
}

bool anyGreen(const cv::Mat& green, int y, int x0, int x1)
{
    x0 = std::max(0, x0);
    x1 = std::min(green.cols - 1, x1);
    const std::uint8_t* row = green.ptr<std::uint8_t>(y);
    for (int x = x0; x <= x1; ++x)
        if (row[x])
            return true;
    return false;
}

bool anyGreenColumn(const cv::Mat& green, int x, int y0, int y1)
{
    y0 = std::max(0, y0);
    y1 = std::min(green.rows - 1, y1);
    for (int y = y0; y <= y1; ++y)
        if (green.at<std::uint8_t>(y, x))
            return true;
    return false;
}

} // namespace

/// The field's far edge per column: the upper convex hull of each column's first row of the
/// field patch from which it fills at least half of a window below; rows below it are the field.
std::vector<double> fieldEdge(const cv::Mat& green_all, double scale)
{
    const cv::Mat green = fieldPatch(green_all, scale);
    const int w = green.cols;
    const int h = green.rows;
    const int window = std::max(4, int(std::lround(8 * scale)));
    std::vector<cv::Point2d> tops;
    std::vector<int> count(std::size_t(h) + 1);
    for (int x = 0; x < w; ++x) {
        count[std::size_t(h)] = 0;
        for (int y = h - 1; y >= 0; --y)
            count[std::size_t(y)] = count[std::size_t(y) + 1] + (green.at<std::uint8_t>(y, x) != 0);
        int top = -1;
        for (int y = 0; y + window <= h; ++y) {
            if (green.at<std::uint8_t>(y, x) &&
                2 * (count[std::size_t(y)] - count[std::size_t(y + window)]) >= window) {
                top = y;
                break;
            }
        }
        if (top >= 0)
            tops.emplace_back(x, -double(top)); // y up, for the upper hull
    }
    std::vector<double> edge(static_cast<std::size_t>(w), static_cast<double>(h));
    if (tops.size() < std::size_t(w / 5))
        return edge; // no field in this frame
    std::vector<cv::Point2d> hull;
    for (const cv::Point2d& p : tops) {
        while (hull.size() >= 2) {
            const cv::Point2d& a = hull[hull.size() - 2];
            const cv::Point2d& b = hull.back();
            if ((b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x) >= 0)
                hull.pop_back();
            else
                break;
        }
        hull.push_back(p);
    }
    for (int x = 0; x < w; ++x) {
        if (x <= hull.front().x) {
            edge[std::size_t(x)] = -hull.front().y;
            continue;
        }
        if (x >= hull.back().x) {
            edge[std::size_t(x)] = -hull.back().y;
            continue;
        }
        const auto next = std::upper_bound(hull.begin(), hull.end(), double(x),
                                           [](double v, const cv::Point2d& p) { return v < p.x; });
        const cv::Point2d& b = *next;
        const cv::Point2d& a = *(next - 1);
        edge[std::size_t(x)] = -(a.y + (b.y - a.y) * (x - a.x) / (b.x - a.x));
    }
    return edge;
}

/// Marks in `white` the candidates that lie in thin runs with carpet at both ends, across rows
/// and down columns. The widest run allowed grows towards the bottom of the frame, where lines
/// are nearer.
void thinRuns(const cv::Mat& candidate, const cv::Mat& green, const std::vector<double>& edge,
              double scale, cv::Mat& white)
{
    const int w = candidate.cols;
    const int h = candidate.rows;
    const int reach = std::max(2, int(std::lround(3 * scale)));
    for (int y = 0; y < h; ++y) {
        const std::uint8_t* row = candidate.ptr<std::uint8_t>(y);
        const double longest = scale * (4 + 26.0 * y / h);
        for (int x = 0; x < w;) {
            if (!row[x] || y < edge[std::size_t(x)] - 1) {
                ++x;
                continue;
            }
            int end = x;
            while (end + 1 < w && row[end + 1])
                ++end;
            if (end - x + 1 <= longest && anyGreen(green, y, x - reach, x - 1) &&
                anyGreen(green, y, end + 1, end + reach))
                for (int i = x; i <= end; ++i)
                    white.at<std::uint8_t>(y, i) = 1;
            x = end + 1;
        }
    }
    for (int x = 0; x < w; ++x) {
        for (int y = std::max(0, int(edge[std::size_t(x)]) - 1); y < h;) {
            if (!candidate.at<std::uint8_t>(y, x)) {
                ++y;
                continue;
            }
            int end = y;
            while (end + 1 < h && candidate.at<std::uint8_t>(end + 1, x))
                ++end;
            const double longest = scale * (3 + 20.0 * end / h);
            if (end - y + 1 <= longest && anyGreenColumn(green, x, y - reach, y - 1) &&
                anyGreenColumn(green, x, end + 1, end + reach))
                for (int i = y; i <= end; ++i)
                    white.at<std::uint8_t>(i, x) = 1;
            y = end + 1;
        }
    }
}

} // namespace fieldsight::autolut
