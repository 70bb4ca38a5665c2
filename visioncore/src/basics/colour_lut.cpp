// The native .lut format (SPEC §3): 2,097,152 raw colour ids, validated on load, saved atomically.
#include "visioncore/basics/colour_lut.h"

#include "visioncore/basics/atomic_file.h"

#include <algorithm>
#include <cstring>
#include <filesystem>
#include <system_error>

namespace fieldsight {

ColourLut::ColourLut() : m_cells(kCells, std::uint8_t(Colour::Unclassified)) {}

namespace {

/// `__restrict`: the class bytes written never alias the pixels or the table, so the compiler need
/// not reload them after every store (uint8_t pointers may alias anything).
void lookupRun(const std::uint8_t* __restrict cells, const std::uint8_t* __restrict px,
               std::ptrdiff_t stride, int count, std::uint8_t* __restrict out)
{
#pragma GCC unroll 4
    for (int i = 0; i < count; ++i, px += stride)
        out[i] = cells[ColourLut::index(px[0], px[1], px[2])];
}

/// lookupRun through an input map: three small tables in front of the big one.
void mappedRun(const std::uint8_t* __restrict cells, const LutInputMap& map,
               const std::uint8_t* __restrict px, std::ptrdiff_t stride, int count,
               std::uint8_t* __restrict out)
{
    for (int i = 0; i < count; ++i, px += stride)
        out[i] = cells[map.index(px[0], px[1], px[2])];
}

} // namespace

void ColourLut::classifyRun(const std::uint8_t* px, std::ptrdiff_t stride, int count,
                            std::uint8_t* out) const
{
    if (m_map)
        mappedRun(m_cells.data(), *m_map, px, stride, count, out);
    else
        lookupRun(m_cells.data(), px, stride, count, out);
}

void ColourLut::classifyImage(const cv::Mat& ycbcr, cv::Mat& classes) const
{
    CV_Assert(ycbcr.type() == CV_8UC3);
    classes.create(ycbcr.rows, ycbcr.cols, CV_8UC1);
    for (int y = 0; y < ycbcr.rows; ++y)
        classifyRun(ycbcr.ptr<std::uint8_t>(y), 3, ycbcr.cols, classes.ptr<std::uint8_t>(y));
}

Result<ColourLut> ColourLut::fromBytes(std::vector<std::uint8_t> bytes, const std::string& source)
{
    if (bytes.size() != kCells)
        return Error{source + ": wrong size: " + std::to_string(bytes.size()) +
                     " bytes, expected " + std::to_string(kCells) + " (128x128x128)"};
    // The largest id first, in a loop that vectorises; the first bad cell only when there is one.
    std::uint8_t largest = 0;
    for (const std::uint8_t v : bytes)
        largest = std::max(largest, v);
    if (!isValidColourId(largest)) {
        const auto bad = std::find_if(bytes.begin(), bytes.end(),
                                      [](std::uint8_t v) { return !isValidColourId(v); });
        const auto count =
            std::count_if(bad, bytes.end(), [](std::uint8_t v) { return !isValidColourId(v); });
        return Error{source + ": invalid colour id " + std::to_string(int(*bad)) + " at offset " +
                     std::to_string(bad - bytes.begin()) + " (ids are 0-10; " +
                     std::to_string(count) + " bad cells)"};
    }
    ColourLut lut;
    lut.m_cells = std::move(bytes);
    return lut;
}

Result<ColourLut> ColourLut::load(const std::string& path)
{
    // Check the size before reading, so that pointing at a huge file fails fast.
    std::error_code ec;
    const auto size = std::filesystem::file_size(path, ec);
    if (!ec && size != kCells)
        return Error{path + ": wrong size: " + std::to_string(size) + " bytes, expected " +
                     std::to_string(kCells) + " (128x128x128)"};
    auto text = readWholeFile(path);
    if (!text)
        return text.error();
    const std::string& s = text.value();
    std::vector<std::uint8_t> bytes(s.size());
    std::memcpy(bytes.data(), s.data(), s.size());
    return fromBytes(std::move(bytes), path);
}

Status ColourLut::save(const std::string& path) const
{
    return writeFileAtomically(path, m_cells.data(), m_cells.size());
}

} // namespace fieldsight
