// The checks of a frame file before decoding (PNG chunk CRCs, BMP layout, header sizes) and the
// decoding itself, with libjpeg for JPEG, libpng for PNG and OpenCV for BMP.
#include "io/frame_file_checks.h"

#include "io/jpeg_decoder.h"
#include "io/png_decoder.h"
#include "io/stream_readers.h"
#include "visioncore/basics/atomic_file.h"

#include "visioncore/io/image_files.h"

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <cstring>

namespace fieldsight::io {

namespace {

std::uint32_t bigEndian(const unsigned char* p, int bytes)
{
    std::uint32_t v = 0;
    for (int i = 0; i < bytes; ++i)
        v = (v << 8) | p[i];
    return v;
}

/// The CRC-32 of PNG chunks (ISO 3309), eight bytes a step ("slicing-by-8"): every chunk of every
/// PNG frame is checked before decoding, 0.06 ms for a 110 kB frame (a byte a step took 0.29).
std::uint32_t crc32(const unsigned char* p, std::size_t n)
{
    static const auto tables = [] {
        std::array<std::array<std::uint32_t, 256>, 8> t{};
        for (std::uint32_t i = 0; i < 256; ++i) {
            std::uint32_t c = i;
            for (int k = 0; k < 8; ++k)
                c = (c >> 1) ^ (0xEDB88320u & (0u - (c & 1u)));
            t[0][i] = c;
        }
        for (std::size_t s = 1; s < 8; ++s)
            for (std::size_t i = 0; i < 256; ++i)
                t[s][i] = (t[s - 1][i] >> 8) ^ t[0][t[s - 1][i] & 0xFFu];
        return t;
    }();
    std::uint32_t c = 0xFFFFFFFFu;
    for (; n >= 8; n -= 8, p += 8) {
        std::uint32_t lo = 0, hi = 0;
        std::memcpy(&lo, p, 4); // little-endian on every machine this builds for
        std::memcpy(&hi, p + 4, 4);
        lo ^= c;
        c = tables[7][lo & 0xFFu] ^ tables[6][lo >> 8 & 0xFFu] ^ tables[5][lo >> 16 & 0xFFu] ^
            tables[4][lo >> 24] ^ tables[3][hi & 0xFFu] ^ tables[2][hi >> 8 & 0xFFu] ^
            tables[1][hi >> 16 & 0xFFu] ^ tables[0][hi >> 24];
    }
    for (; n > 0; --n, ++p)
        c = tables[0][(c ^ *p) & 0xFFu] ^ (c >> 8);
    return c ^ 0xFFFFFFFFu;
}

constexpr unsigned char kPngSignature[8] = {0x89, 'P', 'N', 'G', 0x0D, 0x0A, 0x1A, 0x0A};

/// Why a PNG's chunks are damaged (truncated, a checksum that does not match, no IEND), or
/// nullopt. Checked before decoding because libpng prints its own line on such files.
std::optional<std::string> pngDamage(const unsigned char* h, std::size_t n)
{
    std::size_t at = 8;
    while (at + 12 <= n) {
        const std::size_t length = bigEndian(h + at, 4);
        const std::string type(reinterpret_cast<const char*>(h + at + 4), 4);
        if (length > n - at - 12)
            return "truncated PNG (chunk " + type + " at byte " + std::to_string(at) + " needs " +
                   std::to_string(length + 12) + " bytes, " + std::to_string(n - at) + " left)";
        if (crc32(h + at + 4, length + 4) != bigEndian(h + at + 8 + length, 4))
            return "damaged PNG (checksum mismatch in chunk " + type + " at byte " +
                   std::to_string(at) + ")";
        if (type == "IEND")
            return std::nullopt;
        at += length + 12;
    }
    return "truncated PNG (ends at byte " + std::to_string(n) + " before its IEND chunk)";
}

/// Why a BMP's headers, palette, colour masks or pixel rows do not fit in the file, or nullopt.
/// Checked before decoding because OpenCV's decoder prints its own line ("imdecode_(''): can't
/// read header") when it reads past the end. Run-length-compressed BMPs are refused: their length
/// is known only by decoding, and no camera frame is stored that way.
std::optional<std::string> bmpDamage(const unsigned char* h, std::size_t n)
{
    const auto u32 = [h](std::size_t at) {
        std::uint32_t v = 0;
        std::memcpy(&v, h + at, 4); // little-endian on every machine this builds for
        return v;
    };
    const auto u16 = [h](std::size_t at) { return std::uint32_t(h[at] | h[at + 1] << 8); };
    const auto truncated = [n](const std::string& what, std::size_t needed) {
        return "truncated BMP (" + what + " needs " + std::to_string(needed) +
               " bytes, the file has " + std::to_string(n) + ")";
    };
    if (n < 18)
        return truncated("the file header and the header size", 18);
    const std::size_t info = u32(14);
    const bool core = info == 12; // OS/2 1.x: 16-bit sizes, 3-byte palette entries
    if (!core && (info < 40 || info > 1024))
        return "damaged BMP (unknown header size " + std::to_string(info) + ")";
    if (n < 14 + info)
        return truncated("the header", 14 + info);
    const std::int64_t width = core ? std::int64_t(u16(18)) : std::int64_t(std::int32_t(u32(18)));
    const std::int64_t height = core ? std::int64_t(u16(20)) : std::int64_t(std::int32_t(u32(22)));
    const std::uint32_t bpp = core ? u16(24) : u16(28);
    const std::uint32_t compression = core ? 0 : u32(30);
    if (compression == 1 || compression == 2)
        return std::string("run-length-compressed BMP, not a camera frame (save frames "
                           "uncompressed)");
    if (compression != 0 && compression != 3) // OpenCV asserts on anything but RGB, RLE, masks
        return "damaged BMP (unknown compression " + std::to_string(compression) + ")";
    std::size_t end = 14 + info;
    if (bpp <= 8) {
        const std::uint32_t used = core ? 0 : u32(46);
        if (used > 256)
            return "damaged BMP (palette of " + std::to_string(used) + " colours)";
        end += (used == 0 ? std::size_t(1) << bpp : used) * (core ? 3 : 4);
        if (n < end)
            return truncated("the palette", end);
    } else if (bpp == 16 && compression == 3) { // masks after the header (read for 16 bpp only)
        end += 12;
        if (n < end)
            return truncated("the colour masks", end);
    }
    const std::size_t offset = u32(10);
    const std::uint64_t bits = bpp == 15 ? 16 : bpp;
    const std::uint64_t pitch = (std::uint64_t(std::llabs(width)) * bits + 31) / 32 * 4;
    const std::uint64_t rows = std::uint64_t(std::llabs(height));
    if (offset > n || (rows > 0 && pitch > (n - offset) / rows))
        return "truncated BMP (" + std::to_string(rows) + " rows of " + std::to_string(pitch) +
               " bytes from byte " + std::to_string(offset) + ", the file has " +
               std::to_string(n) + ")";
    return std::nullopt;
}

/// The size an image file's header claims (PNG, JPEG, BMP), read before decoding so a small file
/// claiming a huge image is refused instead of allocated; nullopt when the header says nothing
/// this recognises (the decoder then decides).
std::optional<HeaderSize> headerSize(const unsigned char* h, std::size_t n)
{
    if (n >= 24 && std::equal(kPngSignature, kPngSignature + 8, h) &&
        std::memcmp(h + 12, "IHDR", 4) == 0)
        return HeaderSize{(long long)bigEndian(h + 16, 4), (long long)bigEndian(h + 20, 4)};
    if (n >= 26 && h[0] == 'B' && h[1] == 'M') {
        if (h[14] == 12 && h[15] == 0 && h[16] == 0 && h[17] == 0) // OS/2 1.x: 16-bit sizes
            return HeaderSize{h[18] | h[19] << 8, h[20] | h[21] << 8};
        std::int32_t w = 0, ht = 0;
        std::memcpy(&w, h + 18, 4); // little-endian on every machine this builds for
        std::memcpy(&ht, h + 22, 4);
        return HeaderSize{std::llabs(w), std::llabs(ht)};
    }
    if (n >= 4 && h[0] == 0xFF && h[1] == 0xD8) { // JPEG: walk the segments to a frame header
        std::size_t at = 2;
        while (at + 9 < n && h[at] == 0xFF) {
            const unsigned marker = h[at + 1];
            const std::size_t length = bigEndian(h + at + 2, 2);
            const bool sof = (marker >= 0xC0 && marker <= 0xCF) && marker != 0xC4 &&
                             marker != 0xC8 && marker != 0xCC;
            if (sof)
                return HeaderSize{(long long)bigEndian(h + at + 7, 2),
                                  (long long)bigEndian(h + at + 5, 2)};
            if (length < 2)
                break;
            at += 2 + length;
        }
    }
    return std::nullopt;
}

} // namespace

/// Why a frame of `path` whose header claims (or whose pixels are) `width` x `height` is refused,
/// or nullopt: more than kMaxFrameSide a side, or another size than `expected` (the stream's,
/// once known). One rule for the header, libjpeg's reading of it and the decoded frame.
std::optional<Error> refusedFrameSize(const std::string& path, long long width, long long height,
                                      std::optional<HeaderSize> expected)
{
    const auto size = [](long long w, long long h) {
        return std::to_string(w) + "x" + std::to_string(h);
    };
    if (!isSaneFrameSize(width, height))
        return Error{path + ": the image header claims " + size(width, height) +
                     " pixels (at most " + std::to_string(kMaxFrameSide) + " a side); not decoded"};
    if (expected && (width != expected->width || height != expected->height))
        return Error{path + ": frame size " + size(width, height) + " differs from the stream's " +
                     size(expected->width, expected->height)};
    return std::nullopt;
}

/// An image file's pixels as BGR, or an Error naming the file: read with the checks of every
/// read (a FIFO or device is refused, not waited on), the header's size and a PNG's chunks
/// checked before the decoder sees the bytes. When `expected` is given (the stream's size, known
/// once its first frame is read), a header claiming another size is refused before decoding: a
/// 100-byte file cannot make a 32x24 stream decode 200 MB.
Result<cv::Mat> decodeImageFile(const std::string& path, std::optional<HeaderSize> expected)
{
    auto bytes = readWholeFile(path);
    if (!bytes)
        return bytes.error();
    const auto* h = reinterpret_cast<const unsigned char*>(bytes.value().data());
    const std::size_t n = bytes.value().size();
    if (n == 0)
        return Error{"cannot read " + path + ": empty file"};
    const auto checkSize = [&](long long width, long long height) {
        return refusedFrameSize(path, width, height, expected);
    };
    if (const auto claimed = headerSize(h, n))
        if (auto refused = checkSize(claimed->width, claimed->height))
            return *std::move(refused);
    // Only the three formats a stream folder holds reach the decoder: given anything else,
    // imdecode would try every codec OpenCV was built with (GDAL among them, which copies the
    // bytes to a temporary file and prints its own errors).
    const bool png = n >= 8 && std::equal(kPngSignature, kPngSignature + 8, h);
    const bool jpeg = n >= 3 && h[0] == 0xFF && h[1] == 0xD8 && h[2] == 0xFF;
    const bool bmp = n >= 2 && h[0] == 'B' && h[1] == 'M';
    if (!png && !jpeg && !bmp)
        return Error{"cannot read " + path +
                     ": not a decodable image (no PNG, JPEG or BMP signature)"};
    if (const auto damage = png ? pngDamage(h, n) : bmp ? bmpDamage(h, n) : std::nullopt)
        return Error{"cannot read " + path + ": " + *damage};
    if (jpeg) // libjpeg's reading of the header is checked too: fill bytes may hide it above
        return decodeJpeg(path, h, n, checkSize);
    if (png) // libpng's own lines on a damaged header or image data become this one
        return decodePng(path, h, n, checkSize);
    auto bgr = decodeImage(h, n, cv::IMREAD_COLOR | cv::IMREAD_IGNORE_ORIENTATION, path);
    if (bgr && bgr.value().empty())
        return Error{"cannot read " + path + ": not a decodable image"};
    return bgr;
}

} // namespace fieldsight::io
