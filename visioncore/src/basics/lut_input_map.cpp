// The input map of a von Kries light change, in BT.601 full range as the core's pixels are.
#include "visioncore/basics/lut_input_map.h"

#include <algorithm>
#include <cmath>

namespace fieldsight {

namespace {

/// Rounds to the nearest whole 8-bit level, clamped (no library call: a map is made often).
std::uint32_t toByte(double v)
{
    return v <= 0 ? 0u : v >= 255 ? 255u : std::uint32_t(v + 0.5);
}

} // namespace

LutInputMap LutInputMap::forRgbGain(double r_gain, double g_gain, double b_gain)
{
    const double ir = 1.0 / r_gain;
    const double ig = 1.0 / g_gain;
    const double ib = 1.0 / b_gain;
    LutInputMap m;
    // Y' = level * Y + a * (Cb - 128) + b * (Cr - 128), exactly, for R, G, B divided by the gains;
    // the chroma terms become offsets of the observed Y, in whole levels.
    const double level = 0.299 * ir + 0.587 * ig + 0.114 * ib;
    const double a = -0.587 * 0.344136 * ig + 0.114 * 1.772 * ib;
    const double b = 0.299 * 1.402 * ir - 0.587 * 0.714136 * ig;
    for (std::size_t i = 0; i < m.m_y.size(); ++i)
        m.m_y[i] = (toByte((double(i) - 2 * kOffsetBias) * level) >> 1) << 14;
    // The Y offsets and the band tables are indexed by the chroma read, v = index - kCrossBias.
    constexpr int kWidth = 256 + 2 * kCrossBias;
    std::array<std::uint32_t, kWidth> cb_offset{};
    std::array<std::uint32_t, kWidth> cr_offset{};
    for (int i = 0; i < kWidth; ++i) {
        const int v = i - kCrossBias;
        const auto offset = [&](double coefficient) {
            const double dy = std::clamp(coefficient * (v - 128.0) / level, -double(kOffsetBias),
                                         double(kOffsetBias - 1));
            return std::uint32_t(int(std::floor(dy + 0.5)) + kOffsetBias) << 16;
        };
        cb_offset[std::size_t(i)] = offset(a);
        cr_offset[std::size_t(i)] = offset(b);
    }
    // Cb' and Cr' are linear in the observed Cb and Cr within a band: observed (yc, Cb, Cr) back
    // to R, G, B, divided by the gains, and Cb', Cr' of that. Each channel's own term is in its
    // table; the other's (Cr on Cb', Cb on Cr') shifts the read, in units of the channel read.
    const double cb_slope = 0.331264 * 0.344136 * ig + 0.5 * 1.772 * ib;
    const double cr_slope = 0.5 * 1.402 * ir + 0.418688 * 0.714136 * ig;
    const double cb_per_cr = (-0.168736 * 1.402 * ir + 0.331264 * 0.714136 * ig) / cb_slope;
    const double cr_per_cb = (0.418688 * 0.344136 * ig - 0.081312 * 1.772 * ib) / cr_slope;
    for (int c = 0; c < 256; ++c) {
        const auto shift = [&](double per) {
            const double d =
                std::clamp(per * (c - 128.0), -double(kCrossBias), double(kCrossBias - 1));
            return std::uint32_t(int(std::floor(d + 0.5)) + kCrossBias);
        };
        m.m_cross[std::size_t(c)] = shift(cb_per_cr) | (shift(cr_per_cb) << 16);
    }
    const double cb_per_y = -0.168736 * ir - 0.331264 * ig + 0.5 * ib;
    const double cr_per_y = 0.5 * ir - 0.418688 * ig - 0.081312 * ib;
    for (int band = 0; band < kBands; ++band) {
        const double yc = band * (1 << kBandShift) + ((1 << kBandShift) - 1) / 2.0;
        const double cb0 = 128.0 + cb_per_y * yc - 128.0 * cb_slope;
        const double cr0 = 128.0 + cr_per_y * yc - 128.0 * cr_slope;
        auto& cbs = m.m_cb[std::size_t(band)];
        auto& crs = m.m_cr[std::size_t(band)];
        for (int i = 0; i < kWidth; ++i) {
            const double v = i - kCrossBias;
            cbs[std::size_t(i)] =
                cb_offset[std::size_t(i)] | ((toByte(cb0 + cb_slope * v) >> 1) << 7);
            crs[std::size_t(i)] = cr_offset[std::size_t(i)] | (toByte(cr0 + cr_slope * v) >> 1);
        }
    }
    return m;
}

} // namespace fieldsight
