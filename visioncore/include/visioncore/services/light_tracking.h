// A table that follows the light: per frame, in stream order, the light's R, G, B gains relative
// to the light the table was made for, estimated from the carpet and the white it classifies,
// robust to one frame's outlier and smoothed over the frames. The commands (--adapt) and the
// window's "Follow the light" both use it, so a frame's light never depends on who asks.
#pragma once

#include "visioncore/basics/colour_lut.h"
#include "visioncore/basics/geometry.h"
#include "visioncore/basics/lut_input_map.h"
#include "visioncore/basics/result.h"
#include "visioncore/io/stream_reader.h"

#include <opencv2/core/mat.hpp>

#include <array>
#include <atomic>
#include <cstddef>
#include <deque>
#include <functional>
#include <memory>
#include <optional>
#include <vector>

namespace fieldsight {

class TableLevelCheck;

/// Levels of the light, ln gain of the green channel relative to the table's light (0): from `lo`
/// to `hi`, either infinite where open.
struct LevelRange
{
    double lo = 0;
    double hi = 0;
};

struct LightTrackingOptions
{
    int sample_step = 8;            ///< px between samples along a row, and rows between rows
    int reference_frames = 5;       ///< first frames with enough samples that set the reference
    std::size_t min_samples = 40;   ///< carpet and white samples a frame needs to count
    double max_step = 0.12;         ///< largest |ln gain| a frame may move from the state
    double max_disagreement = 0.04; ///< ln; classes further apart than this do not agree
    int outlier_patience = 4;       ///< outliers in a row, each within max_step of the last,
                                    ///< after which the light has changed (up to median_window
                                    ///< frames with too few samples between two do not break
                                    ///< the row, others do)
    int median_window = 7;          ///< accepted estimates the course is fitted through
    double smoothing = 0.75;        ///< share of the way to the course that the state moves
};

/// The light of one frame, relative to the light the table was made for.
struct LightState
{
    /// What the frame did to the state.
    enum class Verdict {
        Reference,    ///< one of the first frames: it set the reference, the state stayed
        Followed,     ///< its estimate moved the state
        Sparse,       ///< too few carpet and white samples (a jersey filling the view): ignored
        Outlier,      ///< its estimate was far from the state (a flash): ignored
        Inconsistent, ///< the carpet's and the white's colour moved apart (not the light's doing)
        Unread,       ///< the frame could not be read: ignored
    };
    std::array<double, 3> gain{1, 1, 1};     ///< R, G, B of the frame's light over the table's
    std::array<double, 3> estimate{1, 1, 1}; ///< this frame's own estimate (Followed, Outlier)
    std::size_t samples = 0;                 ///< carpet and white samples the frame gave
    Verdict verdict = Verdict::Reference;
    /// Where the table's reads held this frame's level back (Followed, Outlier): the level (the
    /// G gain) the carpet and the white read, further from the table's than `estimate[1]`.
    std::optional<double> held_from;
    /// The part of the level (ln gain of G) that came faster than a hall's light changes, read
    /// as the view's (a hall lit unevenly, its darker end in view) while the table reads the
    /// frame's posts, ball and robots as well without it (TableLevelCheck): the frame is read at
    /// the gain less this level (readGain). The state still follows it, so that a light that does
    /// change is followed from where it is once the table's reads say so.
    double view_level = 0;

    /// How far the light has moved from the table's: the largest |ln gain| (0.1: about 10%).
    double distance() const;
    /// The gains the frame is read with: `gain` less the view's level.
    std::array<double, 3> readGain() const;
    /// How far the table is moved to read the frame: distance() of readGain().
    double readDistance() const;
    /// The map that reads this light's pixels in the table's cells (of readGain()): the colour in
    /// full, the level only beyond 8% (a table is broad in Y) and in full only where that finds
    /// nothing (its next map), the gains rounded to 0.02 in ln gain; nullptr within 2% of the
    /// table's colour and 4% of its level.
    std::shared_ptr<const LutInputMap> makeMap() const;
};

const char* verdictName(LightState::Verdict verdict);

/// A state's map (LightState::makeMap), made again only when the state's map would differ, so a
/// worker running frames in order builds few maps.
class LightMapCache
{
public:
    /// The map of the state's readGain().
    std::shared_ptr<const LutInputMap> mapFor(const LightState& state)
    {
        return mapFor(state.readGain());
    }
    std::shared_ptr<const LutInputMap> mapFor(const std::array<double, 3>& gain);

private:
    std::array<long, 4> m_key{0, 0, 0, 0};
    std::shared_ptr<const LutInputMap> m_map;
};

/// Follows the light frame by frame. Feed it the frames in stream order; deterministic.
class LightTracker
{
public:
    LightTracker(std::shared_ptr<const ColourLut> lut, LightTrackingOptions options = {});
    LightTracker(LightTracker&&) noexcept;
    LightTracker& operator=(LightTracker&&) noexcept;
    ~LightTracker();

    /// The next frame (CV_8UC3 Y, Cb, Cr) with its kinematic horizon (samples below it only).
    const LightState& observe(const cv::Mat& ycbcr, const Horizon& horizon);
    /// The next frame could not be read: the state stays.
    const LightState& skip();
    const LightState& state() const { return m_state; }

private:
    struct ClassSums
    {
        std::array<double, 3> rgb{0, 0, 0};
        std::size_t count = 0;
    };
    void sample(const cv::Mat& ycbcr, const Horizon& horizon, std::array<ClassSums, 2>& sums) const;
    void follow(const std::array<ClassSums, 2>& sums, std::size_t samples);
    /// Splits the followed level into the light's and the view's (LightState::view_level), and
    /// points m_seen at the map the frame is read with.
    void splitView();
    /// Fits the light's course through m_recent (after every change of it).
    void fitCourse();
    /// The course of channel `c` at position `x` of m_recent, in ln gain.
    double courseAt(std::size_t c, double x) const
    {
        return m_course[c].intercept + m_course[c].slope * x;
    }

    LightTrackingOptions m_options;
    LightState m_state;
    LightMapCache m_maps;
    ColourLut m_seen; ///< the table through m_state's map, that classifies the samples
    std::array<ClassSums, 2> m_reference; ///< carpet and white under the table's light
    int m_reference_frames = 0;
    std::vector<std::array<double, 3>> m_outlier_run; ///< ln of the outliers in a row
    std::size_t m_frame = 0;                          ///< frames observed or skipped
    std::size_t m_last_outlier = 0;                   ///< m_frame of the run's last outlier
    std::deque<std::array<double, 3>> m_recent;       ///< ln of the latest accepted estimates
    std::vector<double> m_channel;                    ///< a channel of m_recent (fitCourse)
    std::vector<double> m_pairs;                      ///< the course's slopes, then its intercepts
    struct Line
    {
        double slope = 0;
        double intercept = 0;
    };
    std::array<Line, 3> m_course{}; ///< per channel, through m_recent (fitCourse)
    /// The levels the table reads best at (TableLevelCheck), measured every few frames: a level
    /// the carpet and the white read further from the table's is pulled back to them (not past
    /// the table's own). None: the last check could not say.
    std::unique_ptr<TableLevelCheck> m_check;
    std::optional<LevelRange> m_held;
    std::deque<double> m_levels; ///< ln G gain of the last frames, oldest first (splitView)
    bool m_fast = false;         ///< the level is moving faster than a hall's light (splitView)
    double m_view_read = 0;      ///< the level a fast move is read at (splitView)
};

struct LightTrack
{
    std::vector<LightState> frames; ///< in stream order, from frame 0
    bool cancelled = false;         ///< then `frames` holds the frames tracked before the stop
};

/// Tracks frames 0 .. count-1 of `reader` with `lut`. A frame that cannot be read keeps the
/// state (Verdict::Unread). `progress` (done, total) after every frame; `cancel` stops early.
LightTrack trackLight(StreamReader& reader, std::shared_ptr<const ColourLut> lut, std::size_t count,
                      const LightTrackingOptions& options = {},
                      const std::function<void(std::size_t, std::size_t)>& progress = {},
                      const std::atomic<bool>* cancel = nullptr);

} // namespace fieldsight
