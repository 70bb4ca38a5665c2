// What a LUT edit touches: the cells a click, a brush stroke or a magic wand selects. Pure
// functions over a frame and a table, shared by the GUI's LUT editor and the command line; the
// edit itself (and its undo) is the caller's.
#pragma once

#include "visioncore/basics/colour_lut.h"

#include <opencv2/core/mat.hpp>
#include <opencv2/core/types.hpp>

#include <array>
#include <cstddef>
#include <vector>

namespace fieldsight {

/// Half-widths of a box in Y, Cb and Cr, in 8-bit levels (0 = the one cell of the colour).
struct Tolerance
{
    int y = 0;
    int cb = 0;
    int cr = 0;
};

/// One cell's change: what it was and what it becomes.
struct CellChange
{
    std::uint32_t cell = 0;
    Colour before = Colour::Unclassified;
    Colour after = Colour::Unclassified;
};

/// The cells of every colour within `tolerance` of (y, cb, cr), each channel clamped to 0..255;
/// ascending, without repeats.
std::vector<std::uint32_t> cellsInBox(std::uint8_t y, std::uint8_t cb, std::uint8_t cr,
                                      const Tolerance& tolerance);

/// The cells of a round brush in the UV (Cb, Cr) plane: every cell within `radius` cells of cell
/// (cb, cr) (7-bit cell coordinates), at every Y cell from `y_lo` to `y_hi`; ascending.
std::vector<std::uint32_t> cellsInUvDisc(int cb, int cr, int radius, int y_lo, int y_hi);

/// The cells of a rectangle of the UV plane (cell coordinates, inclusive, any corner order) at
/// every Y cell from `y_lo` to `y_hi`; ascending.
std::vector<std::uint32_t> cellsInUvRect(int cb0, int cr0, int cb1, int cr1, int y_lo, int y_hi);

/// The pixels of a round brush of `radius` px (0: one pixel) centred on `centre`, inside a
/// `size` image.
std::vector<cv::Point> brushPixels(cv::Point centre, int radius, cv::Size size);

/// The centres a stroke passes through from `from` to `to`: one per step along the longer axis
/// (rounded), so a fast drag leaves no gap; `from` itself only with `include_from` (a stroke's
/// first dab; later pieces start where the one before ended).
std::vector<cv::Point> strokePoints(cv::Point from, cv::Point to, bool include_from);

/// Every pixel a round brush of `radius` px covers moving from `from` to `to` in a `size` image
/// (strokePoints, then brushPixels at each; pixels may repeat).
std::vector<cv::Point> strokePixels(cv::Point from, cv::Point to, int radius, cv::Size size,
                                    bool include_from);

/// Every cell a UV brush of `radius` cells covers moving from cell `from` to cell `to` (x = Cb,
/// y = Cr, 7-bit cell coordinates) at every Y cell from `y_lo` to `y_hi`; ascending, no repeats.
std::vector<std::uint32_t> strokeUvCells(cv::Point from, cv::Point to, int radius, int y_lo,
                                         int y_hi, bool include_from);

/// The pixels connected (4-neighbours) to `seed` whose Y, Cb and Cr each differ from the seed's by
/// at most `tolerance` (a magic wand). Empty when the seed is outside the image.
std::vector<cv::Point> wandPixels(const cv::Mat& ycbcr, cv::Point seed, const Tolerance& tolerance);

/// The cells of the colours of `pixels` in a CV_8UC3 Y, Cb, Cr frame, each grown by `tolerance`;
/// ascending, without repeats. Pixels outside the frame are ignored.
std::vector<std::uint32_t> cellsOfPixels(const cv::Mat& ycbcr, const std::vector<cv::Point>& pixels,
                                         const Tolerance& tolerance = {});

/// The class a cell of class `existing` takes when `wanted` is painted on it with soft classes:
/// where pink and orange meet, pink_orange; where orange and yellow meet, yellow_orange (a soft
/// cell painted with either of its two classes stays soft); otherwise `wanted`.
Colour softMeet(Colour existing, Colour wanted);

/// The changes that setting `cells` to `colour` makes in `lut` (cells already `colour` are left
/// out). With `keep_others`, only unclassified cells change; with `soft`, cells where two
/// classes meet become their soft class (softMeet).
std::vector<CellChange> changesTo(const ColourLut& lut, const std::vector<std::uint32_t>& cells,
                                  Colour colour, bool keep_others = false, bool soft = false);

/// How many of `changes` take a cell from each class (index = colour id; unclassified cells are
/// not counted): what an edit would take from another class.
std::array<std::size_t, kColourCount> cellsTakenByClass(const std::vector<CellChange>& changes);

/// Applies `changes` forwards (after) or backwards (before).
void applyChanges(ColourLut& lut, const std::vector<CellChange>& changes, bool forwards = true);

/// A global shift of every channel, in 8-bit levels (a venue's lighting against the lab's).
struct ColourShift
{
    int y = 0;
    int cb = 0;
    int cr = 0;
    friend bool operator==(const ColourShift&, const ColourShift&) = default;
};

/// The shift that moves the table's `colour` onto `samples` (Y, Cb, Cr pixels known to be that
/// colour, such as a frame's field): the samples' per-channel median less the median of the
/// class's cells (at their centres). Zero when either is empty.
ColourShift estimateShift(const ColourLut& lut, Colour colour,
                          const std::vector<cv::Vec3b>& samples);

/// The changes that move the whole table by `shift`: each cell takes the class of the cell
/// `shift` levels back (unclassified where that falls outside the range).
std::vector<CellChange> shiftChanges(const ColourLut& lut, const ColourShift& shift);

/// How many cells of each class (index = colour id).
std::vector<std::size_t> cellsPerClass(const ColourLut& lut);

} // namespace fieldsight
