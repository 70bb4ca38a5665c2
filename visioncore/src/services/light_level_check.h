// The light tracker's check of the level against the table (light_tracking.h): at which levels
// of the light the table reads a frame's posts, balls and robots' colours best.
//
// The tracker measures the light from the carpet and the white against its first frames; but a
// hall is lit unevenly, and a first view of a darker corner then reads every brighter view as a
// brighter light (generated streams with no drift: posts 1.000 -> 0.301 with --adapt). The table
// knows better: it was made for this venue's light, and the classes narrow in Y (a yellow post,
// an orange ball) are read most near the level the light has relative to the table's.
#pragma once

#include "visioncore/basics/colour_lut.h"
#include "visioncore/services/light_tracking.h"

#include <opencv2/core/mat.hpp>

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

namespace fieldsight {

class TableLevelCheck
{
public:
    /// The levels tried, in ln gain of the green channel: kCandidates of them kStep apart around
    /// the tracker's level (at the grid's end when the level is near it), on a grid of kLevels
    /// fixed in the table's light (0 its own light).
    static constexpr int kCandidates = 11;
    static constexpr double kStep = 0.06;
    static constexpr int kLevels = 24;
    static constexpr int kLowest = -12; ///< the grid's first level, in kStep (-0.72 .. +0.66)

    /// Absolute, infinite on a side where the candidates end.
    using Range = LevelRange;

    explicit TableLevelCheck(std::shared_ptr<const ColourLut> table);

    /// The levels at which the table, through the colour of `gain` (R, G, B of the light over
    /// the table's), reads the most pixels of the scored classes (the posts', the ball's and the
    /// robots' colours) on a lattice of about 2,100 pixels of `ycbcr` (CV_8UC3), within the
    /// counts' noise of the most; a side where the candidates end is open. None when every
    /// candidate reads as many (nothing in view says which level is right).
    std::optional<Range> measure(const cv::Mat& ycbcr, const std::array<double, 3>& gain);

private:
    /// Bit k: the grid's level k reads a scored class for pixels of this key
    /// (light_level_check.cpp).
    std::uint32_t levelsOf(std::uint32_t key) const;

    std::shared_ptr<const ColourLut> m_table;
    std::array<long, 2> m_colour_key{0, 0}; ///< R and B over G in kColourStep (the memo's)
    std::array<double, 2> m_colour{1, 1};   ///< R and B over G of m_colour_key
    std::array<float, kLevels> m_divide{};  ///< e^-L of each level of the grid
    /// Observed cells' levels, direct mapped: the cell and the colour's generation, the levels.
    struct Known
    {
        std::uint32_t tag = 0;
        std::uint32_t levels = 0;
    };
    std::vector<Known> m_memo;
    std::uint32_t m_generation = 0;
};

} // namespace fieldsight
