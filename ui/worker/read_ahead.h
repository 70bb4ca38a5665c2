// Frames read ahead of the one shown, on a thread of their own: a 1280x720 PNG takes longer to
// decode and convert than the core takes to run it, so stepping through a large stream finds the
// next frames decoded and ready for display while the worker runs the current one.
#pragma once

#include "visioncore/basics/colour_lut.h"
#include "visioncore/io/stream_reader.h"

#include <QImage>

#include <opencv2/core/mat.hpp>

#include <chrono>
#include <condition_variable>
#include <cstddef>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <set>
#include <thread>
#include <vector>

namespace fieldsight::ui {

struct FrameSource;

/// A frame's pixels as the GUI shows them: made once per frame (and per LUT for the classified
/// view), shared read-only with every output of that frame, never written again.
struct FrameDisplay
{
    cv::Mat ycbcr; ///< a copy, or the frame's own buffer when it is never written again
    QImage raw;
    std::shared_ptr<const ColourLut> lut; ///< what `classified` and `classes` were made with
    QImage classified;
    cv::Mat classes;
};

/// Whether a display may keep its frame's pixel buffer instead of a copy of it.
enum class FramePixels {
    Copy,  ///< the buffer may be written again (a camera's, or one a reader reads into again)
    Share, ///< read into a Frame of its own and never written again: kept, not copied
};

/// Makes what is missing of `display` for `frame`: its pixels (a copy unless `pixels` says they
/// may be shared) and the raw image once, the classified image and class ids again when `lut`
/// (may be null) is not the one they were made with.
void makeFrameDisplay(const Frame& frame, const std::shared_ptr<const ColourLut>& lut,
                      FrameDisplay& display, FramePixels pixels);

/// The frame in colour-class colours (Format_RGB32, SPEC §1), and the class ids in `classes`.
QImage classifyFrame(const cv::Mat& ycbcr, const ColourLut& lut, cv::Mat& classes);

/// Reads frames of a file stream ahead on `threads` threads of its own, each with a reader of its
/// own (StreamReader::reopen); keeps at most `depth` of them.
class ReadAhead
{
public:
    struct Decoded
    {
        Frame frame;
        FrameDisplay display;
    };

    ReadAhead(std::size_t depth, std::size_t threads);
    ~ReadAhead(); ///< stops the thread (after the frame it is reading)
    ReadAhead(const ReadAhead&) = delete;
    ReadAhead& operator=(const ReadAhead&) = delete;

    /// Call on the thread that owns `source`'s reader (it is reopened here when `source` is new):
    /// frames first .. first + depth - 1 of `source` are wanted, their display made with `lut`;
    /// frames outside that range, or of another source, are dropped.
    void want(const std::shared_ptr<FrameSource>& source, std::size_t first,
              std::shared_ptr<const ColourLut> lut);
    /// Thread-safe. Lets go of `source`'s frames and reader (a stream no longer shown).
    void drop(const std::shared_ptr<FrameSource>& source);
    enum class State {
        Taken,   ///< the frame was read ahead: it is in `out`
        Reading, ///< wanted and not read yet (still so after `wait`)
        Absent,  ///< not wanted, or it could not be read: the caller reads it itself
    };
    /// Thread-safe. Frame `index` of `source`, taken out into `out` when it was read ahead;
    /// while it is wanted and not read yet, waits up to `wait` for it.
    State take(const std::shared_ptr<FrameSource>& source, std::size_t index, Decoded& out,
               std::chrono::milliseconds wait = std::chrono::milliseconds(0));

private:
    void loop(std::size_t thread);

    const std::size_t m_depth;
    std::mutex m_mutex;
    std::condition_variable m_wake; ///< the thread: something is wanted, or stop
    std::condition_variable m_done; ///< takers: a frame was read
    bool m_stop = false;
    const FrameSource* m_for = nullptr;     ///< under m_mutex: whose frames (identity only)
    std::weak_ptr<FrameSource> m_for_alive; ///< under m_mutex: m_for is not a reused address
    /// Under m_mutex: m_for's, reopened, one per thread (empty: nothing to read).
    std::vector<std::shared_ptr<StreamReader>> m_readers;
    std::set<std::size_t> m_reading; ///< frames a thread is reading now
    std::size_t m_frame_count = 0;
    std::size_t m_first = 0;
    std::shared_ptr<const ColourLut> m_lut;
    std::map<std::size_t, Decoded> m_ready;
    std::set<std::size_t> m_failed;     ///< frames that could not be read (the worker says why)
    std::vector<std::thread> m_threads; ///< last: they start once the rest is made
};

} // namespace fieldsight::ui
