// The input map of a von Kries light change, in BT.601 full range as the core's pixels are.
#include "visioncore/basics/lut_input_map.h"

#include <algorithm>
#include <cmath>

namespace fieldsight {

namespace {

std::uint8_t toByte(double v)
{
    return std::uint8_t(std::clamp(std::lround(v), 0L, 255L));
}

} // namespace

LutInputMap LutInputMap::forRgbGain(double r_gain, double g_gain, double b_gain)
{
    const double ir = 1.0 / r_gain;
    const double ig = 1.0 / g_gain;
    const double ib = 1.0 / b_gain;
    LutInputMap m;
    // A grey pixel keeps Cb = Cr = 128 only when the gains are equal; its level scales by the
    // luma-weighted inverse gain.
    const double level = 0.299 * ir + 0.587 * ig + 0.114 * ib;
    for (int y = 0; y < 256; ++y)
        m.m_y[std::size_t(y)] = std::uint32_t(toByte(y * level) >> 1) << 14;
    for (int band = 0; band < kBands; ++band) {
        const double yc = band * (1 << kBandShift) + ((1 << kBandShift) - 1) / 2.0;
        for (int c = 0; c < 256; ++c) {
            const double d = c - 128.0;
            // Observed (yc, c, 128) back to R, G, B, divided by the gains, and Cb' of that.
            double r = yc * ir;
            double g = (yc - 0.344136 * d) * ig;
            double b = (yc + 1.772 * d) * ib;
            const double cb = 128.0 - 0.168736 * r - 0.331264 * g + 0.5 * b;
            // Observed (yc, 128, c), and Cr' of that.
            r = (yc + 1.402 * d) * ir;
            g = (yc - 0.714136 * d) * ig;
            b = yc * ib;
            const double cr = 128.0 + 0.5 * r - 0.418688 * g - 0.081312 * b;
            m.m_cb[std::size_t(band)][std::size_t(c)] = std::uint16_t((toByte(cb) >> 1) << 7);
            m.m_cr[std::size_t(band)][std::size_t(c)] = std::uint16_t(toByte(cr) >> 1);
        }
    }
    return m;
}

} // namespace fieldsight
