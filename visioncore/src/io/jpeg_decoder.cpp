#include "io/jpeg_decoder.h"

#include <csetjmp>
#include <cstdio> // before jpeglib.h, which uses FILE
#include <string>

#include <jerror.h>
#include <jpeglib.h>

namespace fieldsight::io {

namespace {

/// Progressive scans allowed: each scan passes over the whole image, so a small file of
/// thousands of scans would keep the decoder busy for minutes (libjpeg-turbo's own fuzzers stop
/// at 500 too).
constexpr int kMaxScans = 500;

/// libjpeg's error manager with where to jump on an error and what the error was. libjpeg sees
/// only `pub`, the first member.
struct ErrorManager
{
    jpeg_error_mgr pub;
    std::jmp_buf jump;
    std::string problem;
    const char* kind = "undecodable JPEG"; // what the problem makes the file
};

// longjmp skips destructors, so no function it leaves holds a std::string (or any object with a
// destructor) at the jump: the problem is stored first, in a statement of its own.

/// Stores libjpeg's message for the current code as the problem.
void keepMessage(j_common_ptr cinfo)
{
    char text[JMSG_LENGTH_MAX] = {};
    (*cinfo->err->format_message)(cinfo, text);
    reinterpret_cast<ErrorManager*>(cinfo->err)->problem = text;
}

[[noreturn]] void jumpOut(j_common_ptr cinfo)
{
    std::longjmp(reinterpret_cast<ErrorManager*>(cinfo->err)->jump, 1);
}

[[noreturn]] void onError(j_common_ptr cinfo)
{
    keepMessage(cinfo);
    jumpOut(cinfo);
}

/// Replaces libjpeg's printing of messages: trace messages (level >= 0) are dropped, warnings
/// about damaged data end the decode, other warnings are only counted.
void onMessage(j_common_ptr cinfo, int level)
{
    if (level >= 0)
        return;
    keepMessage(cinfo);
    auto* manager = reinterpret_cast<ErrorManager*>(cinfo->err);
    manager->kind = "damaged JPEG";
    switch (cinfo->err->msg_code) {
    case JWRN_BOGUS_PROGRESSION:
    case JWRN_EXTRANEOUS_DATA:
    case JWRN_HIT_MARKER:
    case JWRN_HUFF_BAD_CODE:
    case JWRN_JPEG_EOF:
    case JWRN_MUST_RESYNC:
    case JWRN_NOT_SEQUENTIAL:
    case JWRN_TOO_MUCH_DATA:
        jumpOut(cinfo);
    default: // and the other "Corrupt JPEG data" warnings (JWRN_ARITH_BAD_CODE, ...)
        if (manager->problem.rfind("Corrupt JPEG data", 0) == 0)
            jumpOut(cinfo);
        manager->kind = "undecodable JPEG";
        ++cinfo->err->num_warnings;
    }
}

void limitScans(j_common_ptr cinfo)
{
    if (reinterpret_cast<j_decompress_ptr>(cinfo)->input_scan_number <= kMaxScans)
        return;
    auto* manager = reinterpret_cast<ErrorManager*>(cinfo->err);
    manager->problem = "more than " + std::to_string(kMaxScans) + " progressive scans";
    manager->kind = "refused JPEG";
    jumpOut(cinfo);
}

} // namespace

Result<cv::Mat> decodeJpeg(const std::string& path, const unsigned char* data, std::size_t size,
                           const FrameSizeCheck& check_size)
{
    // Everything longjmp returns past is made before setjmp: no destructor is skipped.
    jpeg_decompress_struct cinfo{};
    ErrorManager errors{};
    jpeg_progress_mgr progress{};
    cv::Mat bgr;
    cinfo.err = jpeg_std_error(&errors.pub);
    errors.pub.error_exit = onError;
    errors.pub.emit_message = onMessage;
    progress.progress_monitor = limitScans;
    if (setjmp(errors.jump)) {
        jpeg_destroy_decompress(&cinfo);
        return Error{"cannot read " + path + ": " + errors.kind + " (" + errors.problem + ")"};
    }
    jpeg_create_decompress(&cinfo);
    cinfo.progress = &progress;
    jpeg_mem_src(&cinfo, data, static_cast<unsigned long>(size));
    jpeg_read_header(&cinfo, TRUE);
    const auto refuse = [&cinfo](std::string message) {
        jpeg_destroy_decompress(&cinfo);
        return Error{std::move(message)};
    };
    // The frame header libjpeg itself found: the caller's look at the header may have been
    // misled (libjpeg skips fill bytes between markers, for one).
    if (auto refused = check_size(cinfo.image_width, cinfo.image_height))
        return refuse(std::move(refused->message));
    if (cinfo.jpeg_color_space == JCS_CMYK || cinfo.jpeg_color_space == JCS_YCCK)
        return refuse("cannot read " + path + ": a CMYK JPEG, not a camera frame");
    cinfo.out_color_space = JCS_EXT_BGR;
    jpeg_start_decompress(&cinfo);
    try {
        bgr.create(int(cinfo.output_height), int(cinfo.output_width), CV_8UC3);
    } catch (const cv::Exception&) {
        return refuse("cannot read " + path + ": out of memory for " +
                      std::to_string(cinfo.output_width) + "x" +
                      std::to_string(cinfo.output_height) + " pixels");
    }
    while (cinfo.output_scanline < cinfo.output_height) {
        JSAMPROW row = bgr.ptr(int(cinfo.output_scanline));
        jpeg_read_scanlines(&cinfo, &row, 1);
    }
    jpeg_finish_decompress(&cinfo);
    jpeg_destroy_decompress(&cinfo);
    return bgr;
}

} // namespace fieldsight::io
