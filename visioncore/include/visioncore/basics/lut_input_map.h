// What a pixel seen under one light reads in a table made under another: the table's cell that
// each observed cell's colour falls in under the table's light, so a table follows the light
// without being rebuilt.
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <memory>

#include "visioncore/basics/ycbcr.h"

namespace fieldsight {

/// Maps an observed LUT cell (7-bit Y, Cb, Cr, as ColourLut::index) to the cell its colour had
/// under the table's light: the cell's centre through the 3x3 linear map of Y, Cb - 128, Cr - 128
/// that a von Kries change is, in 1/256 level steps, clamped and rounded down to a cell. A
/// channel the camera clipped says only that the light was at least that bright: a cell whose
/// R, G or B is at the clip keeps that channel as it is (the table saw it clipped too), and a
/// channel the division would take past 255 reads 255, as the table's light clipped it.
/// Immutable once made. A cell costs about twenty to forty operations, so a table remembers what
/// each cell read (ColourLut::setInputMap) instead of asking twice.
class LutInputMap
{
public:
    /// The map of a light whose R, G, B are `gain` times those of the table's light (von Kries):
    /// each observed pixel is divided by the gains, in BT.601 full range as ycbcr.h converts.
    /// Where the cell a pixel reads is unclassified, it reads through `then` instead (when
    /// given), and takes what it finds there if it is one of `then_classes` (bit i: Colour i): a
    /// light's level, which a table's cells are broad in and a view's content moves, can be
    /// followed only where it finds what the cautious map does not, and only for some classes.
    static LutInputMap forRgbGain(double r_gain, double g_gain, double b_gain,
                                  std::shared_ptr<const LutInputMap> then = nullptr,
                                  std::uint32_t then_classes = ~std::uint32_t(0));
    /// This map, reading through `then` next as forRgbGain's would: the same terms, not worked
    /// out again.
    LutInputMap withThen(std::shared_ptr<const LutInputMap> then,
                         std::uint32_t then_classes = ~std::uint32_t(0)) const
    {
        LutInputMap map = *this;
        map.m_then = std::move(then);
        map.m_then_classes = then_classes;
        return map;
    }
    /// The map an unclassified cell reads through next, or null.
    const LutInputMap* then() const { return m_then.get(); }
    /// Whether a cell may take `colour_id` from the next map.
    bool takesFromThen(std::uint8_t colour_id) const { return (m_then_classes >> colour_id) & 1; }

    /// The table's cell (as ColourLut::index) that an observed cell reads.
    std::size_t cellOf(std::size_t observed) const
    {
        if (m_identity)
            return observed;
        if (nearTheClip(observed))
            return clippedCellOf(observed);
        // Y', Cb' and Cr' side by side in one word: three terms, two additions.
        const std::uint64_t sum = m_terms[0][(observed >> 14) & 127] +
                                  m_terms[1][(observed >> 7) & 127] + m_terms[2][observed & 127];
        const auto cell = [sum](int field) {
            // (V + kBias) / 2 levels, to one of the 128 cells.
            return std::size_t(
                kCellOfHalf[(sum >> (field * kFieldBits + kFraction + 1)) & kHalfMask]);
        };
        return (cell(2) << 14) | (cell(1) << 7) | cell(0);
    }
    /// The table's cell that an observed pixel reads: the cell of the pixel's own cell.
    std::size_t index(std::uint8_t y, std::uint8_t cb, std::uint8_t cr) const;

    /// R, G or B at or above this is taken as clipped by the camera (noise and 4:2:2 chroma
    /// scatter a clipped 255 by a few levels).
    static constexpr double kClip = 250;

private:
    /// Whether the cell's centre has a channel at the clip, or one the gain takes past 255: its
    /// R, G, B in 1/512 levels (twice the centre, in 1/256, as rgbOfYcc), each field biased so
    /// that it reaches bit 20 exactly when the channel reaches that level (m_clip_terms): three
    /// terms, two additions and a mask.
    bool nearTheClip(std::size_t observed) const
    {
        return ((m_clip_terms[0][(observed >> 14) & 127] + m_clip_terms[1][(observed >> 7) & 127] +
                 m_clip_terms[2][observed & 127]) &
                kClipBits) != 0;
    }
    /// cellOf() for a cell near the clip, channel by channel in R, G, B.
    std::size_t clippedCellOf(std::size_t observed) const;

    static constexpr int kFraction = 8;   ///< fixed point: levels times 2^kFraction
    static constexpr int kFieldBits = 21; ///< per output channel in a term
    static constexpr int kTermBias = 512; ///< levels added to each term (clamped to +-512..1023)
    static constexpr int kBias = 3 * kTermBias;
    static constexpr std::uint64_t kHalfMask =
        (std::uint64_t(1) << (kFieldBits - kFraction - 1)) - 1;
    /// (V + kBias) / 2 levels to V's cell, clamped to 0..127.
    static constexpr std::array<std::uint8_t, kHalfMask + 1> kCellOfHalf = [] {
        std::array<std::uint8_t, kHalfMask + 1> cells{};
        for (std::size_t half = 0; half < cells.size(); ++half)
            cells[half] = std::uint8_t(std::clamp(int(half) - kBias / 2, 0, 127));
        return cells;
    }();

    /// By input channel (Y, Cb, Cr) and its 7-bit cell: what the cell's centre adds to Cr' (bits
    /// 0-20), Cb' (21-41) and Y' (42-62), each in fixed point plus kTermBias levels (Cb' and Cr'
    /// with their 128 in the Y term), so a cell's map is the sum of three words.
    std::array<std::array<std::uint64_t, 128>, 3> m_terms{};
    std::array<double, 3> m_gain{1, 1, 1};
    /// The gains are all 1 (a light whose colour is the table's, its level in the next map):
    /// every cell reads itself, as the terms would give it (checked cell by cell in a test).
    bool m_identity = false;
    std::shared_ptr<const LutInputMap> m_then;
    std::uint32_t m_then_classes = ~std::uint32_t(0);
    /// By input channel and its 7-bit cell: what the cell's centre adds to R (bits 0-20), G
    /// (21-41) and B (42-62) in 1/512 levels, with biases that keep every term and sum within its
    /// field and put a channel's bit 20 at the level from which a cell goes through
    /// clippedCellOf (the clip, or where the division passes 255).
    std::array<std::array<std::uint64_t, 128>, 3> m_clip_terms{};
    static constexpr std::uint64_t kClipBits =
        (std::uint64_t(1) << 20) | (std::uint64_t(1) << 41) | (std::uint64_t(1) << 62);
};

} // namespace fieldsight
