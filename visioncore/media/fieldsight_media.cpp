// The media module: OpenCV's videoio and imgcodecs behind the function table of media_api.h,
// loaded by the core only when it needs them (src/io/media.cpp). Exceptions stay inside.
#include "io/media_api.h"

#include <opencv2/imgcodecs.hpp>
#include <opencv2/videoio.hpp>

#include <cmath>
#include <limits>
#include <memory>

namespace {

using fieldsight::io::MediaApi;

void* open(const char* path, int device)
{
    auto capture = std::make_unique<cv::VideoCapture>();
    try {
        const bool opened = path && *path ? capture->open(path) : capture->open(device);
        if (!opened || !capture->isOpened())
            return nullptr;
    } catch (const cv::Exception&) {
        return nullptr;
    }
    return capture.release();
}

bool read(void* capture, cv::Mat& out)
{
    try {
        return static_cast<cv::VideoCapture*>(capture)->read(out) && !out.empty();
    } catch (const cv::Exception&) {
        return false;
    }
}

double get(void* capture, int property)
{
    try {
        return static_cast<cv::VideoCapture*>(capture)->get(property);
    } catch (const cv::Exception&) {
        return std::numeric_limits<double>::quiet_NaN();
    }
}

bool set(void* capture, int property, double value)
{
    try {
        return static_cast<cv::VideoCapture*>(capture)->set(property, value);
    } catch (const cv::Exception&) {
        return false;
    }
}

void close(void* capture)
{
    delete static_cast<cv::VideoCapture*>(capture);
}

bool decode(const unsigned char* data, std::size_t size, int flags, cv::Mat& out,
            std::string& error)
{
    try {
        out = cv::imdecode(cv::Mat(1, int(size), CV_8U, const_cast<unsigned char*>(data)), flags);
        return true;
    } catch (const cv::Exception& e) {
        error = e.err;
        return false;
    }
}

bool encode(const char* extension, const cv::Mat& image, const std::vector<int>& params,
            std::vector<unsigned char>& out, std::string& error)
{
    try {
        if (cv::imencode(extension, image, out, params))
            return true;
        error = std::string("no encoder for ") + extension;
    } catch (const cv::Exception& e) {
        error = e.err;
    }
    return false;
}

bool writeVideo(const char* path, const char* fourcc, double fps,
                const std::vector<cv::Mat>& frames, std::string& error)
{
    if (frames.empty() || std::char_traits<char>::length(fourcc) != 4) {
        error = "no frames, or a codec name that is not four characters";
        return false;
    }
    try {
        cv::VideoWriter writer(path,
                               cv::VideoWriter::fourcc(fourcc[0], fourcc[1], fourcc[2], fourcc[3]),
                               fps, frames.front().size());
        if (!writer.isOpened()) {
            error = std::string("no video writer for ") + fourcc;
            return false;
        }
        for (const cv::Mat& frame : frames)
            writer.write(frame);
        return true;
    } catch (const cv::Exception& e) {
        error = e.err;
        return false;
    }
}

constexpr MediaApi kApi{
    fieldsight::io::kMediaApiVersion, open, read, get, set, close, decode, encode, writeVideo};

} // namespace

extern "C" __attribute__((visibility("default"))) const MediaApi* fieldsight_media_api()
{
    return &kApi;
}
