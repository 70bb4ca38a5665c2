// Following the light: sparse samples of the carpet and the white, a least-squares von Kries gain
// per frame, and a median and exponential filter that one odd frame cannot pull away.
#include "visioncore/services/light_tracking.h"

#include "services/light_level_check.h"
#include "visioncore/basics/ycbcr.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <mutex>
#include <utility>
#include <stdexcept>

namespace fieldsight {

namespace {

/// The classes whose colour the light is judged by: the carpet and the white lines, goals and
/// robots, the two every field shows.
constexpr std::array<Colour, 2> kReferenceClasses{Colour::Green, Colour::White};

/// Maps are made for gains rounded to this step of ln gain: at most 1% off (a table's cells are 2
/// levels wide, about 1% at a white's level), and coarse enough that a fast change makes a new map
/// only every few frames: each new map works out afresh every cell the frames read (on the README's
/// measure, a dimming light, this step makes 7 maps in 50 frames and 0.01 made 20).
constexpr double kMapStep = 0.02;
/// A light within this (ln gain, about 2%) of the table's reads the table as it is: its cells are 2
/// levels wide and a table has margins, and a view that tints the carpet moves the estimate by
/// that much with no change of light (generated scenes with no drift then read as static).
constexpr double kNoMapBelow = 0.02;
/// The level held back (within kLevelMargin) is read only where the map finds nothing, and within
/// this (about 4%: one or two of a table's cells in Y) that found no more on the generated streams,
/// while each frame read through a map costs a third more lookups (a generated stream with no
/// drift whose view wanders 2-3% darker: 1.303 M instructions a frame at 0.02, 1.287 M at 0.04;
/// docs/formats.md).
constexpr double kNoLevelMapBelow = 0.04;

/// A level that moves this far (ln gain) within kViewFrames frames moves faster than a hall's light
/// does (a light drifting 30% over a game moves 0.003 a frame; the camera turning from a hall's
/// bright end to its dark one moves 0.03-0.04): the move is read as the view's (LightState::
/// view_level) as long as the table reads the frame as well without it (kViewSpare).
constexpr double kViewMove = 0.1;
constexpr std::size_t kViewFrames = 10;
/// The view's level is kept only while the frame's read level lies this far (ln gain) inside the
/// levels the last TableLevelCheck found the table reads best at.
constexpr double kViewSpare = 0.06;

/// Carpet and white that read a level this far (ln gain) on one side of the table's own while
/// the table reads the frame's posts, ball and robots best at its own level or on the other side
/// say more of the view than of the light (a generated rc2012 hall, seed 71, 30% drift: the carpet
/// read 17% brighter while the light was 8% dimmer, and the check found it right; held at the
/// table's own level the posts fell from 0.93 with no drift to 0.37). Closer to the table's
/// level they are believed (on B-Human's log, pushed across from 0.2% the frames lost none, but
/// found an obstacle more that is not there).
constexpr double kOtherSide = 0.08;

/// The steepest course of the light the tracker believes, in ln gain per frame (30% in 12
/// frames): a line through a few noisy estimates may claim more.
constexpr double kMaxSlope = 0.025;

/// A table's cells are narrow in colour but broad in Y (it is made over shadows and exposures),
/// and on real frames the level is what a change of view moves most: the map corrects the level
/// only beyond this (ln gain, about 8%), the colour in full. On B-Human's log, following every
/// level change lost a quarter of the balls; this keeps them. The level held back is followed
/// where the map finds nothing (LutInputMap's next map): a table narrow in Y (a yellow post on
/// a generated stream, rc2012 seed 13 at 30% drift) then keeps its posts, 0.727 -> 0.939
/// (docs/formats.md).
constexpr double kLevelMargin = 0.08;

/// Every this many frames the level is checked against the table (TableLevelCheck: about 130 k
/// instructions a check at 320 x 240 on the README's measure, half of them the lattice's 2,100
/// lookups, half the keys met for the first time). Every 6th lost a stream's posts (rc2012 seed 71
/// at 30% drift: 0.800 -> 0.600), as a view's posts come and go.
constexpr std::size_t kCheckEvery = 3;

/// Samples a class needs in a frame to say anything of the light.
constexpr std::size_t kMinClassSamples = 10;

/// A map's key: the R, G, B of the cautious map in kMapStep of ln gain, then the level it held
/// back (kLevelMargin), which the map's second map adds where the first finds nothing.
using MapKey = std::array<long, 4>;

MapKey mapKey(const std::array<double, 3>& gain)
{
    // The level (the green gain) beyond the table's margin in Y; the colour in full.
    const double level = std::log(gain[1]);
    const double beyond = level > kLevelMargin    ? level - kLevelMargin
                          : level < -kLevelMargin ? level + kLevelMargin
                                                  : 0.0;
    std::array<double, 3> moved{};
    double largest = 0;
    for (std::size_t k = 0; k < 3; ++k) {
        moved[k] = std::log(gain[k]) - level + beyond;
        largest = std::max(largest, std::abs(moved[k]));
    }
    // Within kNoMapBelow of the table's colour and kNoLevelMapBelow of its level: no map (the key
    // of none).
    MapKey key{};
    if (largest >= kNoMapBelow || std::abs(level - beyond) >= kNoLevelMapBelow) {
        for (std::size_t k = 0; k < 3; ++k)
            key[k] = std::lround(moved[k] / kMapStep);
        key[3] = std::lround((level - beyond) / kMapStep);
    }
    return key;
}

/// The map `cache` holds for `key` while anyone holds it, else `make()`'s, kept for the next
/// asker; entries whose maps are gone are swept once there are 64.
template <class Key, class Make>
std::shared_ptr<const LutInputMap> sharedMap(std::map<Key, std::weak_ptr<const LutInputMap>>& cache,
                                             const Key& key, Make make)
{
    if (cache.size() >= 64)
        std::erase_if(cache, [](const auto& entry) { return entry.second.expired(); });
    std::weak_ptr<const LutInputMap>& known = cache[key];
    if (auto shared = known.lock())
        return shared;
    std::shared_ptr<const LutInputMap> made = make();
    known = made;
    return made;
}

std::shared_ptr<const LutInputMap> mapOfKey(const MapKey& key)
{
    if (key == MapKey{0, 0, 0, 0})
        return nullptr;
    // One map object per key while anyone holds it: the tracker classifying its samples and the
    // worker running the same frame ask for the same map, a table's memo of a map is shared by
    // the map's identity (ColourLut::setInputMap), so one map object means one memo filled once,
    // and the edit-effect scan knows a frame is read as before by its map's identity.
    // The plain maps (no next map) are kept by their gains' keys: a dimming or brightening
    // light's map is the level map of one some frames before (its next map), so it is copied,
    // not worked out.
    static std::mutex mutex;
    static std::map<MapKey, std::weak_ptr<const LutInputMap>> made;
    static std::map<std::array<long, 3>, std::weak_ptr<const LutInputMap>> plain;
    std::lock_guard lock(mutex);
    const auto plainMap = [&key](long level) {
        const std::array<long, 3> gains{key[0] + level, key[1] + level, key[2] + level};
        return sharedMap(plain, gains, [&gains] {
            const auto gain = [&gains](std::size_t k) {
                return std::exp(double(gains[k]) * kMapStep);
            };
            return std::make_shared<const LutInputMap>(
                LutInputMap::forRgbGain(gain(0), gain(1), gain(2)));
        });
    };
    return sharedMap(made, key, [&] {
        auto full = key[3] == 0 ? nullptr : plainMap(key[3]);
        // Not the carpet and the white: they are broad in Y, and dark or bright pixels of a
        // robot that the held level would make carpet or white split its obstacle (B-Human's log
        // with --adapt: obstacles 12/1/2 found/false/missed, 10/3/4 taking every class, 11/0/3
        // so).
        std::uint32_t classes = ~std::uint32_t(0);
        for (const Colour reference : kReferenceClasses)
            classes &= ~(std::uint32_t(1) << int(reference));
        // Allocated apart from its count, so that an expired entry holds no map's memory.
        return std::shared_ptr<const LutInputMap>(
            new LutInputMap(plainMap(0)->withThen(std::move(full), classes)));
    });
}

/// The largest |difference| of two ln gains, over the channels.
double logStep(const std::array<double, 3>& a, const std::array<double, 3>& b)
{
    return std::max({std::abs(a[0] - b[0]), std::abs(a[1] - b[1]), std::abs(a[2] - b[2])});
}

/// Where a level read on the other side of the table's own than `range` goes: the middle of the
/// range where it is closed, else its `edge` nearest the read (posts on the rc2012 hall above:
/// 0.73 at the edge, 0.87 at the middle; 0.95 for tables made for each third's own light).
double acrossTo(const LevelRange& range, double edge)
{
    return std::isfinite(range.lo) && std::isfinite(range.hi) ? (range.lo + range.hi) / 2 : edge;
}

/// The largest |ln| of the gains.
double largestLog(const std::array<double, 3>& gain)
{
    double d = 0;
    for (double g : gain)
        d = std::max(d, std::abs(std::log(g)));
    return d;
}

/// The median of `v`, reordered.
double medianOf(std::vector<double>& v)
{
    const auto mid = v.begin() + std::ptrdiff_t(v.size() / 2);
    std::nth_element(v.begin(), mid, v.end());
    if (v.size() % 2 == 1)
        return *mid;
    return 0.5 * (*mid + *std::max_element(v.begin(), mid));
}

} // namespace

double LightState::distance() const
{
    return largestLog(gain);
}

double LightState::readDistance() const
{
    return largestLog(readGain());
}

std::array<double, 3> LightState::readGain() const
{
    const double view = std::exp(-view_level);
    return {gain[0] * view, gain[1] * view, gain[2] * view};
}

std::shared_ptr<const LutInputMap> LightState::makeMap() const
{
    return mapOfKey(mapKey(readGain()));
}

const char* verdictName(LightState::Verdict verdict)
{
    switch (verdict) {
    case LightState::Verdict::Reference:
        return "reference";
    case LightState::Verdict::Followed:
        return "followed";
    case LightState::Verdict::Sparse:
        return "too few carpet and white samples";
    case LightState::Verdict::Outlier:
        return "outlier";
    case LightState::Verdict::Inconsistent:
        return "the carpet and the white disagree";
    case LightState::Verdict::Unread:
        return "unreadable";
    }
    return "?";
}

LightTracker::LightTracker(std::shared_ptr<const ColourLut> lut, LightTrackingOptions options)
    : m_options(options)
{
    if (!lut)
        throw std::invalid_argument("LightTracker: no table");
    m_seen = *lut;
    m_check = std::make_unique<TableLevelCheck>(std::move(lut));
    m_options.sample_step =
        std::clamp(m_options.sample_step, 1, 1 << 16); // y += 2 step stays an int
    m_options.median_window = std::max(1, m_options.median_window);
}

LightTracker::LightTracker(LightTracker&&) noexcept = default;
LightTracker& LightTracker::operator=(LightTracker&&) noexcept = default;
LightTracker::~LightTracker() = default;

void LightTracker::sample(const cv::Mat& ycbcr, const Horizon& horizon,
                          std::array<ClassSums, 2>& sums) const
{
    const int step = m_options.sample_step;
    const int width = ycbcr.cols;
    const int rows = ycbcr.rows;
    // A fixed lattice below the kinematic horizon where the carpet is (the whole frame when none
    // is known): every 2 steps along every step-th row, shifted by a step on alternate rows, so
    // the samples are spread as evenly as a step's grid with half as many. Walked column by
    // column from each column's first row (the sums are of integers, so their order does not
    // matter).
    constexpr int kClipLevel = int(LutInputMap::kClip);
    static_assert(double(kClipLevel) == LutInputMap::kClip);
    std::array<std::array<long long, 3>, 2> sum{};
    std::array<std::size_t, 2> count{};
    // A colour id's slot: the carpet's sums, the white's, or none.
    static constexpr std::array<std::uint8_t, 256> kSlot = [] {
        std::array<std::uint8_t, 256> slot{};
        slot.fill(2);
        slot[std::size_t(kReferenceClasses[0])] = 0;
        slot[std::size_t(kReferenceClasses[1])] = 1;
        return slot;
    }();
    const std::ptrdiff_t jump = 2 * step * std::ptrdiff_t(ycbcr.step[0]);
    for (int column = 0, x = step / 2; x < width; ++column, x += step) {
        const int first = int(std::clamp(std::ceil(horizon.yAt(x, width)), 0.0, double(rows)));
        // The column's rows: every other lattice row, those of its parity, from `first` on.
        int j = first <= step / 2 ? 0 : (first - step / 2 + step - 1) / step;
        j += (j ^ column) & 1;
        int y = step / 2 + j * step;
        if (y >= rows)
            continue;
        const std::uint8_t* p = ycbcr.ptr<std::uint8_t>(y) + 3 * x;
        for (; y < rows; y += 2 * step, p += jump) {
            const std::size_t k = kSlot[std::uint8_t(m_seen.classify(p[0], p[1], p[2]))];
            if (k == 2)
                continue;
            // Back to R, G, B (BT.601 full range); a clipped channel (at or past kClipLevel) or
            // one at 2 or less says nothing of the gain.
            const auto [r, g, b] = rgbOfYcc(p[0], p[1] - 128, p[2] - 128);
            constexpr unsigned kUsable = unsigned(kClipLevel - 3); // 3 .. kClipLevel - 1
            if (std::max({unsigned(r - 3), unsigned(g - 3), unsigned(b - 3)}) >= kUsable)
                continue;
            sum[k][0] += r;
            sum[k][1] += g;
            sum[k][2] += b;
            ++count[k];
        }
    }
    for (std::size_t k = 0; k < 2; ++k) {
        for (std::size_t c = 0; c < 3; ++c)
            sums[k].rgb[c] = double(sum[k][c]);
        sums[k].count = count[k];
    }
}

const LightState& LightTracker::observe(const cv::Mat& ycbcr, const Horizon& horizon)
{
    CV_Assert(ycbcr.type() == CV_8UC3);
    ++m_frame;
    std::array<ClassSums, 2> sums{};
    sample(ycbcr, horizon, sums);
    const std::size_t samples = sums[0].count + sums[1].count;
    m_state.samples = samples;
    m_state.estimate = m_state.gain;
    m_state.held_from.reset();
    if (m_reference_frames < m_options.reference_frames) {
        m_state.verdict = LightState::Verdict::Reference;
        if (samples >= m_options.min_samples) {
            for (std::size_t k = 0; k < sums.size(); ++k) {
                for (std::size_t c = 0; c < 3; ++c)
                    m_reference[k].rgb[c] += sums[k].rgb[c];
                m_reference[k].count += sums[k].count;
            }
            ++m_reference_frames;
        }
        return m_state;
    }
    if (m_check && m_frame % kCheckEvery == 0) // none in a tracker moved from
        m_held = m_check->measure(ycbcr, m_state.gain);
    follow(sums, samples);
    splitView();
    return m_state;
}

void LightTracker::splitView()
{
    const double level = std::log(m_state.gain[1]);
    m_levels.push_back(level);
    if (m_levels.size() > kViewFrames + 1)
        m_levels.pop_front();
    double view = m_state.view_level;
    if (std::abs(level - m_levels.front()) >= kViewMove) {
        // A fast move: the frame is read at the level it had kViewFrames frames ago, offset by the
        // view held then (a move back towards the table's light so ends the view, by the clamp
        // below; of the three ways tried for a second move this one kept the most posts).
        if (!m_fast)
            m_view_read = m_levels.front() + view;
        m_fast = true;
        view = level - m_view_read;
    } else {
        m_fast = false; // slow moves are the light's: the view is kept and the read follows them
    }
    // Never past the table's own light, nor beyond the level itself.
    view = std::clamp(view, std::min(0.0, level), std::max(0.0, level));
    const double read = level - view;
    if (!m_held || m_held->lo > read - kViewSpare || m_held->hi < read + kViewSpare)
        view = 0; // the table does not read the frame as well at the read level
    m_state.view_level = view;
    // The samples are classified as the pipeline reads the frame.
    m_seen.setInputMap(m_maps.mapFor(m_state));
}

void LightTracker::follow(const std::array<ClassSums, 2>& sums, std::size_t samples)
{
    if (samples < m_options.min_samples) {
        m_state.verdict = LightState::Verdict::Sparse;
        return;
    }
    // Per class, its means over its reference means, in ln. A change of the light moves every
    // class alike; a change of what is in view (the carpet near or far, a robot's white) moves
    // one class's level but not its colour. So the colour (each channel over green) is the
    // classes' weighted mean, and a frame where they disagree on it is ignored; the level moves
    // only as far as every class agrees.
    struct ClassRatio
    {
        std::array<double, 3> log;
        double weight;
    };
    std::vector<ClassRatio> ratios;
    for (std::size_t k = 0; k < sums.size(); ++k) {
        if (sums[k].count < kMinClassSamples || m_reference[k].count == 0)
            continue;
        ClassRatio r{{}, double(sums[k].count)};
        bool positive = true;
        for (std::size_t c = 0; c < 3; ++c) {
            const double seen = sums[k].rgb[c] / double(sums[k].count);
            const double ref = m_reference[k].rgb[c] / double(m_reference[k].count);
            positive = positive && seen > 0 && ref > 0;
            r.log[c] = positive ? std::log(seen / ref) : 0.0;
        }
        if (positive)
            ratios.push_back(r);
    }
    if (ratios.empty()) {
        m_state.verdict = LightState::Verdict::Sparse;
        return;
    }
    // The smallest move from `now` that every class agrees on (the same way); none when they move
    // apart. One class alone: its value.
    const auto agreed = [&ratios](double now, const auto& value_of) {
        if (ratios.size() == 1)
            return value_of(ratios.front());
        double up = std::numeric_limits<double>::infinity();
        double down = std::numeric_limits<double>::infinity();
        for (const ClassRatio& r : ratios) {
            up = std::min(up, value_of(r) - now);
            down = std::min(down, now - value_of(r));
        }
        return now + (up > 0 ? up : down > 0 ? -down : 0.0);
    };
    // The level: a class sees its pixels through the current map, so one whose cells are narrow
    // in Y loses the pixels the light moved furthest and under-reads the change. The level is the
    // move every class agrees on, relative to the state's; none when they move apart (a view with
    // more near carpet and a robot's white, not a change of light).
    const double level_now = std::log(m_state.gain[1]);
    double level = agreed(level_now, [](const ClassRatio& r) { return r.log[1]; });
    // Pulled back towards the table's own level as far as the table reads the frame's posts,
    // ball and robots as well there (TableLevelCheck): where a hall is lit unevenly the carpet
    // and the white move with the view, and a first view of a darker corner read every brighter
    // view as a brighter light (no drift, lab1 seed 88: posts 1.000 static, 0.301 adapting). Only
    // back: the table's reads never push the level past what the carpet and the white say (on
    // B-Human's log, held within the check's levels both ways, 3 of 28 balls were lost). Past it
    // only where the carpet and the white read kOtherSide or more beyond the table's own level and
    // the table reads best at it or on its other side (acrossTo).
    const double read = level;
    if (m_held && level > 0 && m_held->hi < level)
        level = level >= kOtherSide && m_held->hi <= 0 ? acrossTo(*m_held, m_held->hi)
                                                       : std::max(m_held->hi, 0.0);
    else if (m_held && level < 0 && m_held->lo > level)
        level = level <= -kOtherSide && m_held->lo >= 0 ? acrossTo(*m_held, m_held->lo)
                                                        : std::min(m_held->lo, 0.0);

    // The colour (each channel over green) likewise. On real frames the carpet's and the white's
    // colour move apart with the view by up to 7% (the B-Human log: near or far carpet, lines or
    // robots), and a ball's cells are narrow in colour: following their weighted mean lost 3 of
    // its 28 balls. A light's change moves both alike.
    std::array<double, 3> colour{0, 0, 0};
    std::array<double, 3> mean{0, 0, 0};
    double weights = 0;
    for (const ClassRatio& r : ratios) {
        for (std::size_t c = 0; c < 3; ++c)
            mean[c] += r.weight * (r.log[c] - r.log[1]);
        weights += r.weight;
    }
    for (std::size_t c = 0; c < 3; ++c) {
        mean[c] /= weights;
        colour[c] = agreed(std::log(m_state.gain[c]) - level_now,
                           [c](const ClassRatio& r) { return r.log[c] - r.log[1]; });
    }
    for (const ClassRatio& r : ratios)
        for (std::size_t c = 0; c < 3; ++c)
            if (std::abs(r.log[c] - r.log[1] - mean[c]) > m_options.max_disagreement) {
                m_state.verdict = LightState::Verdict::Inconsistent;
                m_outlier_run.clear(); // not the light's doing, so no run of it either
                return;
            }
    std::array<double, 3> estimate{};
    for (std::size_t c = 0; c < 3; ++c)
        estimate[c] = std::exp(level + colour[c]);
    m_state.estimate = estimate;
    if (level != read)
        m_state.held_from = std::exp(read);

    // A frame is judged an outlier against where the light's course says the light is now.
    std::array<double, 3> log_estimate{};
    double step = 0;
    for (std::size_t c = 0; c < 3; ++c) {
        log_estimate[c] = std::log(estimate[c]);
        const double expected =
            m_recent.size() < 3 ? std::log(m_state.gain[c]) : courseAt(c, double(m_recent.size()));
        step = std::max(step, std::abs(log_estimate[c] - expected));
    }
    if (step > m_options.max_step) {
        // A lasting change (a bank of lights off, a cloud over a window) gives outliers frame
        // after frame, each near the last; a flash or a view of something else gives one or two,
        // between frames that agree with the state (on B-Human's log at most two in a row). A run
        // of outlier_patience such frames is the light: start over from them.
        // Frames with too few samples between two outliers do not break the run, unless there
        // are more than median_window of them: the run's first outliers would be stale.
        if (!m_outlier_run.empty() &&
            (logStep(m_outlier_run.back(), log_estimate) > m_options.max_step ||
             m_frame - m_last_outlier > std::size_t(m_options.median_window)))
            m_outlier_run.clear();
        m_outlier_run.push_back(log_estimate);
        m_last_outlier = m_frame;
        if (int(m_outlier_run.size()) < m_options.outlier_patience) {
            m_state.verdict = LightState::Verdict::Outlier;
            return;
        }
        m_recent.assign(m_outlier_run.begin(), m_outlier_run.end());
        m_outlier_run.clear();
        while (m_recent.size() > std::size_t(m_options.median_window))
            m_recent.pop_front();
        fitCourse();
        for (std::size_t c = 0; c < 3; ++c)
            m_state.gain[c] = std::exp(courseAt(c, double(m_recent.size() - 1)));
        m_state.verdict = LightState::Verdict::Followed;
        return;
    }
    m_outlier_run.clear();
    m_recent.push_back(log_estimate);
    while (m_recent.size() > std::size_t(m_options.median_window))
        m_recent.pop_front();
    fitCourse();
    for (std::size_t c = 0; c < 3; ++c) {
        const double target = courseAt(c, double(m_recent.size() - 1));
        const double now = std::log(m_state.gain[c]);
        m_state.gain[c] = std::exp(now + m_options.smoothing * (target - now));
    }
    m_state.verdict = LightState::Verdict::Followed;
}

void LightTracker::fitCourse()
{
    // A robust line (Theil-Sen) through the recent accepted estimates, so a steady change is
    // followed without lag and one odd frame moves nothing. Fitted once each time they change:
    // the next frame's outlier test reads the same line.
    // A channel's values side by side first: a deque's indexing costs more than the division.
    const std::size_t n = m_recent.size();
    m_channel.resize(n);
    for (std::size_t c = 0; c < 3; ++c) {
        for (std::size_t a = 0; a < n; ++a)
            m_channel[a] = m_recent[a][c];
        std::vector<double>& slopes = m_pairs;
        slopes.clear();
        for (std::size_t a = 0; a < n; ++a)
            for (std::size_t b = a + 1; b < n; ++b)
                slopes.push_back((m_channel[b] - m_channel[a]) / double(b - a));
        const double slope =
            slopes.empty() ? 0.0 : std::clamp(medianOf(slopes), -kMaxSlope, kMaxSlope);
        std::vector<double>& intercepts = m_pairs;
        intercepts.clear();
        for (std::size_t a = 0; a < n; ++a)
            intercepts.push_back(m_channel[a] - slope * double(a));
        m_course[c] = {slope, medianOf(intercepts)};
    }
}

const LightState& LightTracker::skip()
{
    ++m_frame;
    m_state.samples = 0;
    m_state.estimate = m_state.gain;
    m_state.held_from.reset();
    m_state.verdict = LightState::Verdict::Unread;
    return m_state;
}

std::shared_ptr<const LutInputMap> LightMapCache::mapFor(const std::array<double, 3>& gain)
{
    const std::array<long, 4> key = mapKey(gain);
    if (key != m_key) {
        m_key = key;
        m_map = mapOfKey(key);
    }
    return m_map;
}

LightTrack trackLight(StreamReader& reader, std::shared_ptr<const ColourLut> lut, std::size_t count,
                      const LightTrackingOptions& options,
                      const std::function<void(std::size_t, std::size_t)>& progress,
                      const std::atomic<bool>* cancel)
{
    LightTracker tracker(std::move(lut), options);
    LightTrack track;
    track.frames.reserve(count);
    Frame frame;
    for (std::size_t i = 0; i < count; ++i) {
        if (cancel && cancel->load()) {
            track.cancelled = true;
            break;
        }
        if (reader.readInto(i, frame))
            track.frames.push_back(tracker.observe(frame.ycbcr, frame.horizon.value_or(Horizon{})));
        else
            track.frames.push_back(tracker.skip());
        if (progress)
            progress(i + 1, count);
    }
    return track;
}

} // namespace fieldsight
