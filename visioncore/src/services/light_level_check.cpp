// The level against the table (light_level_check.h): a lattice of the frame read at a few levels
// of the light. What an observed cell reads at each level of a fixed grid is remembered while the
// light's colour stays, so a check works out only the cells it has not met (a frame's noise).
#include "services/light_level_check.h"

#include "visioncore/basics/lut_input_map.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace fieldsight {

namespace {

/// What the level is judged by: the posts', the ball's and the robots' colours. Not the carpet
/// and the shadows (broad in Y, they gain pixels as the map darkens: the lab1 scenes' robots
/// read shadow at every darker level), nor the white: a brighter map makes grey white, so its
/// count grows the brighter the map, and following it walked the level off (rc2012 seed 13 at
/// 30% drift: balls 1.000 -> 0.556).
constexpr std::uint32_t kScored =
    ~((1u << int(Colour::Unclassified)) | (1u << int(Colour::White)) | (1u << int(Colour::Green)) |
      (1u << int(Colour::ShadowObject)) | (1u << int(Colour::ShadowBlue)));

/// The colour's step in ln gain: what the memo knows is worked out again when it moves this far.
constexpr double kColourStep = 0.04;

/// The lattice: about this many pixels whatever the frame's size (at 320 x 240, every 6th pixel
/// of every 6th row; every 8th lost a stream's posts, rc2012 seed 71 at 30% drift 0.800 -> 0.657).
constexpr double kLatticePixels = 2100;

/// The memo: 2^kMemoBits entries, a pixel's tag its key (kKeyBits of Y, Cb and Cr: cells of
/// 2^kKeyShift levels, a pixel's noise meets fewer than the table's 2) above the colour's
/// generation (kGenerationBits, never 0, so an empty entry matches no key).
constexpr int kMemoBits = 14;
constexpr int kKeyShift = 2;
constexpr int kKeyBits = 8 - kKeyShift;
constexpr std::uint32_t kKeyMask = (1u << kKeyBits) - 1;
constexpr int kGenerationBits = 32 - 3 * kKeyBits;
static_assert(TableLevelCheck::kLevels <= 32);

} // namespace

TableLevelCheck::TableLevelCheck(std::shared_ptr<const ColourLut> table) : m_table(std::move(table))
{
    if (!m_table)
        throw std::invalid_argument("TableLevelCheck: no table");
    for (int k = 0; k < kLevels; ++k)
        m_divide[std::size_t(k)] = float(std::exp(-double(kLowest + k) * kStep));
}

std::uint32_t TableLevelCheck::levelsOf(std::uint32_t key) const
{
    // The key's centre in R, G, B (BT.601 full range, as ycbcr.h converts), the colour divided
    // out: each level then divides the three alike. As LutInputMap does, a clipped channel stays
    // (the table's light clipped it too) and another reads at most 255.
    constexpr int kSide = 1 << kKeyShift;
    constexpr double kCentre = (kSide - 1) / 2.0;
    const double y = double((key >> (2 * kKeyBits)) & kKeyMask) * kSide + kCentre;
    const double cb = double((key >> kKeyBits) & kKeyMask) * kSide + kCentre - 128;
    const double cr = double(key & kKeyMask) * kSide + kCentre - 128;
    const std::array<double, 3> rgb{y + 1.402 * cr, y - 0.344136 * cb - 0.714136 * cr,
                                    y + 1.772 * cb};
    // Per channel: what a level's divisor multiplies, and the bounds (a clipped channel: times
    // 0, held at itself).
    std::array<float, 3> scale{};
    std::array<float, 3> low{};
    std::array<float, 3> high{};
    const std::array<double, 3> colour{m_colour[0], 1.0, m_colour[1]};
    for (std::size_t c = 0; c < 3; ++c) {
        const bool clipped = rgb[c] >= LutInputMap::kClip;
        scale[c] = clipped ? 0.0f : float(rgb[c] / colour[c]);
        low[c] = clipped ? float(rgb[c]) : -1e9f;
        high[c] = clipped ? float(rgb[c]) : 255.0f;
    }
    // The levels' cells side by side (a loop the compiler vectorises), then their classes.
    std::array<std::uint32_t, kLevels> index{};
    for (std::size_t k = 0; k < std::size_t(kLevels); ++k) {
        const float d = m_divide[k];
        const float r = std::min(high[0], std::max(low[0], scale[0] * d));
        const float g = std::min(high[1], std::max(low[1], scale[1] * d));
        const float b = std::min(high[2], std::max(low[2], scale[2] * d));
        const float yk = 0.299f * r + 0.587f * g + 0.114f * b;
        // The cell: floor(v / 2) in 0..127, as LutInputMap rounds.
        const auto cellOf = [](float v) {
            return std::uint32_t(std::min(127.0f, std::max(0.0f, v * 0.5f)));
        };
        index[k] = (cellOf(yk) << 14) | (cellOf(128.0f + 0.564334f * (b - yk)) << 7) |
                   cellOf(128.0f + 0.713267f * (r - yk));
    }
    const std::uint8_t* cells = m_table->data();
    std::uint32_t levels = 0;
    for (std::size_t k = 0; k < std::size_t(kLevels); ++k)
        levels |= std::uint32_t((kScored >> cells[index[k]]) & 1) << k;
    return levels;
}

std::optional<TableLevelCheck::Range> TableLevelCheck::measure(const cv::Mat& ycbcr,
                                                               const std::array<double, 3>& gain)
{
    CV_Assert(ycbcr.type() == CV_8UC3);
    // The candidates: the grid's levels nearest the tracker's, kCandidates of them.
    const double level = std::log(gain[1]);
    // A level near the grid's ends takes the candidates at that end (a side at the end is open).
    const long first = std::clamp(std::lround(level / kStep) - kCandidates / 2 - kLowest, 0L,
                                  long(kLevels - kCandidates));
    const std::array<long, 2> colour_key{std::lround((std::log(gain[0]) - level) / kColourStep),
                                         std::lround((std::log(gain[2]) - level) / kColourStep)};
    if (m_memo.empty() || colour_key != m_colour_key) {
        m_colour_key = colour_key;
        m_colour = {std::exp(double(colour_key[0]) * kColourStep),
                    std::exp(double(colour_key[1]) * kColourStep)};
        if (m_memo.empty() || ++m_generation >> kGenerationBits) {
            m_memo.assign(std::size_t(1) << kMemoBits, Known{});
            m_generation = 1;
        }
    }

    std::array<int, kCandidates> reads{};
    const int step =
        std::max(1, int(std::lround(std::sqrt(double(ycbcr.cols) * ycbcr.rows / kLatticePixels))));
    constexpr std::uint32_t kWindow = (1u << kCandidates) - 1;
    for (int y = step / 2, row = 0; y < ycbcr.rows; y += step, ++row) {
        const std::uint8_t* p = ycbcr.ptr<std::uint8_t>(y);
        for (int x = step / 2 + (row & 1) * (step / 2); x < ycbcr.cols; x += step) {
            const std::uint8_t* q = p + 3 * x;
            const std::uint32_t key = (std::uint32_t(q[0] >> kKeyShift) << (2 * kKeyBits)) |
                                      (std::uint32_t(q[1] >> kKeyShift) << kKeyBits) |
                                      std::uint32_t(q[2] >> kKeyShift);
            Known& known = m_memo[(key * 2654435761u) >> (32 - kMemoBits)];
            const std::uint32_t tag = (key << kGenerationBits) | m_generation;
            if (known.tag != tag)
                known = {tag, levelsOf(key)};
            for (std::uint32_t mask = (known.levels >> first) & kWindow; mask; mask &= mask - 1)
                ++reads[std::size_t(std::countr_zero(mask))];
        }
    }

    // Within the counts' noise (a square root) of the most, and at least 2.
    const int most = *std::max_element(reads.begin(), reads.end());
    const double below = std::max(2.0, std::sqrt(double(most)));
    int lowest = kCandidates;
    int highest = -1;
    for (int j = 0; j < kCandidates; ++j)
        if (reads[std::size_t(j)] >= most - below) {
            lowest = std::min(lowest, j);
            highest = j;
        }
    if (lowest == 0 && highest == kCandidates - 1)
        return std::nullopt;
    constexpr double kOpen = std::numeric_limits<double>::infinity();
    const auto levelOf = [first](int j) { return double(first + j + kLowest) * kStep; };
    return Range{lowest == 0 ? -kOpen : levelOf(lowest),
                 highest == kCandidates - 1 ? kOpen : levelOf(highest)};
}

} // namespace fieldsight
