// The parameter search's frames and scoring: every scored frame decoded once, a seeded split
// into fit and held-out blocks, and one parameter set scored by matchFrame (THE matching path).
#include "param_tuning_eval.h"

#include "visioncore/basics/splitmix.h"

#include <algorithm>
#include <cstdio>
#include <cmath>
#include <mutex>
#include <numeric>
#include <stdexcept>

namespace fieldsight {

double f1Score(const ClassScore& score)
{
    const int denominator = 2 * score.tp + score.fp + score.fn;
    return denominator == 0 ? 1.0 : 2.0 * score.tp / double(denominator);
}

Status checkTuneWeights(const std::map<std::string, double, std::less<>>& weights,
                        const std::vector<const PerceptKind*>& kinds)
{
    for (const auto& [name, weight] : weights) {
        bool known = name == kBoundaryTerm;
        for (const PerceptKind* kind : kinds)
            known = known || scoredClassName(*kind) == name;
        if (!known) {
            std::string names;
            for (const PerceptKind* kind : kinds)
                names += scoredClassName(*kind) + ", ";
            return Error{"unknown score term '" + name + "' (known: " + names + kBoundaryTerm +
                         ")"};
        }
        if (!(weight >= 0) || !std::isfinite(weight))
            return Error{"the weight of '" + name + "' must be a number >= 0"};
    }
    return {};
}

ParamSet differingFromDefaults(const ParamSet& params, const Pipeline& pipeline)
{
    ParamSet out;
    for (const auto& [stage, values] : params.values) {
        const StageDescriptor* descriptor = pipeline.find(stage);
        for (const auto& [name, value] : values) {
            bool is_default = false;
            if (descriptor)
                for (const ParamInfo& p : descriptor->params)
                    is_default = is_default || (p.name == name && p.default_value == value);
            if (!is_default)
                out.set(stage, name, value);
        }
    }
    return out;
}

std::vector<bool> holdoutFrames(std::size_t frames, double share, std::uint64_t seed)
{
    std::vector<bool> held(frames, false);
    if (frames < 2 || share <= 0)
        return held;
    const std::size_t blocks = std::min<std::size_t>(6, frames);
    const std::size_t hold =
        std::clamp<std::size_t>(std::size_t(std::lround(double(blocks) * share)), 1, blocks - 1);
    std::vector<std::size_t> order(blocks);
    std::iota(order.begin(), order.end(), 0);
    SplitMix64 random(seed ^ 0x686f6c646f7574ull); // "holdout"
    for (std::size_t i = blocks - 1; i > 0; --i)   // Fisher-Yates, the same on every platform
        std::swap(order[i], order[random() % (i + 1)]);
    for (std::size_t b = 0; b < hold; ++b) {
        const std::size_t block = order[b];
        for (std::size_t f = block * frames / blocks; f < (block + 1) * frames / blocks; ++f)
            held[f] = true;
    }
    return held;
}

namespace tuning {

Result<std::vector<HeldFrame>> readScoredFrames(StreamInput& input, const Annotations& truth,
                                                const std::string& truth_path, int threads)
{
    auto names = scoredFrameIndices(input, truth, truth_path);
    if (!names)
        return names.error();
    if (names.value().empty())
        return Error{truth_path + ": no frame is done or reviewed, so there is nothing to fit"};
    std::map<std::size_t, std::vector<std::string>> by_index;
    for (const auto& [name, index] : names.value())
        by_index[index].push_back(name);
    std::vector<std::size_t> indices;
    for (const auto& [index, _] : by_index)
        indices.push_back(index);

    std::mutex mutex;
    std::map<std::size_t, Frame> decoded;
    RunHooks hooks;
    hooks.prefilter = [&](std::size_t index, const Frame& frame, const ColourLut&) {
        Frame copy = frame;
        copy.ycbcr = frame.ycbcr.clone(); // the reader may reuse its buffer
        const std::lock_guard lock(mutex);
        decoded.emplace(index, std::move(copy));
        return false;
    };
    auto run = runStream(input, indices, threads, hooks);
    if (!run)
        return run.error();
    std::vector<HeldFrame> frames;
    for (const auto& [index, frame_names] : by_index) {
        for (const std::string& name : frame_names) {
            HeldFrame held;
            held.index = index;
            held.name = name;
            held.frame = decoded.at(index);
            held.truth = &truth.frames.at(name);
            frames.push_back(std::move(held));
        }
    }
    return frames;
}

Result<std::pair<std::vector<HeldFrame>, std::vector<FrameRole>>>
readStreams(StreamInput& input, const Annotations& truth, const std::string& truth_path,
            const TuneOptions& options, const std::vector<TuneStream>& more, bool folds)
{
    auto read = readScoredFrames(input, truth, truth_path, options.threads);
    if (!read)
        return read.error();
    std::vector<HeldFrame> frames = std::move(read).value();
    // Of a fitted stream: held out or fitted.
    const auto roles = [&](std::size_t count, std::uint64_t seed) {
        std::vector<FrameRole> r(count, FrameRole::Fit);
        if (!folds) {
            const std::vector<bool> held = holdoutFrames(count, options.holdout, seed);
            for (std::size_t i = 0; i < count; ++i)
                r[i] = held[i] ? FrameRole::Held : FrameRole::Fit;
        }
        return r;
    };
    std::vector<FrameRole> held = roles(frames.size(), options.seed);
    std::size_t fitted = 0; // streams fitted before this one (the seed of its held-out blocks)
    for (std::size_t k = 0; k < more.size(); ++k) {
        const TuneStream& s = more[k];
        if (!s.input || !s.truth)
            return Error{"tune: a stream without its input or annotations"};
        StreamInput& other = *s.input;
        if (other.pipeline != input.pipeline)
            return Error{other.stream + ": another pipeline than " + input.stream + "'s"};
        if (other.adapt)
            return Error{"the parameters are fitted with the stream's table as it is (no --adapt)"};
        if (Status st = other.checkSettings(); !st)
            return st.error();
        // One parameter set is fitted to every stream, so each must start from it.
        if (other.params.toJson() != input.params.toJson() || other.skip != input.skip)
            return Error{other.stream +
                         ": its parameters or skipped stages (its own params.json, "
                         "--params, --set, --skip) differ from " +
                         input.stream +
                         "'s; the streams are fitted together, so they must start alike"};
        auto frames_of = readScoredFrames(other, *s.truth, s.truth_path, options.threads);
        if (!frames_of)
            return frames_of.error();
        const std::vector<FrameRole> held_of =
            s.validation ? std::vector<FrameRole>(frames_of.value().size(), FrameRole::Validation)
                         : roles(frames_of.value().size(), options.seed + 1 + fitted++);
        for (HeldFrame& f : frames_of.value()) {
            f.lut = other.lut;
            f.name = other.stream + "/" + f.name;
            frames.push_back(std::move(f));
        }
        held.insert(held.end(), held_of.begin(), held_of.end());
    }
    return std::make_pair(std::move(frames), std::move(held));
}

Scorer::Scorer(const StreamInput& input, bool reuse)
    : m_lut(input.lut), m_data(input.lut),
      m_control(std::make_unique<ControlWrapper>(m_data, *input.pipeline)),
      m_kinds(scoredKinds(input.pipeline->perceptKinds())), m_reuse(reuse)
{
    for (const std::string& id : input.skip)
        if (Status s = m_control->setStageEnabled(id, false); !s)
            throw std::invalid_argument(s.error().message);
}

std::string Scorer::prefixKey(std::size_t split) const
{
    std::string key;
    const std::vector<StageDescriptor> stages = m_control->stages();
    for (std::size_t i = 0; i < split && i < stages.size(); ++i)
        for (const ParamInfo& p : stages[i].params) {
            char value[40];
            std::snprintf(value, sizeof value, "%.17g;", p.value);
            key += value;
        }
    return key;
}

Tally Scorer::tally(const ParamSet& params, const std::vector<HeldFrame>& frames,
                    const std::vector<std::size_t>& positions, std::size_t split)
{
    Tally sum;
    for (const Tally& t : tallies(params, frames, positions, split))
        sum += t;
    return sum;
}

std::vector<Tally> Scorer::tallies(const ParamSet& params, const std::vector<HeldFrame>& frames,
                                   const std::vector<std::size_t>& positions, std::size_t split)
{
    m_control->resetParams();
    if (Status s = m_control->applyParams(params); !s)
        throw std::invalid_argument(s.error().message);
    if (!m_reuse)
        split = 0;
    if (split > 0) {
        std::string key = prefixKey(split);
        if (split != m_split || key != m_key) {
            m_kept.clear();
            m_split = split;
            m_key = std::move(key);
        }
    }
    std::vector<Tally> out;
    out.reserve(positions.size());
    for (std::size_t position : positions) {
        Tally& tally = out.emplace_back();
        const HeldFrame& held = frames[position];
        m_data.setLut(held.lut ? held.lut : m_lut);
        m_data.setFrame(held.frame);
        Result<FrameReport> report = Error{""};
        if (split > 0) {
            auto kept = m_kept.find(position);
            if (kept == m_kept.end()) {
                if (auto first = m_control->runFrameUntil(split); !first)
                    throw std::invalid_argument(held.name + ": " + first.error().message);
                kept = m_kept.emplace(position, m_control->blackboard()).first;
            }
            report = m_control->resumeFrame(kept->second, split);
        } else {
            report = m_control->runFrame();
        }
        if (!report)
            throw std::invalid_argument(held.name + ": " + report.error().message);
        const FrameMatch match = matchFrame(m_control->blackboard().percepts, *held.truth,
                                            held.frame.ycbcr.cols, held.frame.ycbcr.rows, m_kinds);
        for (const KindMatch& kind : match.kinds)
            tally.classes[scoredClassName(*kind.kind)] += kind.score;
        if (match.boundary_error >= 0)
            tally.boundary.push_back(match.boundary_error);
        ++tally.frames;
        if (split == 0) {
            tally.core_ms += report.value().total_ms;
            ++tally.timed_frames;
        }
    }
    return out;
}

Tally& Tally::operator+=(const Tally& other)
{
    for (const auto& [name, score] : other.classes)
        classes[name] += score;
    boundary.insert(boundary.end(), other.boundary.begin(), other.boundary.end());
    frames += other.frames;
    core_ms += other.core_ms;
    timed_frames += other.timed_frames;
    return *this;
}

TuneScore scoreOf(const Tally& tally, const std::map<std::string, double, std::less<>>& weights)
{
    TuneScore result;
    result.classes = tally.classes;
    result.frames = tally.frames;
    if (tally.timed_frames > 0)
        result.ms_per_frame = tally.core_ms / double(tally.timed_frames);
    const auto weightOf = [&](const std::string& term) {
        const auto w = weights.find(term);
        return w == weights.end() ? 1.0 : w->second;
    };
    double sum = 0;
    double weight_sum = 0;
    for (const auto& [name, score] : result.classes) {
        if (score.tp + score.fp + score.fn == 0 || weightOf(name) == 0)
            continue;
        result.terms[name] = f1Score(score);
        sum += weightOf(name) * result.terms[name];
        weight_sum += weightOf(name);
    }
    if (!tally.boundary.empty()) {
        std::vector<double> boundary = tally.boundary;
        std::sort(boundary.begin(), boundary.end());
        const std::size_t n = boundary.size();
        result.boundary_median =
            n % 2 ? boundary[n / 2] : 0.5 * (boundary[n / 2 - 1] + boundary[n / 2]);
        result.boundary_mean = std::accumulate(boundary.begin(), boundary.end(), 0.0) / double(n);
        if (weightOf(kBoundaryTerm) > 0) {
            // Within 1 px is as near as a person marks it: no reason to buy more.
            result.terms[kBoundaryTerm] = 2.0 / (2.0 + std::max(0.0, result.boundary_median - 1.0));
            sum += weightOf(kBoundaryTerm) * result.terms[kBoundaryTerm];
            weight_sum += weightOf(kBoundaryTerm);
        }
    }
    result.total = weight_sum > 0 ? sum / weight_sum : 0;
    return result;
}

} // namespace tuning
} // namespace fieldsight
