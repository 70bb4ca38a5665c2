// JPEG frames decoded with libjpeg directly, not through cv::imdecode, so that the library's own
// messages ("Corrupt JPEG data: ...") become Fieldsight's one line instead of stderr lines.
#pragma once

#include "visioncore/result.h"

#include <opencv2/core.hpp>

#include <cstddef>

namespace fieldsight::io {

/// The BGR pixels of the JPEG in `data` (grey JPEGs expanded to three channels), or the problem
/// (without the file's name): libjpeg's error, or one of its warnings that says the data is
/// damaged (bytes before a marker, a premature end, a bad Huffman code). Harmless warnings (an
/// unknown JFIF revision) are ignored. No EXIF rotation: frames are taken as the camera stored
/// them. A header larger than `max_side` a side, CMYK data, or more than 500 progressive scans
/// is refused before the pixels are decoded.
Result<cv::Mat> decodeJpeg(const unsigned char* data, std::size_t size, int max_side);

} // namespace fieldsight::io
