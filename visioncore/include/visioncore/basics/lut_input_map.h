// What a pixel seen under one light reads in a table made under another: per-channel index tables
// in front of the colour LUT, so a table follows the light without being rebuilt.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>

namespace fieldsight {

/// Maps an observed Y, Cb, Cr to the LUT cell it reads. Y' is exact for a change of R, G, B gains
/// (Y plus an offset from Cb and one from Cr, scaled); Cb' and Cr' come from their own channel,
/// shifted by the other's cross term, within one of kBands bands of Y, so a chroma shift can grow
/// with brightness as a white-balance change does. Immutable once made; shared between tables
/// through std::shared_ptr<const LutInputMap>.
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
        // Each chroma read shifted by the other's cross term, so a saturated colour (a ball) lands
        // where the table's light put it.
        const std::uint32_t c = m_cb[band][cb + (m_cross[cr] & 0xFFFF)];
        const std::uint32_t r = m_cr[band][cr + (m_cross[cb] >> 16)];
        return m_y[std::size_t(y) + (c >> 16) + (r >> 16)] | (c & 0xFFFF) | (r & 0xFFFF);
    }

private:
    static constexpr int kOffsetBias = 64; ///< a chroma's Y offset is stored plus this
    static constexpr int kCrossBias = 32;  ///< a chroma's shift of the other is stored plus this

    /// (Y' >> 1) << 14 of the observed Y + the two offsets (each biased by kOffsetBias).
    std::array<std::uint32_t, 256 + 4 * kOffsetBias> m_y{};
    /// Low 16 bits: the shift of the Cb read by this Cr; high: of the Cr read by this Cb (each
    /// plus kCrossBias).
    std::array<std::uint32_t, 256> m_cross{};
    /// By band and Cb + shift: low 16 bits (Cb' >> 1) << 7, high bits Cb's Y offset + kOffsetBias.
    std::array<std::array<std::uint32_t, 256 + 2 * kCrossBias>, kBands> m_cb{};
    /// By band and Cr + shift: low 16 bits Cr' >> 1, high bits Cr's Y offset + kOffsetBias.
    std::array<std::array<std::uint32_t, 256 + 2 * kCrossBias>, kBands> m_cr{};
};

} // namespace fieldsight
