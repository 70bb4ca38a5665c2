#include "visioncore/services/lut_compare.h"

#include <algorithm>
#include <bit>

namespace fieldsight {

CellMask CellMask::of(const std::vector<std::uint32_t>& cells)
{
    CellMask mask;
    for (std::uint32_t cell : cells)
        if (cell < ColourLut::kCells)
            mask.set(cell);
    return mask;
}

CellMask CellMask::of(const std::vector<CellChange>& changes)
{
    CellMask mask;
    for (const CellChange& change : changes)
        if (change.cell < ColourLut::kCells && change.before != change.after)
            mask.set(change.cell);
    return mask;
}

CellMask CellMask::differences(const ColourLut& a, const ColourLut& b)
{
    CellMask mask;
    const std::uint8_t* pa = a.data();
    const std::uint8_t* pb = b.data();
    for (std::size_t word = 0; word < mask.m_bits.size(); ++word) {
        std::uint64_t bits = 0;
        const std::size_t base = word * 64;
        for (std::size_t i = 0; i < 64; ++i)
            bits |= std::uint64_t(pa[base + i] != pb[base + i]) << i;
        mask.m_bits[word] = bits;
    }
    return mask;
}

std::size_t CellMask::count() const
{
    std::size_t n = 0;
    for (std::uint64_t word : m_bits)
        n += std::size_t(std::popcount(word));
    return n;
}

CellMask& CellMask::operator|=(const CellMask& other)
{
    for (std::size_t i = 0; i < m_bits.size(); ++i)
        m_bits[i] |= other.m_bits[i];
    return *this;
}

PixelTallier::PixelTallier(const ColourLut& lut, const CellMask& mask)
    : m_flags(ColourLut::kCells / 4, 0)
{
    const std::uint8_t* cells = lut.data();
    for (std::uint32_t cell = 0; cell < ColourLut::kCells; ++cell) {
        const unsigned f = unsigned(mask.test(cell)) |
                           unsigned(cells[cell] == std::uint8_t(Colour::Unclassified)) << 1;
        m_flags[cell >> 2] |= std::uint8_t(f << ((cell & 3) * 2));
    }
}

PixelTally PixelTallier::operator()(const cv::Mat& ycbcr) const
{
    PixelTally tally;
    if (ycbcr.type() != CV_8UC3)
        return tally;
    std::size_t counts[4] = {0, 0, 0, 0};
    const std::uint8_t* flags = m_flags.data();
    for (int row = 0; row < ycbcr.rows; ++row) {
        const std::uint8_t* px = ycbcr.ptr<std::uint8_t>(row);
        for (int col = 0; col < ycbcr.cols; ++col, px += 3) {
            const auto cell = std::uint32_t(ColourLut::index(px[0], px[1], px[2]));
            ++counts[(flags[cell >> 2] >> ((cell & 3) * 2)) & 3];
        }
    }
    tally.in_mask = counts[1] + counts[3];
    tally.unclassified = counts[2] + counts[3];
    tally.pixels = std::size_t(ycbcr.rows) * std::size_t(ycbcr.cols);
    return tally;
}

PixelTally tallyThroughMap(const ColourLut* before, const ColourLut& after, const cv::Mat& ycbcr)
{
    PixelTally tally;
    if (ycbcr.type() != CV_8UC3)
        return tally;
    std::vector<std::uint8_t> a(std::size_t(ycbcr.cols));
    std::vector<std::uint8_t> b(std::size_t(ycbcr.cols));
    for (int row = 0; row < ycbcr.rows; ++row) {
        const std::uint8_t* px = ycbcr.ptr<std::uint8_t>(row);
        after.classifyRun(px, 3, ycbcr.cols, a.data());
        if (before)
            before->classifyRun(px, 3, ycbcr.cols, b.data());
        for (std::size_t col = 0; col < a.size(); ++col) {
            tally.unclassified += a[col] == std::uint8_t(Colour::Unclassified);
            tally.in_mask += before && a[col] != b[col];
        }
    }
    tally.pixels = std::size_t(ycbcr.rows) * std::size_t(ycbcr.cols);
    return tally;
}

cv::Mat pixelsIn(const cv::Mat& ycbcr, const CellMask& mask)
{
    cv::Mat out(ycbcr.rows, ycbcr.cols, CV_8U, cv::Scalar(0));
    if (ycbcr.type() != CV_8UC3)
        return out;
    for (int row = 0; row < ycbcr.rows; ++row) {
        const std::uint8_t* px = ycbcr.ptr<std::uint8_t>(row);
        std::uint8_t* o = out.ptr<std::uint8_t>(row);
        for (int col = 0; col < ycbcr.cols; ++col, px += 3)
            o[col] = mask.test(px[0], px[1], px[2]) ? 255 : 0;
    }
    return out;
}

LutDiff::PairCounts LutDiff::pairCounts() const
{
    PairCounts counts{};
    for (const CellChange& change : cells)
        ++counts[std::size_t(change.before)][std::size_t(change.after)];
    return counts;
}

LutDiff diffLuts(const ColourLut& first, const ColourLut& second)
{
    LutDiff diff;
    const std::uint8_t* a = first.data();
    const std::uint8_t* b = second.data();
    for (std::size_t i = 0; i < ColourLut::kCells; ++i)
        if (a[i] != b[i])
            diff.cells.push_back({std::uint32_t(i), Colour(a[i]), Colour(b[i])});
    return diff;
}

std::vector<CellChange> mergeChanges(const ColourLut& into, const ColourLut& from,
                                     const std::vector<Colour>& classes, bool keep_others)
{
    std::array<bool, kColourCount> wanted{};
    for (Colour c : classes)
        if (std::size_t(c) < wanted.size())
            wanted[std::size_t(c)] = true;
    std::vector<CellChange> changes;
    const std::uint8_t* a = into.data();
    const std::uint8_t* b = from.data();
    for (std::size_t i = 0; i < ColourLut::kCells; ++i) {
        if (a[i] == b[i] || b[i] >= wanted.size() || !wanted[b[i]])
            continue;
        if (keep_others && a[i] != std::uint8_t(Colour::Unclassified))
            continue;
        changes.push_back({std::uint32_t(i), Colour(a[i]), Colour(b[i])});
    }
    return changes;
}

std::size_t conflictsIn(const std::vector<CellChange>& changes)
{
    return std::size_t(std::count_if(changes.begin(), changes.end(), [](const CellChange& c) {
        return c.before != Colour::Unclassified && c.before != c.after;
    }));
}

} // namespace fieldsight
