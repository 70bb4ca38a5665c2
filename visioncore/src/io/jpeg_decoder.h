// JPEG frames decoded with libjpeg directly, not through cv::imdecode, so that the library's own
// messages ("Corrupt JPEG data: ...") become Fieldsight's one line instead of stderr lines.
#pragma once

#include "visioncore/basics/result.h"

#include <opencv2/core.hpp>

#include <cstddef>
#include <functional>
#include <optional>
#include <string>

namespace fieldsight::io {

/// Why a frame of `width` x `height` px is refused before its pixels are decoded, or nullopt.
using FrameSizeCheck = std::function<std::optional<Error>(long long width, long long height)>;

/// The BGR pixels of the JPEG `data` read from `path` (grey JPEGs expanded to three channels),
/// or an Error naming `path`. Refused before any pixel is decoded: a frame header that
/// `check_size` refuses (on libjpeg's own reading of it), CMYK data. Refused while decoding:
/// libjpeg's errors, its warnings that say the data is damaged (bytes before a marker, a
/// premature end, a bad Huffman code), more than 500 progressive scans. Harmless warnings (an
/// unknown JFIF revision) are ignored. No EXIF rotation: frames are taken as the camera stored
/// them.
Result<cv::Mat> decodeJpeg(const std::string& path, const unsigned char* data, std::size_t size,
                           const FrameSizeCheck& check_size);

} // namespace fieldsight::io
