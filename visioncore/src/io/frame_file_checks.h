// One image file of a folder stream read with its checks: the size its header claims and a PNG's
// or BMP's damage found before any decoder sees the bytes, then decoded to BGR.
#pragma once

#include "visioncore/basics/result.h"

#include <opencv2/core/mat.hpp>

#include <optional>
#include <string>

namespace fieldsight::io {

struct HeaderSize
{
    long long width = 0;
    long long height = 0;
};

/// Why a frame of `path` whose header claims (or whose pixels are) `width` x `height` is refused,
/// or nullopt: more than kMaxFrameSide a side, or another size than `expected` (the stream's,
/// once known). One rule for the header, libjpeg's reading of it and the decoded frame.
std::optional<Error> refusedFrameSize(const std::string& path, long long width, long long height,
                                      std::optional<HeaderSize> expected);

/// An image file's pixels as BGR, or an Error naming the file: read with the checks of every
/// read (a FIFO or device is refused, not waited on), the header's size and a PNG's chunks
/// checked before the decoder sees the bytes. When `expected` is given (the stream's size, known
/// once its first frame is read), a header claiming another size is refused before decoding: a
/// 100-byte file cannot make a 32x24 stream decode 200 MB.
Result<cv::Mat> decodeImageFile(const std::string& path,
                                std::optional<HeaderSize> expected = std::nullopt);

} // namespace fieldsight::io
