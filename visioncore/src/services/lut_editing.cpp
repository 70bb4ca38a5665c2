#include "visioncore/services/lut_editing.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>

namespace fieldsight {

namespace {

/// The 7-bit cell coordinates that the 8-bit levels v - t .. v + t fall in.
std::pair<int, int> cellRange(int v, int t)
{
    t = std::max(0, t);
    return {std::clamp(v - t, 0, 255) >> 1, std::clamp(v + t, 0, 255) >> 1};
}

void addBox(std::vector<std::uint32_t>& cells, const cv::Vec3b& c, const Tolerance& t)
{
    const auto [y0, y1] = cellRange(c[0], t.y);
    const auto [b0, b1] = cellRange(c[1], t.cb);
    const auto [r0, r1] = cellRange(c[2], t.cr);
    for (int y = y0; y <= y1; ++y)
        for (int b = b0; b <= b1; ++b)
            for (int r = r0; r <= r1; ++r)
                cells.push_back(std::uint32_t((y << 14) | (b << 7) | r));
}

void sortUnique(std::vector<std::uint32_t>& cells)
{
    std::sort(cells.begin(), cells.end());
    cells.erase(std::unique(cells.begin(), cells.end()), cells.end());
}

} // namespace

std::vector<std::uint32_t> cellsInUvDisc(int cb, int cr, int radius, int y_lo, int y_hi)
{
    std::vector<std::uint32_t> cells;
    radius = std::max(0, radius);
    y_lo = std::clamp(y_lo, 0, 127);
    y_hi = std::clamp(y_hi, 0, 127);
    for (int y = y_lo; y <= y_hi; ++y)
        for (int b = std::max(0, cb - radius); b <= std::min(127, cb + radius); ++b)
            for (int r = std::max(0, cr - radius); r <= std::min(127, cr + radius); ++r)
                if ((b - cb) * (b - cb) + (r - cr) * (r - cr) <= radius * radius)
                    cells.push_back(std::uint32_t((y << 14) | (b << 7) | r));
    return cells;
}

std::vector<std::uint32_t> cellsInUvRect(int cb0, int cr0, int cb1, int cr1, int y_lo, int y_hi)
{
    std::vector<std::uint32_t> cells;
    cb0 = std::clamp(cb0, 0, 127);
    cb1 = std::clamp(cb1, 0, 127);
    cr0 = std::clamp(cr0, 0, 127);
    cr1 = std::clamp(cr1, 0, 127);
    const int b0 = std::min(cb0, cb1), b1 = std::max(cb0, cb1);
    const int r0 = std::min(cr0, cr1), r1 = std::max(cr0, cr1);
    y_lo = std::clamp(y_lo, 0, 127);
    y_hi = std::clamp(y_hi, 0, 127);
    for (int y = y_lo; y <= y_hi; ++y)
        for (int b = b0; b <= b1; ++b)
            for (int r = r0; r <= r1; ++r)
                cells.push_back(std::uint32_t((y << 14) | (b << 7) | r));
    return cells;
}

std::vector<std::uint32_t> cellsInBox(std::uint8_t y, std::uint8_t cb, std::uint8_t cr,
                                      const Tolerance& tolerance)
{
    std::vector<std::uint32_t> cells;
    addBox(cells, cv::Vec3b(y, cb, cr), tolerance);
    return cells; // the loops already give ascending, distinct cells
}

std::vector<cv::Point> brushPixels(cv::Point centre, int radius, cv::Size size)
{
    std::vector<cv::Point> pixels;
    radius = std::max(0, radius);
    const long long r2 = (long long)(radius)*radius;
    for (int dy = -radius; dy <= radius; ++dy) {
        for (int dx = -radius; dx <= radius; ++dx) {
            const cv::Point p(centre.x + dx, centre.y + dy);
            if ((long long)(dx)*dx + (long long)(dy)*dy <= r2 && p.x >= 0 && p.y >= 0 &&
                p.x < size.width && p.y < size.height)
                pixels.push_back(p);
        }
    }
    return pixels;
}

std::vector<cv::Point> strokePoints(cv::Point from, cv::Point to, bool include_from)
{
    std::vector<cv::Point> points;
    const int steps = std::max({1, std::abs(to.x - from.x), std::abs(to.y - from.y)});
    if (include_from)
        points.push_back(from);
    if (from == to)
        return include_from ? points : std::vector<cv::Point>{to};
    for (int i = 1; i <= steps; ++i)
        points.emplace_back(int(std::lround(from.x + (to.x - from.x) * i / double(steps))),
                            int(std::lround(from.y + (to.y - from.y) * i / double(steps))));
    return points;
}

std::vector<cv::Point> strokePixels(cv::Point from, cv::Point to, int radius, cv::Size size,
                                    bool include_from)
{
    std::vector<cv::Point> pixels;
    for (const cv::Point& centre : strokePoints(from, to, include_from)) {
        const auto disc = brushPixels(centre, radius, size);
        pixels.insert(pixels.end(), disc.begin(), disc.end());
    }
    return pixels;
}

std::vector<std::uint32_t> strokeUvCells(cv::Point from, cv::Point to, int radius, int y_lo,
                                         int y_hi, bool include_from)
{
    std::vector<std::uint32_t> cells;
    for (const cv::Point& centre : strokePoints(from, to, include_from)) {
        const auto disc = cellsInUvDisc(centre.x, centre.y, radius, y_lo, y_hi);
        cells.insert(cells.end(), disc.begin(), disc.end());
    }
    std::sort(cells.begin(), cells.end());
    cells.erase(std::unique(cells.begin(), cells.end()), cells.end());
    return cells;
}

std::vector<cv::Point> wandPixels(const cv::Mat& ycbcr, cv::Point seed, const Tolerance& tolerance)
{
    std::vector<cv::Point> pixels;
    if (ycbcr.empty() || ycbcr.type() != CV_8UC3 || seed.x < 0 || seed.y < 0 ||
        seed.x >= ycbcr.cols || seed.y >= ycbcr.rows)
        return pixels;
    const cv::Vec3b s = ycbcr.at<cv::Vec3b>(seed);
    auto similar = [&](const cv::Vec3b& c) {
        return std::abs(int(c[0]) - s[0]) <= tolerance.y &&
               std::abs(int(c[1]) - s[1]) <= tolerance.cb &&
               std::abs(int(c[2]) - s[2]) <= tolerance.cr;
    };
    std::vector<std::uint8_t> seen(std::size_t(ycbcr.rows) * std::size_t(ycbcr.cols), 0);
    std::vector<cv::Point> stack{seed};
    seen[std::size_t(seed.y) * std::size_t(ycbcr.cols) + std::size_t(seed.x)] = 1;
    while (!stack.empty()) {
        const cv::Point p = stack.back();
        stack.pop_back();
        pixels.push_back(p);
        for (const cv::Point d :
             {cv::Point(1, 0), cv::Point(-1, 0), cv::Point(0, 1), cv::Point(0, -1)}) {
            const cv::Point q = p + d;
            if (q.x < 0 || q.y < 0 || q.x >= ycbcr.cols || q.y >= ycbcr.rows)
                continue;
            std::uint8_t& mark =
                seen[std::size_t(q.y) * std::size_t(ycbcr.cols) + std::size_t(q.x)];
            if (mark || !similar(ycbcr.at<cv::Vec3b>(q)))
                continue;
            mark = 1;
            stack.push_back(q);
        }
    }
    return pixels;
}

std::vector<std::uint32_t> cellsOfPixels(const cv::Mat& ycbcr, const std::vector<cv::Point>& pixels,
                                         const Tolerance& tolerance)
{
    std::vector<std::uint32_t> cells;
    if (ycbcr.empty() || ycbcr.type() != CV_8UC3)
        return cells;
    for (const cv::Point& p : pixels) {
        if (p.x < 0 || p.y < 0 || p.x >= ycbcr.cols || p.y >= ycbcr.rows)
            continue;
        addBox(cells, ycbcr.at<cv::Vec3b>(p), tolerance);
    }
    sortUnique(cells);
    return cells;
}

Colour softMeet(Colour existing, Colour wanted)
{
    const auto meet = [&](Colour a, Colour b) {
        return (existing == a && wanted == b) || (existing == b && wanted == a);
    };
    if (meet(Colour::Pink, Colour::Orange))
        return Colour::PinkOrange;
    if (meet(Colour::Orange, Colour::Yellow))
        return Colour::YellowOrange;
    if (existing == Colour::PinkOrange && (wanted == Colour::Pink || wanted == Colour::Orange))
        return existing;
    if (existing == Colour::YellowOrange && (wanted == Colour::Orange || wanted == Colour::Yellow))
        return existing;
    return wanted;
}

std::vector<CellChange> changesTo(const ColourLut& lut, const std::vector<std::uint32_t>& cells,
                                  Colour colour, bool keep_others, bool soft)
{
    std::vector<CellChange> changes;
    for (const std::uint32_t cell : cells) {
        if (cell >= ColourLut::kCells)
            continue;
        const Colour before = lut.cell(cell);
        const Colour after = soft ? softMeet(before, colour) : colour;
        if (before == after || (keep_others && before != Colour::Unclassified))
            continue;
        changes.push_back({cell, before, after});
    }
    return changes;
}

std::array<std::size_t, kColourCount> cellsTakenByClass(const std::vector<CellChange>& changes)
{
    std::array<std::size_t, kColourCount> taken{};
    for (const CellChange& c : changes)
        if (c.before != Colour::Unclassified && std::size_t(c.before) < taken.size())
            ++taken[std::size_t(c.before)];
    return taken;
}

void applyChanges(ColourLut& lut, const std::vector<CellChange>& changes, bool forwards)
{
    if (forwards) {
        for (const CellChange& c : changes)
            lut.setCell(c.cell, c.after);
    } else {
        for (auto it = changes.rbegin(); it != changes.rend(); ++it)
            lut.setCell(it->cell, it->before);
    }
}

std::vector<std::size_t> cellsPerClass(const ColourLut& lut)
{
    std::vector<std::size_t> counts(kColourCount, 0);
    const std::uint8_t* cells = lut.data();
    for (std::size_t i = 0; i < ColourLut::kCells; ++i)
        if (cells[i] < kColourCount)
            ++counts[cells[i]];
    return counts;
}

} // namespace fieldsight

namespace fieldsight {

namespace {

int median(std::vector<int>& v)
{
    std::nth_element(v.begin(), v.begin() + std::ptrdiff_t(v.size() / 2), v.end());
    return v[v.size() / 2];
}

} // namespace

ColourShift estimateShift(const ColourLut& lut, Colour colour,
                          const std::vector<cv::Vec3b>& samples)
{
    std::array<std::vector<int>, 3> cells, pixels;
    for (std::uint32_t i = 0; i < ColourLut::kCells; ++i)
        if (lut.cell(i) == colour) {
            cells[0].push_back(int((i >> 14) & 127) * 2 + 1); // the cell's centre level
            cells[1].push_back(int((i >> 7) & 127) * 2 + 1);
            cells[2].push_back(int(i & 127) * 2 + 1);
        }
    if (cells[0].empty() || samples.empty())
        return {};
    for (const cv::Vec3b& p : samples)
        for (int c = 0; c < 3; ++c)
            pixels[std::size_t(c)].push_back(p[c]);
    return {median(pixels[0]) - median(cells[0]), median(pixels[1]) - median(cells[1]),
            median(pixels[2]) - median(cells[2])};
}

std::vector<CellChange> shiftChanges(const ColourLut& lut, const ColourShift& shift)
{
    // Whole cells: an odd shift rounds to the nearer cell.
    const auto cellsOf = [](int levels) { return int(std::lround(levels / 2.0)); };
    const int dy = cellsOf(shift.y), db = cellsOf(shift.cb), dr = cellsOf(shift.cr);
    std::vector<CellChange> changes;
    for (int y = 0; y < 128; ++y)
        for (int b = 0; b < 128; ++b)
            for (int r = 0; r < 128; ++r) {
                const int sy = y - dy, sb = b - db, sr = r - dr;
                const bool inside =
                    sy >= 0 && sy < 128 && sb >= 0 && sb < 128 && sr >= 0 && sr < 128;
                const Colour from = inside ? lut.cell(std::size_t((sy << 14) | (sb << 7) | sr))
                                           : Colour::Unclassified;
                const auto cell = std::uint32_t((y << 14) | (b << 7) | r);
                if (lut.cell(cell) != from)
                    changes.push_back({cell, lut.cell(cell), from});
            }
    return changes;
}

} // namespace fieldsight
