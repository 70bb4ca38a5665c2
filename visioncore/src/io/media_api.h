// The table of functions the media module (libfieldsight_media.so) gives the core: OpenCV's
// videoio and imgcodecs behind one door. Those two libraries pull in GDAL, FFmpeg and GStreamer,
// about 220 shared libraries that cost every process 0.17 s to load and relocate; the core loads
// them only when a stream is a video or a camera, or a picture is BMP (media.h). Both sides are
// built by the same project with the same compiler, so the table may carry C++ types.
#pragma once

#include <opencv2/core/mat.hpp>

#include <cstddef>
#include <string>
#include <vector>

namespace fieldsight::io {

struct MediaApi
{
    int version; ///< kMediaApiVersion of the module's build

    /// A video file or a camera (path empty: `device`) opened with cv::VideoCapture, or nullptr.
    void* (*open)(const char* path, int device);
    /// The next frame into `out`; false at the end or on a decoder's failure (or exception).
    bool (*read)(void* capture, cv::Mat& out);
    /// VideoCapture::get and set (cv::CAP_PROP_*); NaN and false on an exception.
    double (*get)(void* capture, int property);
    bool (*set)(void* capture, int property, double value);
    void (*close)(void* capture);

    /// cv::imdecode; false with the codec's message in `error` when it throws.
    bool (*decode)(const unsigned char* data, std::size_t size, int flags, cv::Mat& out,
                   std::string& error);
    /// cv::imencode with the format of `extension` (".png") and its parameters.
    bool (*encode)(const char* extension, const cv::Mat& image, const std::vector<int>& params,
                   std::vector<unsigned char>& out, std::string& error);
    /// cv::VideoWriter: `frames` (8-bit BGR, all one size) into `path` with the codec `fourcc`.
    bool (*writeVideo)(const char* path, const char* fourcc, double fps,
                       const std::vector<cv::Mat>& frames, std::string& error);
};

inline constexpr int kMediaApiVersion = 1;

/// The one symbol the module exports.
inline constexpr const char* kMediaApiSymbol = "fieldsight_media_api";
using MediaApiEntry = const MediaApi* (*)();

} // namespace fieldsight::io
