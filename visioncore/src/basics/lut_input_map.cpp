// The input map of a von Kries light change, in BT.601 full range as the core's pixels are.
#include "visioncore/basics/lut_input_map.h"

#include "visioncore/basics/colour_lut.h"

#include <algorithm>
#include <cmath>

namespace fieldsight {

namespace {

using Matrix = std::array<double, 9>;

Matrix times(const Matrix& a, const Matrix& b)
{
    Matrix p{};
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c)
            for (int k = 0; k < 3; ++k)
                p[std::size_t(3 * r + c)] += a[std::size_t(3 * r + k)] * b[std::size_t(3 * k + c)];
    return p;
}

} // namespace

LutInputMap LutInputMap::forRgbGain(double r_gain, double g_gain, double b_gain)
{
    // R, G, B from Y, Cb - 128, Cr - 128 and back (BT.601 full range, as ycbcr.h): the map is
    // to_ycbcr * diag(1 / gain) * to_rgb.
    // clang-format off
    constexpr Matrix kToRgb{1, 0,         1.402,
                            1, -0.344136, -0.714136,
                            1, 1.772,     0};
    constexpr Matrix kToYcbcr{0.299,     0.587,     0.114,
                              -0.168736, -0.331264, 0.5,
                              0.5,       -0.418688, -0.081312};
    // clang-format on
    const Matrix divide{1 / r_gain, 0, 0, 0, 1 / g_gain, 0, 0, 0, 1 / b_gain};
    const Matrix m = times(kToYcbcr, times(divide, kToRgb));
    LutInputMap map;
    constexpr double kOne = double(1 << kFraction);
    for (std::size_t in = 0; in < 3; ++in)
        for (std::size_t cell = 0; cell < 128; ++cell) {
            // The centre of the cell's two levels, Cb and Cr about 128.
            const double v = double(cell) * 2 + 0.5 - (in == 0 ? 0.0 : 128.0);
            std::uint64_t word = 0;
            for (std::size_t out = 0; out < 3; ++out) {
                const double offset = in == 0 && out > 0 ? 128.0 : 0.0;
                const double term = std::clamp(m[3 * out + in] * v + offset, -double(kTermBias),
                                               2.0 * kTermBias - 1) +
                                    kTermBias;
                // Non-negative, so rounding is adding a half; Y' in the top field.
                word |= std::uint64_t(term * kOne + 0.5) << ((2 - out) * kFieldBits);
            }
            map.m_terms[in][cell] = word;
        }
    return map;
}

std::size_t LutInputMap::index(std::uint8_t y, std::uint8_t cb, std::uint8_t cr) const
{
    return cellOf(ColourLut::index(y, cb, cr));
}

} // namespace fieldsight
