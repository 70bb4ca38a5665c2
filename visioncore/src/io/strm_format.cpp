// Encoding and decoding of .strm record headers and pixels.
#include "io/strm_format.h"

#include <bit>
#include <cstring>

#if defined(__x86_64__)
#include <immintrin.h>
#endif

namespace fieldsight::io {

namespace {

template <class T> T loadLittle(const unsigned char* p)
{
    static_assert(std::endian::native == std::endian::little, "big-endian hosts need byte swaps");
    T value;
    std::memcpy(&value, p, sizeof value);
    return value;
}

template <class T> void storeLittle(unsigned char* p, T value)
{
    static_assert(std::endian::native == std::endian::little, "big-endian hosts need byte swaps");
    std::memcpy(p, &value, sizeof value);
}

} // namespace

StrmHeader decodeStrmHeader(const unsigned char* raw)
{
    StrmHeader h;
    std::memcpy(h.magic, raw, 4);
    h.version = loadLittle<std::int32_t>(raw + 4);
    h.width = loadLittle<std::int32_t>(raw + 8);
    h.height = loadLittle<std::int32_t>(raw + 12);
    h.timestamp_ms = loadLittle<double>(raw + 16);
    h.flipped = h.version >= 1 && raw[24] != 0;
    return h;
}

void encodeStrmHeader(const StrmHeader& header, unsigned char* raw)
{
    std::memcpy(raw, header.magic, 4);
    storeLittle(raw + 4, header.version);
    storeLittle(raw + 8, header.width);
    storeLittle(raw + 12, header.height);
    storeLittle(raw + 16, header.timestamp_ms);
    raw[24] = header.flipped ? 1 : 0;
}

namespace {

// Scalar fallback: three byte moves per pixel; the compiler keeps it a tight loop.
void convertScalar(const std::uint8_t* in, std::uint8_t* out, std::size_t pixels)
{
    for (std::size_t i = 0; i < pixels; ++i, in += 4, out += 3) {
        out[0] = in[2];
        out[1] = in[1];
        out[2] = in[3];
    }
}

void convertScalarReversed(const std::uint8_t* in, std::uint8_t* out, std::size_t pixels)
{
    const std::uint8_t* src = in + pixels * 4;
    for (std::size_t i = 0; i < pixels; ++i, out += 3) {
        src -= 4;
        out[0] = src[2];
        out[1] = src[1];
        out[2] = src[3];
    }
}

#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
#define FIELDSIGHT_STRM_SSSE3 1

// Four pixels per step: one 16-byte load, one byte shuffle, one 16-byte store of which 12 bytes
// are pixels (the next store overwrites the other 4). The last block is left to the scalar loop
// so the store never runs past the output.
__attribute__((target("ssse3"))) std::size_t convertSsse3(const std::uint8_t* in, std::uint8_t* out,
                                                          std::size_t pixels, bool reversed)
{
    if (pixels < 8)
        return 0;
    const std::size_t blocks = (pixels - 4) / 4;
    if (!reversed) {
        const __m128i order =
            _mm_setr_epi8(2, 1, 3, 6, 5, 7, 10, 9, 11, 14, 13, 15, -1, -1, -1, -1);
#pragma GCC unroll 4
        for (std::size_t b = 0; b < blocks; ++b, in += 16, out += 12)
            _mm_storeu_si128(
                reinterpret_cast<__m128i*>(out),
                _mm_shuffle_epi8(_mm_loadu_si128(reinterpret_cast<const __m128i*>(in)), order));
    } else {
        const __m128i order =
            _mm_setr_epi8(14, 13, 15, 10, 9, 11, 6, 5, 7, 2, 1, 3, -1, -1, -1, -1);
        const std::uint8_t* src = in + pixels * 4;
#pragma GCC unroll 4
        for (std::size_t b = 0; b < blocks; ++b, out += 12) {
            src -= 16;
            _mm_storeu_si128(
                reinterpret_cast<__m128i*>(out),
                _mm_shuffle_epi8(_mm_loadu_si128(reinterpret_cast<const __m128i*>(src)), order));
        }
    }
    return blocks * 4;
}

bool hasSsse3()
{
    static const bool supported = __builtin_cpu_supports("ssse3");
    return supported;
}
#endif

} // namespace

// The hot path of .strm playback, once per frame: SSSE3 shuffles where the CPU has them (about
// one instruction per pixel), else a plain byte loop.
void strmPixelsToYCbCr(const std::uint8_t* in, std::uint8_t* out, std::size_t pixels, bool flipped)
{
    std::size_t done = 0;
#ifdef FIELDSIGHT_STRM_SSSE3
    if (hasSsse3())
        done = convertSsse3(in, out, pixels, flipped);
#endif
    if (!flipped)
        convertScalar(in + done * 4, out + done * 3, pixels - done);
    else
        convertScalarReversed(in, out + done * 3, pixels - done);
}

void yCbCrToStrmPixels(const std::uint8_t* in, std::uint8_t* out, std::size_t pixels, bool flipped)
{
    std::uint8_t* dst = flipped ? out + pixels * 4 - 4 : out;
    const std::ptrdiff_t step = flipped ? -4 : 4;
    for (std::size_t i = 0; i < pixels; ++i, in += 3, dst += step) {
        dst[0] = in[0];
        dst[1] = in[1];
        dst[2] = in[0];
        dst[3] = in[2];
    }
}

} // namespace fieldsight::io
