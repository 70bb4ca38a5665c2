// The byte layout of one NUbots image-stream record (design note §4.1), shared by reader and
// writer.
#pragma once

#include <cstddef>
#include <cstdint>

namespace fieldsight::io {

inline constexpr char kStrmMagic[4] = {'I', 'M', 'A', 'G'};
inline constexpr std::size_t kStrmHeaderSizeV0 = 24; ///< magic, version, width, height, timestamp
inline constexpr std::size_t kStrmHeaderSize = 25;   ///< version >= 1 adds the flipped byte
inline constexpr std::size_t kStrmBytesPerPixel = 4; ///< Y0, Cb, Y, Cr
inline constexpr std::int32_t kStrmWriteVersion = 1;

inline std::size_t strmHeaderSize(std::int32_t version)
{
    return version >= 1 ? kStrmHeaderSize : kStrmHeaderSizeV0;
}

struct StrmHeader
{
    char magic[4] = {};
    std::int32_t version = 0;
    std::int32_t width = 0;  ///< px
    std::int32_t height = 0; ///< px
    double timestamp_ms = 0;
    bool flipped = false; ///< only meaningful when version >= 1
};

/// Decodes the little-endian header at `raw` (at least strmHeaderSize(version) bytes).
StrmHeader decodeStrmHeader(const unsigned char* raw);
/// Encodes a version-1 header into `raw` (kStrmHeaderSize bytes).
void encodeStrmHeader(const StrmHeader& header, unsigned char* raw);

/// Converts `pixels` 4-byte record pixels (Y0, Cb, Y, Cr) to 3-byte Y, Cb, Cr. With `flipped`
/// the output is the input rotated 180 degrees (pixel order reversed).
void strmPixelsToYCbCr(const std::uint8_t* in, std::uint8_t* out, std::size_t pixels, bool flipped);
/// The inverse, writing Y into both luma bytes; with `flipped` the output is rotated 180 degrees.
void yCbCrToStrmPixels(const std::uint8_t* in, std::uint8_t* out, std::size_t pixels, bool flipped);

} // namespace fieldsight::io
