// Frames read and converted for display ahead of the one shown (see read_ahead.h).
#include "ui/worker/read_ahead.h"

#include "ui/adapters/image_adapter.h"
#include "ui/worker/frame_worker.h"

#include <array>

namespace fieldsight::ui {

QImage classifyFrame(const cv::Mat& ycbcr, const ColourLut& lut, cv::Mat& classes)
{
    if (ycbcr.empty() || ycbcr.type() != CV_8UC3)
        return {};
    std::array<QRgb, 256> palette{};
    for (int c = 0; c < kColourCount; ++c) {
        const Rgb rgb = colourDisplayRgb(Colour(c));
        palette[std::size_t(c)] = qRgb(rgb.r, rgb.g, rgb.b);
    }
    lut.classifyImage(ycbcr, classes);
    QImage classified(ycbcr.cols, ycbcr.rows, QImage::Format_RGB32);
    if (classified.isNull())
        return classified;
    for (int y = 0; y < ycbcr.rows; ++y) {
        const std::uint8_t* ids = classes.ptr<std::uint8_t>(y);
        auto* out = reinterpret_cast<QRgb*>(classified.scanLine(y));
        for (int x = 0; x < ycbcr.cols; ++x)
            out[x] = palette[ids[x]];
    }
    return classified;
}

void makeFrameDisplay(const Frame& frame, const std::shared_ptr<const ColourLut>& lut,
                      FrameDisplay& display, FramePixels pixels)
{
    // Fresh buffers every time: the old ones may still be shown by the GUI.
    if (display.ycbcr.empty()) {
        display.ycbcr = pixels == FramePixels::Share ? frame.ycbcr : frame.ycbcr.clone();
        display.raw = ycbcrToZoomedQImage(display.ycbcr, 1);
    }
    if (lut && display.lut != lut) {
        display.lut = lut;
        display.classes = cv::Mat();
        display.classified = classifyFrame(display.ycbcr, *lut, display.classes);
    }
}

ReadAhead::ReadAhead(std::size_t depth, std::size_t threads) : m_depth(depth)
{
    for (std::size_t i = 0; i < std::max<std::size_t>(1, threads); ++i)
        m_threads.emplace_back([this, i] { loop(i); });
}

ReadAhead::~ReadAhead()
{
    {
        std::lock_guard lock(m_mutex);
        m_stop = true;
    }
    m_wake.notify_all();
    for (std::thread& thread : m_threads)
        thread.join();
}

void ReadAhead::want(const std::shared_ptr<FrameSource>& source, std::size_t first,
                     std::shared_ptr<const ColourLut> lut)
{
    std::unique_lock lock(m_mutex);
    const bool same = source && source.get() == m_for && m_for_alive.lock() == source;
    if (!same) {
        m_ready.clear();
        m_failed.clear();
        m_readers.clear();
        m_for = nullptr;
        m_for_alive.reset();
        if (!source || !source->reader)
            return;    // a live camera has no frames ahead
        lock.unlock(); // reopening may read a folder's listing
        std::vector<std::shared_ptr<StreamReader>> readers;
        for (std::size_t i = 0; i < m_threads.size(); ++i) {
            auto reader = source->reader->reopen();
            if (!reader)
                return; // the worker reads every frame itself
            readers.push_back(std::move(reader).value());
        }
        lock.lock();
        m_readers = std::move(readers);
        m_frame_count = m_readers.front()->info().frame_count;
        m_for = source.get();
        m_for_alive = source;
    }
    m_first = first;
    m_lut = std::move(lut);
    for (auto it = m_ready.begin(); it != m_ready.end();)
        it = it->first < m_first || it->first >= m_first + m_depth ? m_ready.erase(it)
                                                                   : std::next(it);
    lock.unlock();
    m_wake.notify_all();
    m_done.notify_all(); // a taker waiting for a frame no longer wanted
}

void ReadAhead::drop(const std::shared_ptr<FrameSource>& source)
{
    std::lock_guard lock(m_mutex);
    if (!source || source.get() != m_for)
        return;
    m_ready.clear();
    m_failed.clear();
    m_readers.clear(); // a thread lets go of its copy after the frame it is reading
    m_for = nullptr;
    m_for_alive.reset();
}

ReadAhead::State ReadAhead::take(const std::shared_ptr<FrameSource>& source, std::size_t index,
                                 Decoded& out, std::chrono::milliseconds wait)
{
    std::unique_lock lock(m_mutex);
    const auto state = [&] {
        if (!source || source.get() != m_for || m_readers.empty() || m_failed.count(index))
            return State::Absent;
        if (m_ready.count(index))
            return State::Taken;
        const bool wanted = index >= m_first && index < m_first + m_depth && index < m_frame_count;
        return wanted ? State::Reading : State::Absent;
    };
    State now = state();
    if (now == State::Reading && wait.count() > 0) {
        m_done.wait_for(lock, wait, [&] { return state() != State::Reading; });
        now = state();
    }
    if (now == State::Taken) {
        const auto it = m_ready.find(index);
        out = std::move(it->second);
        m_ready.erase(it);
    }
    return now;
}

void ReadAhead::loop(std::size_t thread)
{
    std::unique_lock lock(m_mutex);
    for (;;) {
        // The first wanted frame not read yet, of the source wanted now.
        std::optional<std::size_t> next;
        if (!m_readers.empty())
            for (std::size_t i = m_first; i < m_first + m_depth && i < m_frame_count; ++i)
                if (!m_ready.count(i) && !m_failed.count(i) && !m_reading.count(i)) {
                    next = i;
                    break;
                }
        if (m_stop)
            return;
        if (!next) {
            m_wake.wait(lock);
            continue;
        }
        const std::shared_ptr<StreamReader> reader = m_readers[thread];
        m_reading.insert(*next);
        const std::shared_ptr<const ColourLut> lut = m_lut;
        const FrameSource* source = m_for;
        lock.unlock();
        Decoded decoded;
        bool ok = false;
        try {
            // A Frame of its own, never read into again: the display shares its pixels.
            ok = reader->readInto(*next, decoded.frame).ok();
            if (ok)
                makeFrameDisplay(decoded.frame, lut, decoded.display, FramePixels::Share);
        } catch (const std::exception&) {
            ok = false; // the worker's own read of that frame reports it
        }
        lock.lock();
        m_reading.erase(*next);
        if (m_readers.empty() || m_readers[thread] != reader || m_for != source ||
            *next < m_first || *next >= m_first + m_depth)
            continue; // wanted no more
        // A frame that cannot be read is left to the worker, whose own read says why.
        if (!ok)
            m_failed.insert(*next);
        else
            m_ready.emplace(*next, std::move(decoded));
        m_done.notify_all();
    }
}

} // namespace fieldsight::ui
