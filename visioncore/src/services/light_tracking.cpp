// Following the light: sparse samples of the carpet and the white, a least-squares von Kries gain
// per frame, and a median and exponential filter that one odd frame cannot pull away.
#include "visioncore/services/light_tracking.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace fieldsight {

namespace {

/// The classes whose colour the light is judged by: the carpet and the white lines, goals and
/// robots, the two every field shows.
constexpr std::array<Colour, 2> kReferenceClasses{Colour::Green, Colour::White};

/// Maps are made for gains rounded to this step of ln gain: about half an 8-bit level at mid
/// grey, finer than the table's 2-level cells.
constexpr double kMapStep = 0.004;

std::array<long, 3> mapKey(const std::array<double, 3>& gain)
{
    std::array<long, 3> key{};
    for (std::size_t k = 0; k < 3; ++k)
        key[k] = std::lround(std::log(gain[k]) / kMapStep);
    return key;
}

std::shared_ptr<const LutInputMap> mapOfKey(const std::array<long, 3>& key)
{
    if (key == std::array<long, 3>{0, 0, 0})
        return nullptr;
    return std::make_shared<const LutInputMap>(LutInputMap::forRgbGain(
        std::exp(double(key[0]) * kMapStep), std::exp(double(key[1]) * kMapStep),
        std::exp(double(key[2]) * kMapStep)));
}

double medianOf(std::vector<double> v)
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
    double d = 0;
    for (double g : gain)
        d = std::max(d, std::abs(std::log(g)));
    return d;
}

std::shared_ptr<const LutInputMap> LightState::makeMap() const
{
    return mapOfKey(mapKey(gain));
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
    case LightState::Verdict::Unread:
        return "unreadable";
    }
    return "?";
}

LightTracker::LightTracker(std::shared_ptr<const ColourLut> lut, LightTrackingOptions options)
    : m_lut(std::move(lut)), m_options(options)
{
    if (!m_lut)
        throw std::invalid_argument("LightTracker: no table");
    m_options.sample_step = std::max(1, m_options.sample_step);
    m_options.median_window = std::max(1, m_options.median_window);
}

void LightTracker::sample(const cv::Mat& ycbcr, const Horizon& horizon,
                          std::array<ClassSums, 2>& sums) const
{
    const int step = m_options.sample_step;
    const int width = ycbcr.cols;
    // Below the kinematic horizon where the carpet is; the whole frame when none is known.
    const double top = std::min(horizon.y_left, horizon.y_right);
    const int first_row = std::clamp(int(std::ceil(std::max(0.0, top))), 0, ycbcr.rows);
    const std::uint8_t* cells = m_lut->data();
    for (int y = first_row + step / 2; y < ycbcr.rows; y += step) {
        const std::uint8_t* row = ycbcr.ptr<std::uint8_t>(y);
        for (int x = step / 2; x < width; x += step) {
            const std::uint8_t* p = row + 3 * x;
            if (horizon.yAt(x, width) > y)
                continue;
            const std::size_t cell =
                m_map ? m_map->index(p[0], p[1], p[2]) : ColourLut::index(p[0], p[1], p[2]);
            const Colour c = Colour(cells[cell]);
            const std::size_t k = c == kReferenceClasses[0] ? 0 : c == kReferenceClasses[1] ? 1 : 2;
            if (k == 2)
                continue;
            // Back to R, G, B (BT.601 full range); a clipped channel says nothing of the gain.
            const double cb = p[1] - 128.0;
            const double cr = p[2] - 128.0;
            const double r = p[0] + 1.402 * cr;
            const double g = p[0] - 0.344136 * cb - 0.714136 * cr;
            const double b = p[0] + 1.772 * cb;
            if (std::max({r, g, b}) >= 250.0 || std::min({r, g, b}) <= 2.0)
                continue;
            sums[k].rgb[0] += r;
            sums[k].rgb[1] += g;
            sums[k].rgb[2] += b;
            ++sums[k].count;
        }
    }
}

const LightState& LightTracker::observe(const cv::Mat& ycbcr, const Horizon& horizon)
{
    CV_Assert(ycbcr.type() == CV_8UC3);
    std::array<ClassSums, 2> sums{};
    sample(ycbcr, horizon, sums);
    const std::size_t samples = sums[0].count + sums[1].count;
    m_state.samples = samples;
    m_state.estimate = m_state.gain;
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
    follow(sums, samples);
    return m_state;
}

void LightTracker::follow(const std::array<ClassSums, 2>& sums, std::size_t samples)
{
    if (samples < m_options.min_samples) {
        m_state.verdict = LightState::Verdict::Sparse;
        return;
    }
    // Least squares for observed = gain * reference over the classes' means, each class weighed
    // by its samples, one channel at a time.
    std::array<double, 3> estimate{};
    for (std::size_t c = 0; c < 3; ++c) {
        double num = 0;
        double den = 0;
        for (std::size_t k = 0; k < sums.size(); ++k) {
            if (sums[k].count == 0 || m_reference[k].count == 0)
                continue;
            const double seen = sums[k].rgb[c] / double(sums[k].count);
            const double ref = m_reference[k].rgb[c] / double(m_reference[k].count);
            num += double(sums[k].count) * seen * ref;
            den += double(sums[k].count) * ref * ref;
        }
        if (num <= 0 || den <= 0) {
            m_state.verdict = LightState::Verdict::Sparse;
            return;
        }
        estimate[c] = num / den;
    }
    m_state.estimate = estimate;

    std::array<double, 3> log_estimate{};
    double step = 0;
    for (std::size_t c = 0; c < 3; ++c) {
        log_estimate[c] = std::log(estimate[c]);
        step = std::max(step, std::abs(log_estimate[c] - std::log(m_state.gain[c])));
    }
    if (step > m_options.max_step && ++m_outliers_in_a_row < m_options.outlier_patience) {
        m_state.verdict = LightState::Verdict::Outlier;
        return;
    }
    if (step > m_options.max_step)
        m_recent.clear(); // the light has changed for good: start over from the new one
    m_outliers_in_a_row = 0;
    m_recent.push_back(log_estimate);
    while (m_recent.size() > std::size_t(m_options.median_window))
        m_recent.pop_front();
    for (std::size_t c = 0; c < 3; ++c) {
        std::vector<double> channel;
        for (const auto& e : m_recent)
            channel.push_back(e[c]);
        const double target = medianOf(std::move(channel));
        const double now = std::log(m_state.gain[c]);
        m_state.gain[c] = std::exp(now + m_options.smoothing * (target - now));
    }
    m_state.verdict = LightState::Verdict::Followed;
    m_map = m_maps.mapFor(m_state);
}

const LightState& LightTracker::skip()
{
    m_state.samples = 0;
    m_state.estimate = m_state.gain;
    m_state.verdict = LightState::Verdict::Unread;
    return m_state;
}

std::shared_ptr<const LutInputMap> LightMapCache::mapFor(const LightState& state)
{
    const std::array<long, 3> key = mapKey(state.gain);
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
