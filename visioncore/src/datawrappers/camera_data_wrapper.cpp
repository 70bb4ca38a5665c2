#include "visioncore/datawrappers/camera_data_wrapper.h"

#include <utility>

namespace fieldsight {

CameraDataWrapper::CameraDataWrapper(std::unique_ptr<StreamReader> camera,
                                     std::shared_ptr<const ColourLut> lut)
    : m_camera(std::move(camera)), m_info(m_camera->info()), m_lut(std::move(lut)),
      m_thread([this] { capture(); })
{
}

CameraDataWrapper::~CameraDataWrapper()
{
    {
        std::lock_guard lock(m_mutex);
        m_stop = true;
    }
    m_thread.join();
}

void CameraDataWrapper::capture()
{
    Frame frame;
    for (std::size_t index = 0;; ++index) {
        {
            std::lock_guard lock(m_mutex);
            if (m_stop)
                return;
        }
        Status status = m_camera->readInto(index, frame);
        std::lock_guard lock(m_mutex);
        if (!status) {
            m_failure = status.error().message;
            m_changed.notify_all();
            return;
        }
        if (m_newest)
            ++m_dropped;
        ++m_captured;
        // A fresh buffer for the next read: the latched frame may still share this one.
        m_newest = std::exchange(frame, Frame{});
        m_changed.notify_all();
    }
}

Status CameraDataWrapper::latch(std::chrono::milliseconds timeout)
{
    std::unique_lock lock(m_mutex);
    m_changed.wait_for(lock, timeout, [this] { return m_newest || m_failure; });
    if (m_newest) {
        m_current = std::move(*m_newest);
        m_newest.reset();
        return {};
    }
    if (m_failure)
        return Error{*m_failure};
    return Error{m_info.path + ": no frame from the camera within " +
                 std::to_string(timeout.count()) + " ms"};
}

std::size_t CameraDataWrapper::captured() const
{
    std::lock_guard lock(m_mutex);
    return m_captured;
}

std::size_t CameraDataWrapper::dropped() const
{
    std::lock_guard lock(m_mutex);
    return m_dropped;
}

} // namespace fieldsight
