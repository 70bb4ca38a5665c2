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

/// Each input channel's share of R, G, B by cell: rgbOfYcc of twice the cell's centre in 1/256
/// levels, input channel by input channel (exact and so additive: each of its products is a
/// multiple of 256 before the shift), and the most negative share each adds to R, G and B.
struct ClipShares
{
    std::array<std::array<std::array<int, 3>, 128>, 3> share{};
    std::array<std::array<std::int64_t, 3>, 3> lowest{};

    ClipShares()
    {
        for (int cell = 0; cell < 128; ++cell) {
            const int v = cell * 4 + 1; // twice the centre, in levels
            const int chroma = (v - 256) << 8;
            share[0][std::size_t(cell)] = rgbOfYcc(v << 8, 0, 0);
            share[1][std::size_t(cell)] = rgbOfYcc(0, chroma, 0);
            share[2][std::size_t(cell)] = rgbOfYcc(0, 0, chroma);
            for (std::size_t in = 0; in < 3; ++in)
                for (std::size_t c = 0; c < 3; ++c)
                    lowest[in][c] =
                        std::min<std::int64_t>(lowest[in][c], share[in][std::size_t(cell)][c]);
        }
    }
};

using Terms = std::array<std::array<std::uint64_t, 128>, 3>;

/// LutInputMap::m_clip_terms for the gains of the table's own light less each channel's level
/// where the slow path starts: the shares, the chroma ones raised by their lowest so that no field
/// borrows, the Y one lowered by both. The same for every map, so worked out once.
struct ClipTermBase
{
    Terms terms{};

    ClipTermBase()
    {
        static const ClipShares shares;
        constexpr std::int64_t kTop = std::int64_t(1) << 20;
        std::array<std::array<std::int64_t, 3>, 3> bias{};
        for (std::size_t c = 0; c < 3; ++c) {
            bias[1][c] = -shares.lowest[1][c];
            bias[2][c] = -shares.lowest[2][c];
            bias[0][c] = kTop - bias[1][c] - bias[2][c];
        }
        for (std::size_t in = 0; in < 3; ++in)
            for (std::size_t cell = 0; cell < 128; ++cell) {
                std::uint64_t word = 0;
                for (std::size_t c = 0; c < 3; ++c)
                    word += std::uint64_t(shares.share[in][cell][c] + bias[in][c]) << (21 * c);
                terms[in][cell] = word;
            }
    }
};

/// LutInputMap::m_clip_terms for `gain`: the base with the Y terms lowered by the level, per
/// channel, where the slow path starts (the words are sums of their fields, so lowering every
/// field of a word is one subtraction).
Terms clipTerms(const std::array<double, 3>& gain)
{
    static const ClipTermBase base;
    std::uint64_t start = 0;
    for (std::size_t c = 0; c < 3; ++c)
        start += std::uint64_t(std::floor(std::min(LutInputMap::kClip, 255.0 * gain[c]) * 512))
                 << (21 * c);
    Terms terms = base.terms;
    for (std::uint64_t& word : terms[0])
        word -= start;
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
    map.m_identity = r_gain == 1 && g_gain == 1 && b_gain == 1;
    map.m_then = std::move(then);
    map.m_then_classes = then_classes;
    map.m_clip_terms = clipTerms(map.m_gain);
    constexpr double kOne = double(1 << kFraction);
    // Input channel by output channel, the 128 cells in loops of their own.
    for (std::size_t in = 0; in < 3; ++in) {
        std::array<std::uint64_t, 128>& words = map.m_terms[in];
        words.fill(0);
        const double from = in == 0 ? 0.5 : 0.5 - 128.0;
        for (std::size_t out = 0; out < 3; ++out) {
            const double factor = m[3 * out + in];
            const double offset = in == 0 && out > 0 ? 128.0 : 0.0;
            const int shift = int(2 - out) * kFieldBits; // Y' in the top field
            // The centre of the cell's two levels, Cb and Cr about 128, and its term before the
            // clamp: monotonic in the cell (rounding is), so when neither end is clamped no cell
            // is, and the loop without the clamp vectorises.
            const auto unclamped = [&](std::size_t cell) {
                return factor * (double(int(cell)) * 2 + from) + offset;
            };
            const double lo = -double(kTermBias);
            const double hi = 2.0 * kTermBias - 1;
            const bool inside = std::min(unclamped(0), unclamped(127)) >= lo &&
                                std::max(unclamped(0), unclamped(127)) <= hi;
            // Non-negative and under 2^19, so rounding is adding a half.
            std::array<std::int32_t, 128> field;
            if (inside) {
                for (std::size_t cell = 0; cell < 128; ++cell)
                    field[cell] = std::int32_t((unclamped(cell) + kTermBias) * kOne + 0.5);
            } else {
                for (std::size_t cell = 0; cell < 128; ++cell)
                    field[cell] = std::int32_t(
                        (std::clamp(unclamped(cell), lo, hi) + kTermBias) * kOne + 0.5);
            }
            for (std::size_t cell = 0; cell < 128; ++cell)
                words[cell] |= std::uint64_t(std::uint32_t(field[cell])) << shift;
        }
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
