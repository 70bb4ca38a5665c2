// Video files and live cameras through OpenCV videoio, converted to Y, Cb, Cr like RGB folders.
#include "io/stream_readers.h"

#include "visioncore/basics/atomic_file.h"
#include "visioncore/basics/ycbcr.h"

#include <opencv2/imgproc.hpp>
#include <opencv2/videoio.hpp>

#include <cmath>

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

class VideoReader final : public StreamReader
{
public:
    VideoReader(StreamInfo info, cv::VideoCapture capture)
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
        bool decoded_ok = false;
        try {
            if (m_info.kind == StreamKind::Video && index != m_next)
                m_capture.set(cv::CAP_PROP_POS_FRAMES, double(index));
            decoded_ok = m_capture.read(decoded) && !decoded.empty();
        } catch (const cv::Exception&) {
            decoded_ok = false;
        }
        if (!decoded_ok) {
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
    cv::VideoCapture m_capture;
    std::size_t m_next = 0; ///< the frame the capture will deliver next (video files)
};

/// VideoCapture::open, with a backend's exception taken as "cannot open".
bool openCapture(cv::VideoCapture& capture, const std::string& path, int device)
{
    try {
        return (path.empty() ? capture.open(device) : capture.open(path)) && capture.isOpened();
    } catch (const cv::Exception&) {
        return false;
    }
}

} // namespace

ReaderResult openVideo(const std::string& path, const std::string& spec)
{
    // The back ends open the file by name and would wait on a FIFO for a writer.
    if (Status s = checkRegularFile(path); !s)
        return s.error();
    cv::VideoCapture capture;
    if (!openCapture(capture, path, 0))
        return Error{path + ": not a stream (no image folder, .strm, or video OpenCV can open)"};
    StreamInfo info;
    info.path = spec;
    info.kind = StreamKind::Video;
    const double count = capture.get(cv::CAP_PROP_FRAME_COUNT);
    info.frame_count = std::isfinite(count) && count > 0 ? std::size_t(count) : 0;
    cv::Mat first;
    if (!capture.read(first) || first.empty())
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
    cv::VideoCapture capture;
    if (!openCapture(capture, std::string(), device))
        return Error{spec + ": cannot open camera " + std::to_string(device)};
    cv::Mat first;
    if (!capture.read(first) || first.empty())
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
