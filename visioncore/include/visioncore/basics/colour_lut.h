// The colour lookup table: 128^3 cells of colour ids, indexed by 7-bit Y, Cb, Cr (SPEC §3).
#pragma once

#include "visioncore/basics/colour.h"
#include "visioncore/basics/lut_input_map.h"
#include "visioncore/basics/result.h"

#include <opencv2/core/mat.hpp>

#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace fieldsight {

class ColourLut
{
public:
    static constexpr std::size_t kCells = 128 * 128 * 128; ///< also the file size in bytes

    /// A table with every cell unclassified.
    ColourLut();

    static constexpr std::size_t index(std::uint8_t y, std::uint8_t cb, std::uint8_t cr)
    {
        return (std::size_t(y >> 1) << 14) | (std::size_t(cb >> 1) << 7) | std::size_t(cr >> 1);
    }
    /// The class of an observed pixel: its cell, or with an input map the cell the map sends it to.
    Colour classify(std::uint8_t y, std::uint8_t cb, std::uint8_t cr) const
    {
        return Colour(m_cells[m_map ? m_map->index(y, cb, cr) : index(y, cb, cr)]);
    }
    /// Classifies `count` pixels (Y, Cb, Cr bytes) starting at `px`, `stride` bytes apart, into
    /// `out`. The one lookup loop of the scan lines, the bench floor and its full-frame baseline,
    /// so their times compare the same machine code. With an input map, through the map.
    void classifyRun(const std::uint8_t* px, std::ptrdiff_t stride, int count,
                     std::uint8_t* out) const;
    /// Every pixel of `ycbcr` (CV_8UC3, Y, Cb, Cr) through classifyRun into `classes`, made
    /// CV_8UC1 of the same size, one colour id a pixel. The one whole-image classification.
    void classifyImage(const cv::Mat& ycbcr, cv::Mat& classes) const;
    Colour cell(std::size_t i) const { return Colour(m_cells[i]); }
    void setCell(std::size_t i, Colour colour) { m_cells[i] = std::uint8_t(colour); }
    const std::uint8_t* data() const { return m_cells.data(); }

    /// Puts `map` in front of every lookup (classify, classifyRun, classifyImage; not cell()):
    /// the table then follows a light other than its own. nullptr: the cells as they are.
    void setInputMap(std::shared_ptr<const LutInputMap> map) { m_map = std::move(map); }
    const std::shared_ptr<const LutInputMap>& inputMap() const { return m_map; }

    /// Validates size and values; `source` names the origin in error messages.
    static Result<ColourLut> fromBytes(std::vector<std::uint8_t> bytes, const std::string& source);
    static Result<ColourLut> load(const std::string& path);
    /// Writes a temporary file beside `path`, then renames it over `path`.
    Status save(const std::string& path) const;

    /// The same cells and the same input map (or none).
    friend bool operator==(const ColourLut&, const ColourLut&) = default;

private:
    std::vector<std::uint8_t> m_cells;
    std::shared_ptr<const LutInputMap> m_map;
};

} // namespace fieldsight
