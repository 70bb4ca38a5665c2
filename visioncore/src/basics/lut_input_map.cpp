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
    // Y' = level * Y + a * (Cb - 128) + b * (Cr - 128), exactly, for R, G, B divided by the gains;
    // the chroma terms become offsets of the observed Y, in whole levels.
    const double level = 0.299 * ir + 0.587 * ig + 0.114 * ib;
    const double a = -0.587 * 0.344136 * ig + 0.114 * 1.772 * ib;
    const double b = 0.299 * 1.402 * ir - 0.587 * 0.714136 * ig;
    const auto offset = [&](double coefficient, int c) {
        const long dy = std::lround(coefficient * (c - 128.0) / level);
        return std::uint32_t(std::clamp(dy, long(-kOffsetBias), long(kOffsetBias - 1)) +
                             kOffsetBias);
    };
    for (std::size_t i = 0; i < m.m_y.size(); ++i) {
        const double y = double(i) - 2 * kOffsetBias;
        m.m_y[i] = std::uint32_t(toByte(y * level) >> 1) << 14;
    }
    for (int band = 0; band < kBands; ++band) {
        const double yc = band * (1 << kBandShift) + ((1 << kBandShift) - 1) / 2.0;
        for (int c = 0; c < 256; ++c) {
            const double d = c - 128.0;
            // Observed (yc, c, 128) back to R, G, B, divided by the gains, and Cb' of that.
            double r = yc * ir;
            double g = (yc - 0.344136 * d) * ig;
            double bl = (yc + 1.772 * d) * ib;
            const double cb = 128.0 - 0.168736 * r - 0.331264 * g + 0.5 * bl;
            // Observed (yc, 128, c), and Cr' of that.
            r = (yc + 1.402 * d) * ir;
            g = (yc - 0.714136 * d) * ig;
            bl = yc * ib;
            const double cr = 128.0 + 0.5 * r - 0.418688 * g - 0.081312 * bl;
            m.m_cb[std::size_t(band)][std::size_t(c)] =
                (offset(a, c) << 16) | std::uint32_t((toByte(cb) >> 1) << 7);
            m.m_cr[std::size_t(band)][std::size_t(c)] =
                (offset(b, c) << 16) | std::uint32_t(toByte(cr) >> 1);
        }
    }
    return m;
}

} // namespace fieldsight
