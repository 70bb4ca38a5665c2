// Colour segments: runs of one colour class along a scan line, and the regions that hold them.
#pragma once

#include "visioncore/basics/colour.h"
#include "visioncore/basics/geometry.h"

#include <array>
#include <cstdint>
#include <type_traits>
#include <vector>

namespace fieldsight {

/// A run of pixels of one class along a scan line. The end is exclusive along the scan direction
/// for every segment, including the last one (the original mixed inclusive and exclusive ends,
/// design note §2.2), so length() is always the run length in pixels.
/// Trivial (no member initialisers), so scans copy and grow as raw memory in the hot loops; write
/// `ColourSegment s{}` for a zeroed one.
struct ColourSegment
{
    std::int16_t x0; ///< px, first pixel
    std::int16_t y0; ///< px
    std::int16_t x1; ///< px, one past the last pixel along the scan direction
    std::int16_t y1; ///< px
    Colour colour;

    int length() const { return (x1 - x0) + (y1 - y0); }
    PointF centre() const
    {
        return {(x0 + x1 - (x1 > x0 ? 1 : 0)) * 0.5, (y0 + y1 - (y1 > y0 ? 1 : 0)) * 0.5};
    }
    /// The last pixel of the run (inclusive end).
    PixelPoint last() const { return {x1 > x0 ? x1 - 1 : x1, y1 > y0 ? y1 - 1 : y1}; }
    PixelPoint first() const { return {x0, y0}; }
};

static_assert(std::is_trivial_v<ColourSegment>);

enum class ScanDirection { Horizontal, Vertical };

using Scan = std::vector<ColourSegment>;

/// All scans of one direction for one frame. Inner vectors keep their capacity across frames.
struct SegmentedRegion
{
    ScanDirection direction = ScanDirection::Horizontal;
    std::vector<Scan> scans;
    std::size_t count = 0; ///< scans in use this frame (scans.size() may be larger)

    /// Returns a cleared scan to fill, reusing storage.
    Scan& addScan()
    {
        if (count == scans.size())
            scans.emplace_back();
        Scan& s = scans[count++];
        s.clear();
        return s;
    }
    void reset() { count = 0; }
    std::size_t size() const { return count; }
    const Scan& operator[](std::size_t i) const { return scans[i]; }
    Scan& operator[](std::size_t i) { return scans[i]; }
};

/// The object classes a transition can stand for.
enum class TransitionClass : std::uint8_t { Ball, Goal, Line, TeamCyan, TeamMagenta };
inline constexpr int kTransitionClassCount = 5;

/// Matched segments per class ("transitions" in the paper).
struct Transitions
{
    std::array<std::vector<ColourSegment>, kTransitionClassCount> of{};
    std::vector<ColourSegment>& operator[](TransitionClass c) { return of[std::size_t(c)]; }
    const std::vector<ColourSegment>& operator[](TransitionClass c) const
    {
        return of[std::size_t(c)];
    }
    void clear()
    {
        for (auto& v : of)
            v.clear();
    }
};

} // namespace fieldsight
