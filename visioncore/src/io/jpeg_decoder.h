// JPEG frames decoded with libjpeg directly, not through cv::imdecode, so that the library's own
// messages ("Corrupt JPEG data: ...") become Fieldsight's one line instead of stderr lines.
#pragma once

#include "visioncore/result.h"

#include <opencv2/core.hpp>

#include <cstddef>
#include <optional>
#include <string>

namespace fieldsight::io {

/// The BGR pixels of the JPEG `data` read from `path` (grey JPEGs expanded to three channels),
/// or an Error naming `path`. Refused before any pixel is decoded: a frame header larger than
/// `max_side` a side, or of another size than `expected` (the stream's, once known), CMYK data.
/// Refused while decoding: libjpeg's errors, its warnings that say the data is damaged (bytes
/// before a marker, a premature end, a bad Huffman code), more than 500 progressive scans.
/// Harmless warnings (an unknown JFIF revision) are ignored. No EXIF rotation: frames are taken
/// as the camera stored them.
Result<cv::Mat> decodeJpeg(const std::string& path, const unsigned char* data, std::size_t size,
                           int max_side, std::optional<cv::Size> expected);

} // namespace fieldsight::io
