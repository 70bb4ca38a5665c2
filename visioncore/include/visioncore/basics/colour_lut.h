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
        const std::size_t i = index(y, cb, cr);
        return Colour(m_map ? mappedClass(i) : m_cells[i]);
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
    void setCell(std::size_t i, Colour colour);
    const std::uint8_t* data() const { return m_cells.data(); }

    /// Puts `map` in front of every lookup (classify, classifyRun, classifyImage; not cell()):
    /// the table then follows a light other than its own. nullptr: the cells as they are. What
    /// each observed cell reads through the map is worked out on its first lookup and remembered,
    /// shared by every table with these cells and this map (copies, other threads), so a lookup
    /// through a map costs about what one without does. setCell() forgets it until the map is set
    /// again (lookups meanwhile work the map out each time).
    void setInputMap(std::shared_ptr<const LutInputMap> map);
    const std::shared_ptr<const LutInputMap>& inputMap() const { return m_map; }

    /// Validates size and values; `source` names the origin in error messages.
    static Result<ColourLut> fromBytes(std::vector<std::uint8_t> bytes, const std::string& source);
    static Result<ColourLut> load(const std::string& path);
    /// Writes a temporary file beside `path`, then renames it over `path`.
    Status save(const std::string& path) const;

    /// The same cells and the same input map (or none).
    friend bool operator==(const ColourLut& a, const ColourLut& b)
    {
        return a.m_cells == b.m_cells && a.m_map == b.m_map;
    }

private:
    /// A table of these cells (kCells valid ids), without clearing a table first.
    explicit ColourLut(std::vector<std::uint8_t> cells);

    /// What each observed cell reads through the input map: its class | kKnown, 0 until asked.
    struct MapMemo;
    static constexpr std::uint8_t kKnown = 0x80;

    /// The class observed cell `i` reads through the map (the memo, filled on a first lookup).
    std::uint8_t mappedClass(std::size_t i) const
    {
        const std::uint8_t v = __atomic_load_n(m_memo_cells + i, __ATOMIC_RELAXED);
        return v ? std::uint8_t(v & ~kKnown) : fillMemo(i);
    }
    std::uint8_t fillMemo(std::size_t i) const;
    /// classifyRun's first reads: the memo of the pixel at `px` (class | kKnown), filled if empty.
    /// An earlier pixel of the run may have filled the cell since the run's lookups read it (a
    /// run over the carpet reads a few cells many times).
    std::uint8_t knownOrFilled(const std::uint8_t* px) const
    {
        const std::size_t i = index(px[0], px[1], px[2]);
        const std::uint8_t known = __atomic_load_n(m_memo_cells + i, __ATOMIC_RELAXED);
        return known ? known : std::uint8_t(fillMemo(i) | kKnown);
    }
    /// The class observed cell `i` reads through the map, and its next map where unclassified
    /// (a class the map takes from it).
    std::uint8_t readThroughMap(std::size_t i) const
    {
        const std::uint8_t c = m_cells[m_map->cellOf(i)];
        if (c || !m_map->then())
            return c;
        const std::uint8_t next = m_cells[m_map->then()->cellOf(i)];
        return m_map->takesFromThen(next) ? next : std::uint8_t(0);
    }

    std::vector<std::uint8_t> m_cells;
    /// Names these cells, so that tables with the same cells share a memo: new for a new table,
    /// kept by copies, 0 once a cell is set (named again by the next setInputMap).
    std::uint64_t m_content;
    std::shared_ptr<const LutInputMap> m_map;
    std::shared_ptr<MapMemo> m_memo; ///< of m_cells through m_map, or null
    /// m_memo's bytes; with a map but no memo (a cell set since the map was) a read-only memo that
    /// knows no cell, so that every lookup works its cell out and stores nothing (fillMemo): a
    /// lookup through a map then has one test, not two. Null without a map.
    const std::uint8_t* m_memo_cells = nullptr;
    static const std::uint8_t* noMemoCells();
};

} // namespace fieldsight
