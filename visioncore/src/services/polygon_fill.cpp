// Polygon filling by runs: each edge is cut into the runs of rows (or columns) over which nothing
// about it changes, each run leaves two marks, and one pass over the bounding box turns the marks
// into pixels. No sorting, no active edge list, no pixel-by-pixel line.
#include "services/polygon_fill.h"

#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cstdint>
#include <cstring>

namespace fieldsight {

namespace {

/// cv::fillPoly's fixed point: x in 1/65536 px.
constexpr int kShift = 16;
constexpr std::int64_t kOne = std::int64_t(1) << kShift;
constexpr int kFar = 1 << 24; ///< px; keeps every product below in 64 bits

/// A mark's bits. kDownToggle: from this row down (until the next one in the column), the
/// crossing count left of the pixel changes parity here. kRowToggle: the same, on this row only.
constexpr std::uint8_t kDownToggle = 1;
constexpr std::uint8_t kRowToggle = 2;

cv::Point clamped(cv::Point p)
{
    return {std::clamp(p.x, -kFar, kFar), std::clamp(p.y, -kFar, kFar)};
}

/// The marks of one polygon over the box [left, left + cols) x [top, top + rows) of the image.
struct Marks
{
    int left = 0, top = 0;
    cv::Mat1b toggles; ///< rows + 1 rows (a run's end is marked on the row after it)
    cv::Mat1i forced;  ///< rows + 1 rows: +1 where a column's run of set pixels starts, -1 after

    /// Sets the pixels of column `x`, rows `y0` to `y1`, whatever the parity (image coordinates;
    /// nothing outside the box).
    void force(int x, int y0, int y1)
    {
        x -= left;
        y0 = std::max(y0 - top, 0);
        y1 = std::min(y1 - top, forced.rows - 2);
        if (x < 0 || x >= forced.cols || y0 > y1)
            return;
        forced(y0, x) += 1;
        forced(y1 + 1, x) -= 1;
    }

    /// The fill's crossings of one edge, as cv::fillPoly computes them: x from the upper end
    /// with the slope truncated to fixed point, on the rows from the upper end to before the
    /// lower one. A pixel is inside when an odd number of crossings lie strictly left of it,
    /// or one lies exactly on it.
    void addEdge(cv::Point a, cv::Point b)
    {
        if (a.y == b.y)
            return;
        const std::int64_t dx = (std::int64_t(b.x - a.x) << kShift) / std::int64_t(b.y - a.y);
        const cv::Point upper = a.y < b.y ? a : b;
        const int first = std::max(upper.y, top);
        const int last = std::min(std::max(a.y, b.y) - 1, top + toggles.rows - 2);
        const int right = left + toggles.cols - 1;
        std::int64_t x = (std::int64_t(upper.x) << kShift) + std::int64_t(first - upper.y) * dx;
        const bool steep = dx > -kOne && dx < kOne;
        for (int y = first; y <= last;) {
            // The first pixel strictly right of the crossing, the same over rows y .. end.
            const std::int64_t pixel = (x >> kShift) + 1;
            int end = y;
            if (steep && dx != 0) {
                const std::int64_t base = (x >> kShift) << kShift;
                const std::int64_t rows = dx > 0 ? (base + kOne - x + dx - 1) / dx // to next px
                                                 : (x - base) / -dx + 1;           // below base
                end = int(std::min<std::int64_t>(last, y + rows - 1));
            } else if (steep) {
                end = last;
            }
            // A crossing exactly on a pixel: only where x is whole, the run's first row when x
            // grows, its last when x shrinks, every row of a vertical edge.
            const std::int64_t on = x >> kShift;
            if (dx >= 0 && (x & (kOne - 1)) == 0)
                force(int(on), y, dx == 0 ? end : y);
            const std::int64_t x_end = x + std::int64_t(end - y) * dx;
            if (dx < 0 && (x_end & (kOne - 1)) == 0)
                force(int(x_end >> kShift), end, end);
            if (pixel <= right) {
                const int column = int(std::max<std::int64_t>(pixel - left, 0));
                if (end == y) {
                    toggles(y - top, column) ^= kRowToggle;
                } else {
                    toggles(y - top, column) ^= kDownToggle;
                    toggles(end + 1 - top, column) ^= kDownToggle;
                }
            }
            x += std::int64_t(end - y + 1) * dx;
            y = end + 1;
        }
    }

    /// The outline of one edge as cv::line draws it (8-connected, clipped to the image, from the
    /// left end), in runs: a run along a row is drawn at once, a run down a column is marked.
    void addOutline(cv::Mat& image, cv::Point a, cv::Point b, std::uint8_t value)
    {
        if (!cv::clipLine(image.size(), a, b))
            return;
        if (a.x > b.x)
            std::swap(a, b);
        const int dx = b.x - a.x, step_y = b.y >= a.y ? 1 : -1, dy = std::abs(b.y - a.y);
        const bool vertical = dy > dx;
        const std::int64_t major = vertical ? dy : dx, minor = vertical ? dx : dy;
        // Bresenham as cv::LineIterator runs it: pixel k of the major axis is minor(k) =
        // floor((2 minor k + major - 1) / (2 major)) along the other; run j starts at the
        // first k with minor(k) = j.
        const auto runStart = [&](std::int64_t j) -> std::int64_t {
            if (j == 0)
                return 0;
            if (j > minor)
                return major + 1;
            return (2 * major * j - major + 1 + 2 * minor - 1) / (2 * minor);
        };
        for (std::int64_t j = 0; j <= minor; ++j) {
            const std::int64_t from = runStart(j), to = runStart(j + 1) - 1;
            if (from > to)
                continue;
            if (vertical) {
                const int y0 = a.y + step_y * int(from), y1 = a.y + step_y * int(to);
                force(a.x + int(j), std::min(y0, y1), std::max(y0, y1));
            } else {
                const int y = a.y + step_y * int(j);
                std::memset(image.ptr<std::uint8_t>(y) + a.x + from, value,
                            std::size_t(to - from + 1));
            }
        }
    }
};

} // namespace

void fillPolygon(cv::Mat& image, const std::vector<cv::Point>& polygon, std::uint8_t value)
{
    CV_Assert(image.type() == CV_8UC1);
    if (polygon.empty() || image.empty())
        return;
    int min_x = kFar, max_x = -kFar, min_y = kFar, max_y = -kFar;
    for (const cv::Point& raw : polygon) {
        const cv::Point p = clamped(raw);
        min_x = std::min(min_x, p.x);
        max_x = std::max(max_x, p.x);
        min_y = std::min(min_y, p.y);
        max_y = std::max(max_y, p.y);
    }
    // Every pixel filled or on the outline lies in the polygon's bounding box.
    const int top = std::max(min_y, 0), bottom = std::min(max_y, image.rows - 1);
    const int left = std::max(min_x, 0), right = std::min(max_x, image.cols - 1);
    if (top > bottom || left > right)
        return;
    Marks marks;
    marks.left = left;
    marks.top = top;
    marks.toggles = cv::Mat1b(bottom - top + 2, right - left + 1, std::uint8_t(0));
    marks.forced = cv::Mat1i(bottom - top + 2, right - left + 1, 0);
    cv::Point previous = clamped(polygon.back());
    for (const cv::Point& raw : polygon) {
        const cv::Point p = clamped(raw);
        if (polygon.size() >= 2)
            marks.addEdge(previous, p);
        marks.addOutline(image, previous, p, value);
        previous = p;
    }
    std::vector<std::uint8_t> down(std::size_t(right - left + 1), 0);
    std::vector<int> covered(std::size_t(right - left + 1), 0);
    for (int y = top; y <= bottom; ++y) {
        const std::uint8_t* toggles = marks.toggles.ptr<std::uint8_t>(y - top);
        const int* forced = marks.forced.ptr<int>(y - top);
        std::uint8_t* out = image.ptr<std::uint8_t>(y) + left;
        std::uint8_t inside = 0;
        for (std::size_t i = 0; i < down.size(); ++i) {
            down[i] ^= toggles[i] & kDownToggle;
            covered[i] += forced[i];
            inside ^= std::uint8_t(down[i] ^ ((toggles[i] & kRowToggle) >> 1));
            if (inside || covered[i] > 0)
                out[i] = value;
        }
    }
}

} // namespace fieldsight
