// Video files and live cameras through OpenCV videoio (in the media module, loaded when a video
// or a camera is opened), converted to Y, Cb, Cr like RGB folders.
#include "io/media.h"
#include "io/stream_readers.h"

#include "visioncore/basics/atomic_file.h"
#include "visioncore/basics/ycbcr.h"

#include <opencv2/imgproc.hpp>
#include <opencv2/videoio.hpp> // the cv::CAP_PROP_* constants only

#include <cmath>
#include <optional>
#include <utility>

namespace fieldsight::io {

namespace {

/// Brings a decoded frame to 8-bit BGR (cameras may deliver grey or 4-channel images).
cv::Mat toBgr(const cv::Mat& image)
{
    if (image.type() == CV_8UC3)
        return image;
    cv::Mat bgr;
    if (image.channels() == 1)
        cv::cvtColor(image, bgr, cv::COLOR_GRAY2BGR);
    else if (image.channels() == 4)
        cv::cvtColor(image, bgr, cv::COLOR_BGRA2BGR);
    else
        bgr = image;
    if (bgr.depth() != CV_8U)
        bgr.convertTo(bgr, CV_8U);
    return bgr;
}

/// A cv::VideoCapture in the media module, closed with its owner.
class Capture
{
public:
    Capture(const MediaApi* api, void* handle) : m_api(api), m_handle(handle) {}
    Capture(Capture&& other) noexcept
        : m_api(other.m_api), m_handle(std::exchange(other.m_handle, nullptr))
    {
    }
    Capture& operator=(Capture&&) = delete;
    ~Capture()
    {
        if (m_handle)
            m_api->close(m_handle);
    }

    bool read(cv::Mat& out) { return m_api->read(m_handle, out); }
    double get(int property) const { return m_api->get(m_handle, property); }
    bool set(int property, double value) { return m_api->set(m_handle, property, value); }

private:
    const MediaApi* m_api;
    void* m_handle;
};

class VideoReader final : public StreamReader
{
public:
    VideoReader(StreamInfo info, Capture capture)
        : m_info(std::move(info)), m_capture(std::move(capture))
    {
    }

    const StreamInfo& info() const override { return m_info; }
    std::string frameName(std::size_t index) const override { return indexedFrameName(index); }

    Result<Frame> read(std::size_t index) override
    {
        if (m_info.kind == StreamKind::Video && index >= m_info.frame_count)
            return Error{m_info.path + ": frame " + std::to_string(index) + " out of range (" +
                         std::to_string(m_info.frame_count) + " frames)"};
        // Seeking is slow (back to a key frame and decode forward), so only when not sequential.
        cv::Mat decoded;
        if (m_info.kind == StreamKind::Video && index != m_next)
            m_capture.set(cv::CAP_PROP_POS_FRAMES, double(index));
        if (!m_capture.read(decoded)) {
            m_next = std::size_t(-1); // position unknown: seek before the next read
            return Error{m_info.path + ": cannot decode frame " + std::to_string(index)};
        }
        m_next = index + 1;
        Frame frame;
        frame.ycbcr = bgrToYcbcr(toBgr(decoded));
        if (frame.ycbcr.cols != m_info.width || frame.ycbcr.rows != m_info.height)
            return Error{m_info.path + ": frame " + std::to_string(index) + " is " +
                         std::to_string(frame.ycbcr.cols) + "x" + std::to_string(frame.ycbcr.rows) +
                         ", the stream is " + std::to_string(m_info.width) + "x" +
                         std::to_string(m_info.height)};
        frame.name = indexedFrameName(index);
        const double pos_ms = m_capture.get(cv::CAP_PROP_POS_MSEC);
        frame.timestamp_ms = std::isfinite(pos_ms) && pos_ms > 0 ? pos_ms : 0.0;
        return frame;
    }

private:
    StreamInfo m_info;
    Capture m_capture;
    std::size_t m_next = 0; ///< the frame the capture will deliver next (video files)
};

/// A capture of the file `path`, or of camera `device` when `path` is empty; nullopt when the
/// back ends cannot open it (or throw), an Error when the media module is not there.
Result<std::optional<Capture>> openCapture(const std::string& path, int device)
{
    auto api = mediaApi();
    if (!api)
        return api.error();
    void* handle = api.value()->open(path.c_str(), device);
    if (!handle)
        return std::optional<Capture>();
    return std::optional<Capture>(Capture(api.value(), handle));
}

} // namespace

ReaderResult openVideo(const std::string& path, const std::string& spec)
{
    // The back ends open the file by name and would wait on a FIFO for a writer.
    if (Status s = checkRegularFile(path); !s)
        return s.error();
    auto opened = openCapture(path, 0);
    if (!opened)
        return Error{path + ": " + opened.error().message};
    if (!opened.value())
        return Error{path + ": not a stream (no image folder, .strm, or video OpenCV can open)"};
    Capture& capture = *opened.value();
    StreamInfo info;
    info.path = spec;
    info.kind = StreamKind::Video;
    const double count = capture.get(cv::CAP_PROP_FRAME_COUNT);
    info.frame_count = std::isfinite(count) && count > 0 ? std::size_t(count) : 0;
    cv::Mat first;
    if (!capture.read(first))
        return Error{path + ": cannot decode the first video frame"};
    if (!isSaneFrameSize(first.cols, first.rows))
        return Error{path + ": absurd frame size " + std::to_string(first.cols) + "x" +
                     std::to_string(first.rows)};
    if (info.frame_count == 0)
        return Error{path + ": the video does not report its frame count"};
    info.width = first.cols;
    info.height = first.rows;
    capture.set(cv::CAP_PROP_POS_FRAMES, 0.0);
    return std::unique_ptr<StreamReader>(new VideoReader(std::move(info), std::move(capture)));
}

// A camera has no frame count (0 = unknown) and no random access: read(i) always returns the next
// live frame, named "frame_<i>"; `i` is not used to seek.
ReaderResult openCamera(int device, const std::string& spec)
{
    auto opened = openCapture(std::string(), device);
    if (!opened)
        return Error{spec + ": " + opened.error().message};
    if (!opened.value())
        return Error{spec + ": cannot open camera " + std::to_string(device)};
    Capture& capture = *opened.value();
    cv::Mat first;
    if (!capture.read(first))
        return Error{spec + ": the camera delivered no frame"};
    if (!isSaneFrameSize(first.cols, first.rows))
        return Error{spec + ": absurd frame size " + std::to_string(first.cols) + "x" +
                     std::to_string(first.rows)};
    StreamInfo info;
    info.path = spec;
    info.kind = StreamKind::Camera;
    info.frame_count = 0;
    info.width = first.cols;
    info.height = first.rows;
    return std::unique_ptr<StreamReader>(new VideoReader(std::move(info), std::move(capture)));
}

} // namespace fieldsight::io
