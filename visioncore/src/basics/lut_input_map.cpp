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

// R, G, B from Y, Cb - 128, Cr - 128 and back (BT.601 full range, as ycbcr.h).
// clang-format off
constexpr Matrix kToRgb{1, 0,         1.402,
                        1, -0.344136, -0.714136,
                        1, 1.772,     0};
constexpr Matrix kToYcbcr{0.299,     0.587,     0.114,
                          -0.168736, -0.331264, 0.5,
                          0.5,       -0.418688, -0.081312};
// clang-format on

std::array<double, 3> times(const Matrix& a, const std::array<double, 3>& v) // a v
{
    std::array<double, 3> p{};
    for (std::size_t r = 0; r < 3; ++r)
        for (std::size_t k = 0; k < 3; ++k)
            p[r] += a[3 * r + k] * v[k];
    return p;
}

/// The R, G, B of an observed cell's centre.
std::array<double, 3> centreRgb(std::size_t observed)
{
    const std::array<double, 3> centre{double((observed >> 14) & 127) * 2 + 0.5,
                                       double((observed >> 7) & 127) * 2 + 0.5 - 128,
                                       double(observed & 127) * 2 + 0.5 - 128};
    return times(kToRgb, centre);
}

/// LutInputMap::m_clip_terms for `gain`: rgbOfYcc of twice a cell's centre in 1/256 levels, term
/// by term (exact: each of its products is a multiple of 256 before the shift).
std::array<std::array<std::uint64_t, 128>, 3> clipTerms(const std::array<double, 3>& gain)
{
    // The most negative a Cb or Cr term can add to R, G, B, added back so that no field borrows.
    constexpr std::array<std::int64_t, 3> kCbLow{0, 88 * 253, 454 * 255};
    constexpr std::array<std::int64_t, 3> kCrLow{359 * 255, 183 * 253, 0};
    constexpr std::int64_t kTop = std::int64_t(1) << 20;
    std::array<std::array<std::uint64_t, 128>, 3> terms{};
    const auto pack = [](const std::array<std::int64_t, 3>& rgb) {
        std::uint64_t word = 0;
        for (std::size_t c = 0; c < 3; ++c)
            word |= std::uint64_t(rgb[c]) << (21 * c);
        return word;
    };
    std::array<std::int64_t, 3> y_bias{};
    for (std::size_t c = 0; c < 3; ++c)
        y_bias[c] = kTop - kCbLow[c] - kCrLow[c] -
                    std::int64_t(std::floor(std::min(LutInputMap::kClip, 255.0 * gain[c]) * 512));
    for (int cell = 0; cell < 128; ++cell) {
        const std::int64_t v = cell * 4 + 1; // twice the centre, in levels
        const std::array<std::int64_t, 3> y{256 * v + y_bias[0], 256 * v + y_bias[1],
                                            256 * v + y_bias[2]};
        const std::int64_t chroma = v - 256;
        terms[0][std::size_t(cell)] = pack(y);
        terms[1][std::size_t(cell)] = pack({0, -88 * chroma + kCbLow[1], 454 * chroma + kCbLow[2]});
        terms[2][std::size_t(cell)] =
            pack({359 * chroma + kCrLow[0], -183 * chroma + kCrLow[1], 0});
    }
    return terms;
}

} // namespace

LutInputMap LutInputMap::forRgbGain(double r_gain, double g_gain, double b_gain,
                                    std::shared_ptr<const LutInputMap> then,
                                    std::uint32_t then_classes)
{
    // The map is to_ycbcr * diag(1 / gain) * to_rgb.
    const Matrix divide{1 / r_gain, 0, 0, 0, 1 / g_gain, 0, 0, 0, 1 / b_gain};
    const Matrix m = times(kToYcbcr, times(divide, kToRgb));
    LutInputMap map;
    map.m_gain = {r_gain, g_gain, b_gain};
    map.m_then = std::move(then);
    map.m_then_classes = then_classes;
    map.m_clip_terms = clipTerms(map.m_gain);
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
                word |= std::uint64_t(std::int64_t(term * kOne + 0.5)) << ((2 - out) * kFieldBits);
            }
            map.m_terms[in][cell] = word;
        }
    return map;
}

std::size_t LutInputMap::clippedCellOf(std::size_t observed) const
{
    std::array<double, 3> rgb = centreRgb(observed);
    for (std::size_t c = 0; c < 3; ++c)
        if (rgb[c] < kClip) // a clipped channel stays; the table's light clips at 255 too
            rgb[c] = std::min(255.0, rgb[c] / m_gain[c]);
    const std::array<double, 3> mapped = times(kToYcbcr, rgb);
    const auto cell = [](double v) {
        return std::size_t(std::clamp(int(std::floor(v / 2)), 0, 127));
    };
    return (cell(mapped[0]) << 14) | (cell(mapped[1] + 128) << 7) | cell(mapped[2] + 128);
}

std::size_t LutInputMap::index(std::uint8_t y, std::uint8_t cb, std::uint8_t cr) const
{
    return cellOf(ColourLut::index(y, cb, cr));
}

} // namespace fieldsight
