// What a pixel seen under one light reads in a table made under another: per-channel index tables
// in front of the colour LUT, so a table follows the light without being rebuilt.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>

namespace fieldsight {

/// Maps an observed Y, Cb, Cr to the LUT cell it reads. Y maps to the Y part of the cell index
/// alone; Cb and Cr each map to their part within one of kBands bands of Y, so a chroma shift can
/// grow with brightness as a white-balance change does. The cross terms of a full colour
/// transform (Cr on Cb', chroma on Y') are left out: small for the gains a light drifts by.
/// Immutable once made; shared between tables through std::shared_ptr<const LutInputMap>.
class LutInputMap
{
public:
    static constexpr int kBandShift = 4;             ///< Y >> kBandShift is the band
    static constexpr int kBands = 256 >> kBandShift; ///< 16 bands of 16 Y levels

    /// The map of a light whose R, G, B are `gain` times those of the table's light (von Kries):
    /// each observed pixel is divided by the gains, in BT.601 full range as ycbcr.h converts.
    static LutInputMap forRgbGain(double r_gain, double g_gain, double b_gain);

    /// The LUT cell index (as ColourLut::index) that an observed pixel reads.
    std::size_t index(std::uint8_t y, std::uint8_t cb, std::uint8_t cr) const
    {
        const std::size_t band = std::size_t(y >> kBandShift);
        return m_y[y] | m_cb[band][cb] | m_cr[band][cr];
    }

private:
    std::array<std::uint32_t, 256> m_y{};                      ///< (Y' >> 1) << 14
    std::array<std::array<std::uint16_t, 256>, kBands> m_cb{}; ///< (Cb' >> 1) << 7
    std::array<std::array<std::uint16_t, 256>, kBands> m_cr{}; ///< Cr' >> 1
};

} // namespace fieldsight
