// cv::imread, cv::imwrite and cv::imencode for the suites, through the core's media module
// (visioncore/io/image_files.h), so that the test runners do not link OpenCV's codecs and start
// in a tenth of the time. Same results, same codecs.
#pragma once

#include "visioncore/io/image_files.h"

#include <string>
#include <vector>

namespace fieldsight::test {

/// The decoded picture, or an empty Mat (as cv::imread).
inline cv::Mat imread(const std::string& path, int flags = cv::IMREAD_COLOR)
{
    auto image = readImage(path, flags);
    return image ? std::move(image.value()) : cv::Mat();
}

/// True when written (as cv::imwrite).
inline bool imwrite(const std::string& path, const cv::Mat& image,
                    const std::vector<int>& params = {})
{
    return bool(writeImage(path, image, params));
}

/// True when encoded (as cv::imencode).
inline bool imencode(const std::string& extension, const cv::Mat& image,
                     std::vector<unsigned char>& out, const std::vector<int>& params = {})
{
    auto bytes = encodeImage(extension, image, params);
    if (!bytes)
        return false;
    out = std::move(bytes.value());
    return true;
}

} // namespace fieldsight::test
