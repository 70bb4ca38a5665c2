// Pictures through OpenCV's codecs (cv::imdecode, cv::imencode), which the core reaches through its
// media module, loaded on first use: a process that never decodes a BMP, writes a PNG this way or
// opens a video does not load them (src/io/media_api.h says why). Stream folders' PNG and JPEG
// frames are decoded with libpng and libjpeg directly and do not come here.
#pragma once

#include "visioncore/basics/result.h"

#include <opencv2/core/mat.hpp>
#include <opencv2/imgcodecs.hpp> // the cv::IMREAD_* and cv::IMWRITE_* constants only

#include <cstddef>
#include <string>
#include <vector>

namespace fieldsight {

/// cv::imdecode of `size` bytes; an empty Mat when no codec reads them. `source` names the bytes
/// in errors (a file's path).
Result<cv::Mat> decodeImage(const unsigned char* data, std::size_t size, int flags,
                            const std::string& source);
/// cv::imencode in the format named by `extension` (".png", ".jpg", ".bmp").
Result<std::vector<unsigned char>> encodeImage(const std::string& extension, const cv::Mat& image,
                                               const std::vector<int>& params = {});
/// cv::imread: the file decoded, or an error naming it (missing, unreadable, not a picture).
Result<cv::Mat> readImage(const std::string& path, int flags = cv::IMREAD_COLOR);
/// cv::imwrite in the format of the path's extension, written atomically.
Status writeImage(const std::string& path, const cv::Mat& image,
                  const std::vector<int>& params = {});
/// cv::VideoWriter: `frames` (8-bit BGR, one size) as a video at `path`, with the codec named by
/// its four characters ("MJPG").
Status writeVideo(const std::string& path, const std::string& fourcc, double fps,
                  const std::vector<cv::Mat>& frames);

} // namespace fieldsight
