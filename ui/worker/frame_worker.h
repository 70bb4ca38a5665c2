// The worker that runs the core off the GUI thread: one ControlWrapper of its own, fed through a
// GuiDataWrapper, and a mailbox that keeps only the newest request, so a frame superseded by a
// newer step is dropped, not queued.
#pragma once

#include "ui/worker/gui_data_wrapper.h"
#include "ui/worker/read_ahead.h"
#include "visioncore/framework/control_wrapper.h"
#include "visioncore/services/layers.h"
#include "visioncore/datawrappers/camera_data_wrapper.h"
#include "visioncore/io/stream_reader.h"
#include "visioncore/services/stream_runner.h"

#include <QImage>
#include <QObject>
#include <QRectF>
#include <QString>

#include <atomic>
#include <chrono>
#include <cstdint>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

namespace fieldsight::ui {

/// An open stream as the worker reads it: a file stream's reader, or a live camera's own
/// DataWrapper (which captures on a thread of its own). Only the worker thread touches them.
struct FrameSource
{
    std::unique_ptr<StreamReader> reader;      ///< files: random access by index
    std::unique_ptr<CameraDataWrapper> camera; ///< live: the newest frame at each run
};

/// What one run uses; each version of the LUT or the settings is a new immutable object, so an
/// edit in the GUI never changes what a running worker reads.
struct FrameRequest
{
    std::uint64_t serial = 0;
    std::size_t index = 0;
    std::shared_ptr<FrameSource> source;
    std::shared_ptr<const ColourLut> lut;
    std::shared_ptr<const ParamSet> params; ///< values that differ from the defaults
    /// The stages' debug layers the core draws (ids from the pipeline's registry); the others
    /// cost nothing. The detections are drawn on every layer of theirs; the truth is the
    /// window's to draw (FrameView), not the worker's.
    LayerSet layers;
    /// "Follow the light": every frame's light from `lut`'s; a frame it covers is read through
    /// its light's input map (null: the table as it is).
    std::shared_ptr<const LightTrack> light;
    std::set<std::string, std::less<>> skip;
    std::chrono::steady_clock::time_point submitted = std::chrono::steady_clock::now();
    /// Answered already (from takeAhead): make `index` current and prepare the frame after it.
    bool look_ahead_only = false;
};

/// A detection as the view shows it: where it is, for hovering, and its numbers.
struct PerceptItem
{
    std::string layer; ///< the percept layer it is drawn on ("percepts.<kind key>")
    QRectF bounds;     ///< image px, pixel-centre coordinates
    QString label;     ///< short, drawn beside it (the kind's noun and a number)
    QString details;   ///< its fields, one per line
};

/// Everything the GUI shows of one frame, made on the worker thread and then only read.
struct FrameOutput
{
    std::uint64_t serial = 0;
    std::size_t index = 0;
    QString error;     ///< the frame could not be read or run; the rest is empty
    Frame frame;       ///< its own copy of the pixels
    QImage raw;        ///< RGB32, the frame as a person sees it
    QImage classified; ///< RGB32, every pixel in its colour class's display colour (SPEC §1)
    cv::Mat classes;   ///< CV_8U colour ids
    FrameResult result;
    std::vector<DebugDrawing> drawings; ///< the request's layers and the detections', in order
    LayerSet layers;                    ///< the stage layers asked for (FrameRequest::layers)
    std::vector<PerceptItem> items;
    double wait_ms = 0;   ///< from the request to the worker taking it up
    double worker_ms = 0; ///< read, run and convert
};

class FrameWorker : public QObject
{
    Q_OBJECT
public:
    /// Each run draws the stage layers its request asks for and every detection layer.
    explicit FrameWorker(const Pipeline& pipeline);

    /// Thread-safe. Replaces any request not yet started.
    void submit(FrameRequest request);
    /// Thread-safe. The output prepared ahead for exactly what `request` asks (the same source,
    /// frame, table, parameters and switches), taken out; null when there is none. While the user
    /// looks at a frame, the worker runs the next one with the same settings, so a step finds its
    /// answer ready on the GUI thread without waiting for a thread to wake.
    std::shared_ptr<FrameOutput> takeAhead(const FrameRequest& request);
    /// Thread-safe. The frame prepared ahead with `like`'s source, table, parameters and
    /// switches (the frame it asks for aside), if any: what a step there would be answered with.
    std::optional<std::size_t> aheadIndex(const FrameRequest& like);
    /// Thread-safe. Lets go of a source no longer shown, on the worker thread (closing a camera
    /// waits for its capture thread; a reader may close files), after any run still using it.
    void release(std::shared_ptr<FrameSource> source);

    /// Where the frames of file streams came from when a request made them current (counted
    /// since the worker was made; thread-safe to read).
    struct LoadCounts
    {
        std::atomic<std::uint64_t> read{0};       ///< read and decoded for the request
        std::atomic<std::uint64_t> read_ahead{0}; ///< from the read-ahead or the prefetch
        std::atomic<std::uint64_t> recent{0};     ///< shown lately: kept, not decoded again
    };
    const LoadCounts& loadCounts() const { return m_load_counts; }
    /// Frames shown lately kept decoded with their display, so stepping back finds them (a
    /// 1280x720 frame with its display is about 11 MB).
    static constexpr std::size_t kRecentFrames = 3;

signals:
    void frameDone(std::shared_ptr<const FrameOutput> output);

private:
    void processPending();
    std::shared_ptr<FrameOutput> run(const FrameRequest& request);
    /// Runs `control`'s core on `frame` (already in its DataWrapper) with the request's settings.
    void runCore(const FrameRequest& request, ControlWrapper& control,
                 std::shared_ptr<const ParamSet>& applied, const Frame& frame, FrameOutput& out);
    /// After a request: decodes the next frame and runs it with the request's settings, kept
    /// for takeAhead(); the current frame stays loaded.
    void lookAhead(const FrameRequest& request);
    /// Under m_mutex: the look-ahead's answer was made for `request` (any frame of it).
    bool aheadAnswers(const FrameRequest& request, bool any_frame) const;
    /// Swaps the loaded frame with the prefetched one (pixels, display, and which they are).
    void swapPrefetch();
    /// Makes frame `index` of `source` current in m_data: kept from the last run (a parameter
    /// or LUT edit), taken from the prefetch, or read.
    Status load(const std::shared_ptr<FrameSource>& source, std::size_t index);
    /// While idle, reads the frame after the current one and converts it for display with the
    /// last LUT, so the next step finds it ready.
    void prefetch();
    /// Keeps the current frame among the recent ones (it is no longer current after this).
    void keepRecent();
    /// Moves frame `index` of `source` out of the recent ones into `frame` and `display`; false
    /// when it is not there.
    bool takeRecent(const std::shared_ptr<FrameSource>& source, std::size_t index, Frame& frame,
                    FrameDisplay& display);

    using Display = FrameDisplay;
    /// The request's table, or a copy of it reading frame `index` through its light's map.
    std::shared_ptr<const ColourLut> lutFor(const FrameRequest& request, std::size_t index);

    const Pipeline& m_pipeline;
    LayerSet m_percept_layers; ///< drawn on every run: they cost no stage any work
    GuiDataWrapper m_data;
    ControlWrapper m_control;
    std::shared_ptr<const ParamSet> m_applied_params; ///< in m_control (null: the defaults)

    /// A live camera's own core: its ControlWrapper reads the camera's DataWrapper.
    std::shared_ptr<FrameSource> m_live_source;
    std::unique_ptr<ControlWrapper> m_live_control;
    std::shared_ptr<const ParamSet> m_live_params;
    std::vector<std::string> m_skippable;

    std::shared_ptr<FrameSource> m_frame_source; ///< what m_data's frame is, when valid
    std::size_t m_frame_index = 0;
    bool m_frame_valid = false;
    Display m_display; ///< of m_data's frame, when valid
    Frame m_prefetch;
    Display m_prefetch_display;
    std::shared_ptr<const ColourLut> m_last_lut;
    LightMapCache m_light_maps;
    std::shared_ptr<const ColourLut> m_light_base; ///< the table m_light_lut copies
    std::shared_ptr<const ColourLut> m_light_lut;  ///< with the last frame's light's map
    std::shared_ptr<FrameSource> m_prefetch_source;
    std::size_t m_prefetch_index = 0;
    /// The frames after the current one, read on two threads of their own: two 1280x720 PNGs
    /// decode in about the time the user takes for a step (4 frames with their displays are about
    /// 55 MB at that size).
    static constexpr std::size_t kReadAheadDepth = 4;
    ReadAhead m_read_ahead{kReadAheadDepth, 2};
    struct RecentFrame
    {
        std::shared_ptr<FrameSource> source;
        std::size_t index = 0;
        Frame frame;
        Display display;
    };
    std::vector<RecentFrame> m_recent; ///< the newest last; worker thread only
    LoadCounts m_load_counts;

    std::mutex m_mutex;
    std::optional<FrameRequest> m_pending;
    bool m_scheduled = false;
    std::shared_ptr<FrameOutput> m_ahead; ///< under m_mutex: the answer to m_ahead_for
    FrameRequest m_ahead_for;
    std::optional<std::size_t> m_last_index; ///< of the last request taken up
    std::uint64_t m_taken = 0;               ///< requests taken up (worker thread only)
};

/// The percept items of one frame's detections.
std::vector<PerceptItem> perceptItems(const PerceptSet& percepts);

} // namespace fieldsight::ui
