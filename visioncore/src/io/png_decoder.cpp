#include "io/png_decoder.h"

#include <png.h>

#include <csetjmp>
#include <cstring>
#include <string>
#include <vector>

namespace fieldsight::io {

namespace {

/// Ancillary chunks (text, profiles) libpng keeps in memory while reading: a frame has none
/// worth more.
constexpr png_alloc_size_t kMaxChunkBytes = png_alloc_size_t(8) << 20;

struct Source
{
    const unsigned char* data = nullptr;
    std::size_t size = 0;
    std::size_t at = 0;
};

/// Where to jump on an error and what it was.
struct Errors
{
    std::jmp_buf jump;
    std::string problem;
};

// longjmp skips destructors, so no function it leaves holds an object with one: the problem is
// stored in the Errors made before setjmp.

[[noreturn]] void onError(png_structp png, png_const_charp message)
{
    auto* errors = static_cast<Errors*>(png_get_error_ptr(png));
    errors->problem = message;
    std::longjmp(errors->jump, 1);
}

void onWarning(png_structp, png_const_charp) {}

void readBytes(png_structp png, png_bytep out, png_size_t count)
{
    auto* source = static_cast<Source*>(png_get_io_ptr(png));
    if (count > source->size - source->at)
        png_error(png, "the file ends inside a chunk");
    std::memcpy(out, source->data + source->at, count);
    source->at += count;
}

} // namespace

Result<cv::Mat> decodePng(const std::string& path, const unsigned char* data, std::size_t size,
                          const FrameSizeCheck& check_size)
{
    // Everything longjmp returns past is made before setjmp: no destructor is skipped.
    Errors errors{};
    Source source{data, size, 0};
    cv::Mat bgr;
    std::vector<png_bytep> rows;
    png_structp png = png_create_read_struct(PNG_LIBPNG_VER_STRING, &errors, onError, onWarning);
    if (!png)
        return Error{"cannot read " + path + ": out of memory for the PNG reader"};
    png_infop info = png_create_info_struct(png);
    if (!info) {
        png_destroy_read_struct(&png, nullptr, nullptr);
        return Error{"cannot read " + path + ": out of memory for the PNG reader"};
    }
    if (setjmp(errors.jump)) {
        png_destroy_read_struct(&png, &info, nullptr);
        return Error{"cannot read " + path + ": damaged PNG (" + errors.problem + ")"};
    }
    png_set_read_fn(png, &source, readBytes);
    png_set_chunk_malloc_max(png, kMaxChunkBytes);
    png_read_info(png, info);
    png_uint_32 width = 0, height = 0;
    int depth = 0, colour = 0;
    png_get_IHDR(png, info, &width, &height, &depth, &colour, nullptr, nullptr, nullptr);
    const auto refuse = [&png, &info](std::string message) {
        png_destroy_read_struct(&png, &info, nullptr);
        return Error{std::move(message)};
    };
    if (auto refused = check_size(width, height))
        return refuse(std::move(refused->message));
    // The transformations cv::imdecode asks for with IMREAD_COLOR.
    if (colour & PNG_COLOR_MASK_COLOR)
        png_set_bgr(png);
    if (depth > 8)
        png_set_strip_16(png);
    png_set_strip_alpha(png);
    if (colour == PNG_COLOR_TYPE_PALETTE)
        png_set_palette_to_rgb(png);
    if ((colour & PNG_COLOR_MASK_COLOR) == 0 && depth < 8)
        png_set_expand_gray_1_2_4_to_8(png);
    if ((colour & PNG_COLOR_MASK_COLOR) == 0)
        png_set_gray_to_rgb(png);
    png_set_interlace_handling(png);
    png_read_update_info(png, info);
    if (png_get_rowbytes(png, info) != png_size_t(width) * 3)
        return refuse("cannot read " + path + ": a PNG of an unexpected layout");
    try {
        bgr.create(int(height), int(width), CV_8UC3);
        rows.resize(height);
    } catch (const std::exception&) {
        return refuse("cannot read " + path + ": out of memory for " + std::to_string(width) + "x" +
                      std::to_string(height) + " pixels");
    }
    for (png_uint_32 y = 0; y < height; ++y)
        rows[y] = bgr.ptr(int(y));
    png_read_image(png, rows.data());
    png_read_end(png, nullptr);
    png_destroy_read_struct(&png, &info, nullptr);
    return bgr;
}

} // namespace fieldsight::io
