// Comparing colour tables: which cells differ between two LUTs (by class pair), merging one table
// into another by class, and a one-bit-per-cell set for finding the pixels of a set of cells in a
// frame (the whole-stream effect of an edit, the UV view's selection shown in the image).
#pragma once

#include "visioncore/basics/colour_lut.h"
#include "visioncore/services/lut_editing.h"

#include <opencv2/core/mat.hpp>

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace fieldsight {

/// A set of LUT cells, one bit each (256 KiB, so a lookup per pixel stays in the cache).
class CellMask
{
public:
    CellMask() : m_bits(ColourLut::kCells / 64, 0) {}
    static CellMask of(const std::vector<std::uint32_t>& cells);
    static CellMask of(const std::vector<CellChange>& changes);
    /// The cells whose class differs between `a` and `b`.
    static CellMask differences(const ColourLut& a, const ColourLut& b);

    void set(std::uint32_t cell) { m_bits[cell >> 6] |= std::uint64_t(1) << (cell & 63); }
    bool test(std::uint32_t cell) const { return (m_bits[cell >> 6] >> (cell & 63)) & 1; }
    bool test(std::uint8_t y, std::uint8_t cb, std::uint8_t cr) const
    {
        return test(std::uint32_t(ColourLut::index(y, cb, cr)));
    }
    std::size_t count() const;
    bool empty() const { return count() == 0; }
    CellMask& operator|=(const CellMask& other);

private:
    std::vector<std::uint64_t> m_bits;
};

/// Pixels of a frame counted in one pass.
struct PixelTally
{
    std::size_t in_mask = 0;      ///< whose cell is in the mask
    std::size_t unclassified = 0; ///< that the table leaves unclassified
    std::size_t pixels = 0;
};

/// Tallies frames' pixels against a mask and a table with one lookup a pixel, in a 512 KiB table
/// of two bits a cell that mostly stays in the cache. Made once, used on many frames.
class PixelTallier
{
public:
    PixelTallier(const ColourLut& lut, const CellMask& mask);
    /// Of a CV_8UC3 Y, Cb, Cr frame.
    PixelTally operator()(const cv::Mat& ycbcr) const;

private:
    std::vector<std::uint8_t> m_flags;
};
/// A frame's pixels as two tables read them through the same input map (a light the tables
/// follow): `in_mask` counts the pixels the two read as different classes, `unclassified` those
/// `after` leaves unclassified. `before` may be null (nothing is compared). Two memo lookups a
/// pixel: for frames PixelTallier cannot read, whose pixels go through a map first.
PixelTally tallyThroughMap(const ColourLut* before, const ColourLut& after, const cv::Mat& ycbcr);
/// A CV_8U image, 255 where the frame's pixel falls in a cell of `mask`, else 0.
cv::Mat pixelsIn(const cv::Mat& ycbcr, const CellMask& mask);

/// The cells that differ between two tables.
struct LutDiff
{
    /// Every differing cell, ascending: `before` is the first table's class, `after` the
    /// second's (so applyChanges() turns the first into the second).
    std::vector<CellChange> cells;

    /// How many cells go from class `from` (first table) to class `to` (second table).
    using PairCounts = std::array<std::array<std::size_t, kColourCount>, kColourCount>;
    PairCounts pairCounts() const;
};

LutDiff diffLuts(const ColourLut& first, const ColourLut& second);

/// The changes that copy the cells `from` gives one of `classes` into `into`. With
/// `keep_others`, a cell `into` already gives another class keeps it (a conflict left alone).
std::vector<CellChange> mergeChanges(const ColourLut& into, const ColourLut& from,
                                     const std::vector<Colour>& classes, bool keep_others = false);

/// The cells of a merge that take a cell from another class: what a preview warns about.
std::size_t conflictsIn(const std::vector<CellChange>& changes);

} // namespace fieldsight
