// PNG frames decoded with libpng directly, not through cv::imdecode, so that the library's own
// lines ("libpng error: ...", "libpng warning: ...") never reach stderr: its errors become
// Fieldsight's one line, its warnings are dropped.
#pragma once

#include "io/jpeg_decoder.h"

namespace fieldsight::io {

/// The BGR pixels of the PNG `data` read from `path`, as cv::imdecode with IMREAD_COLOR gives
/// them (16-bit samples cut to 8, grey and palettes expanded, alpha dropped), or an Error naming
/// `path`. Refused before any pixel is decoded: a header that `check_size` refuses. Refused while
/// decoding: whatever libpng calls an error (an invalid header, a missing palette, damaged
/// compressed data, too little image data). Its warnings (an ancillary chunk it ignores, extra
/// data after the image) are not: the pixels are whole.
Result<cv::Mat> decodePng(const std::string& path, const unsigned char* data, std::size_t size,
                          const FrameSizeCheck& check_size);

} // namespace fieldsight::io
