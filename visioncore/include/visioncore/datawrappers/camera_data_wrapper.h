// The live camera's DataWrapper: a capture thread reads the camera continuously and keeps only
// the newest frame, so the core always sees what the robot sees now, never a frame that waited in
// the driver's queue while the core (or a person at the GUI) was busy.
#pragma once

#include "visioncore/framework/data_wrapper.h"
#include "visioncore/io/frame.h"
#include "visioncore/io/stream_reader.h"
#include "visioncore/basics/result.h"

#include <chrono>
#include <condition_variable>
#include <cstddef>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>

namespace fieldsight {

class CameraDataWrapper : public DataWrapper
{
public:
    /// Starts capturing from `camera`: a live reader (openStream("camera:N")), or any reader whose
    /// successive reads stand in for one. Capture stops at the first read that fails (a camera
    /// unplugged, the end of a stand-in); latch() then reports that error.
    CameraDataWrapper(std::unique_ptr<StreamReader> camera, std::shared_ptr<const ColourLut> lut);
    /// Stops the capture thread (waits for the read in progress, at most one camera frame).
    ~CameraDataWrapper() override;
    CameraDataWrapper(const CameraDataWrapper&) = delete;
    CameraDataWrapper& operator=(const CameraDataWrapper&) = delete;

    /// Makes the newest captured frame current, waiting up to `timeout` for one not latched
    /// before. The frame then stays unchanged until the next latch. An Error when the camera
    /// failed, or when no new frame came in time (the current frame is kept).
    Status latch(std::chrono::milliseconds timeout);

    /// The current (latched) frame.
    const Frame& frame() const { return m_current; }
    const StreamInfo& info() const { return m_info; }
    /// Frames read from the camera so far, and how many of them were replaced by a newer one
    /// before anyone latched them.
    std::size_t captured() const;
    std::size_t dropped() const;

    void setLut(std::shared_ptr<const ColourLut> lut) { m_lut = std::move(lut); }
    void setDebugSink(DebugSink* sink) { m_sink = sink; }

    const cv::Mat& image() const override { return m_current.ycbcr; }
    Horizon kinematicHorizon() const override { return m_current.horizon.value_or(Horizon{}); }
    const ColourLut& lut() const override { return *m_lut; }
    DebugSink* debugSink() override { return m_sink; }

private:
    void capture();

    std::unique_ptr<StreamReader> m_camera; ///< used only by the capture thread
    StreamInfo m_info;
    std::shared_ptr<const ColourLut> m_lut;
    DebugSink* m_sink = nullptr;
    Frame m_current;

    mutable std::mutex m_mutex;
    std::condition_variable m_changed;
    std::optional<Frame> m_newest; ///< captured and not latched yet
    std::optional<std::string> m_failure;
    std::size_t m_captured = 0;
    std::size_t m_dropped = 0;
    bool m_stop = false;
    std::thread m_thread; ///< last: starts after everything it uses exists
};

} // namespace fieldsight
