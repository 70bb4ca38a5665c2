// The parameter search (docs/formats.md, "fieldsight tune"): coordinate rounds over every
// searched parameter (a coarse grid over its range first, then ever finer steps around the best
// value, switches and choices tried again each round), then random moves of a few parameters at
// once until the budget is spent; the changes that buy nothing are put back. Candidates are
// scored in batches whose make-up depends only on the seed, so the result is the same on any
// number of cores.
#include "param_tuning_eval.h"

#include "visioncore/basics/splitmix.h"
#include "visioncore/services/worker_pool.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>

namespace fieldsight {

namespace {

using tuning::HeldFrame;
using tuning::Scorer;

/// A searched parameter, with where it started.
struct Searched
{
    std::string stage;
    ParamInfo info;
    double start = 0;
};

double valueOf(const ParamSet& params, const Searched& p)
{
    const auto stage = params.values.find(p.stage);
    if (stage == params.values.end())
        return p.info.default_value;
    const auto value = stage->second.find(p.info.name);
    return value == stage->second.end() ? p.info.default_value : value->second;
}

/// A uniform number in [0, 1) from the engine (the same on every platform).
double unit(SplitMix64& random)
{
    return double(random()) / 4294967296.0;
}

/// A range wide enough, and above zero, is searched on a log scale (iterations 1..10000).
bool logScale(const ParamInfo& p)
{
    return p.min > 0 && p.max / p.min >= 50;
}

/// `value` made valid for the parameter: clamped, whole for integers.
double legal(const ParamInfo& p, double value)
{
    value = std::clamp(value, p.min, p.max);
    if (p.kind != ParamKind::Real)
        value = std::round(value);
    else
        value = std::round(value * 1e6) / 1e6; // short numbers in the saved file
    return std::clamp(value, p.min, p.max);
}

/// The values to try for `p` now at `current` in round `round` (0: a coarse grid over the
/// whole range; later: steps around the current value, shrinking each round).
std::vector<double> candidates(const ParamInfo& p, double current, int round, SplitMix64& random)
{
    std::vector<double> values;
    if (p.kind == ParamKind::Boolean) {
        values.push_back(current != 0 ? 0 : 1);
    } else if (p.kind == ParamKind::Choice) {
        for (const ParamChoice& c : p.choices)
            values.push_back(c.value);
    } else if (round == 0) {
        for (int i = 0; i <= 8; ++i) {
            const double t = i / 8.0;
            values.push_back(logScale(p) ? p.min * std::pow(p.max / p.min, t)
                                         : p.min + t * (p.max - p.min));
        }
    } else {
        const double shrink = std::pow(0.5, round);
        for (double step : {-1.0, -0.5, 0.5, 1.0}) {
            if (logScale(p))
                values.push_back(current * std::pow(p.max / p.min, step * shrink / 8));
            else
                values.push_back(current + step * shrink * (p.max - p.min) / 8);
        }
        values.push_back(logScale(p) ? p.min * std::pow(p.max / p.min, unit(random))
                                     : p.min + unit(random) * (p.max - p.min));
    }
    std::vector<double> out;
    for (double v : values) {
        v = legal(p, v);
        if (v != current && std::find(out.begin(), out.end(), v) == out.end())
            out.push_back(v);
    }
    return out;
}

/// A random move of one parameter from `current` (for moves of several at once).
double randomMove(const ParamInfo& p, double current, SplitMix64& random)
{
    if (p.kind == ParamKind::Boolean)
        return current != 0 ? 0 : 1;
    if (p.kind == ParamKind::Choice)
        return p.choices.empty() ? current : p.choices[random() % p.choices.size()].value;
    const double t = (unit(random) + unit(random) + unit(random) - 1.5) / 6; // about +-0.25
    if (logScale(p))
        return legal(p, std::max(p.min, current) * std::pow(p.max / p.min, t));
    return legal(p, current + t * (p.max - p.min));
}

/// The search's state shared by its steps.
class Search
{
public:
    Search(const StreamInput& input, const std::vector<HeldFrame>& frames,
           std::vector<std::size_t> fit, const TuneOptions& options)
        : m_frames(frames), m_fit(std::move(fit)), m_options(options)
    {
        const int workers = workerCount(options.threads, 64);
        for (int w = 0; w < workers; ++w)
            m_scorers.push_back(std::make_unique<Scorer>(input));
    }

    /// Scores every set in `sets` on `positions`; counts them against the budget when `count`.
    std::vector<TuneScore> scoreAll(const std::vector<ParamSet>& sets,
                                    const std::vector<std::size_t>& positions, bool count)
    {
        std::vector<TuneScore> scores(sets.size());
        const int workers = int(std::min(m_scorers.size(), std::max<std::size_t>(sets.size(), 1)));
        std::vector<std::string> problems(static_cast<std::size_t>(workers));
        runOnWorkers(workers, [&](int w) {
            try {
                for (std::size_t i = std::size_t(w); i < sets.size(); i += std::size_t(workers))
                    scores[i] = m_scorers[std::size_t(w)]->score(sets[i], m_frames, positions,
                                                                 m_options.weights);
            } catch (const std::exception& e) {
                problems[std::size_t(w)] = e.what();
            }
        });
        for (const std::string& p : problems)
            if (!p.empty())
                throw std::invalid_argument(p);
        if (count)
            m_evaluations += int(sets.size());
        return scores;
    }

    int evaluations() const { return m_evaluations; }
    bool exhausted() const
    {
        return m_evaluations >= m_options.budget || (m_options.cancel && m_options.cancel->load());
    }
    const std::vector<std::size_t>& fit() const { return m_fit; }

    /// Tries `sets` (moves from `best`); keeps the best if it beats `best_score`. True if so.
    bool tryBatch(std::vector<ParamSet> sets, ParamSet& best, TuneScore& best_score,
                  TuneResult& result)
    {
        const int room = m_options.budget - m_evaluations;
        if (room <= 0 || sets.empty())
            return false;
        if (int(sets.size()) > room)
            sets.resize(std::size_t(room));
        const std::vector<TuneScore> scores = scoreAll(sets, m_fit, true);
        std::size_t winner = sets.size();
        double top = best_score.total + 1e-9;
        for (std::size_t i = 0; i < scores.size(); ++i)
            if (scores[i].total > top) {
                top = scores[i].total;
                winner = i;
            }
        if (m_options.progress)
            m_options.progress({m_evaluations, m_options.budget, std::max(top, best_score.total)});
        if (winner == sets.size())
            return false;
        best = sets[winner];
        best_score = scores[winner];
        result.history.emplace_back(m_evaluations, best_score.total);
        return true;
    }

private:
    const std::vector<HeldFrame>& m_frames;
    std::vector<std::size_t> m_fit;
    const TuneOptions& m_options;
    std::vector<std::unique_ptr<Scorer>> m_scorers;
    int m_evaluations = 0;
};

/// The parameters searched: those of `options.stages` (every stage when empty) not skipped.
Result<std::vector<Searched>> searchedParams(const StreamInput& input, const TuneOptions& options)
{
    for (const std::string& id : options.stages)
        if (!input.pipeline->find(id))
            return Error{"unknown stage '" + id + "' (stages: " + input.pipeline->idList() + ")"};
    std::vector<Searched> searched;
    for (const StageDescriptor& stage : input.pipeline->descriptors()) {
        const std::string& id = stage.info.id;
        const bool chosen =
            options.stages.empty() ||
            std::find(options.stages.begin(), options.stages.end(), id) != options.stages.end();
        const bool skipped =
            std::find(input.skip.begin(), input.skip.end(), id) != input.skip.end();
        if (!chosen || skipped)
            continue;
        for (const ParamInfo& info : stage.params) {
            if (!info.fitted)
                continue;
            Searched s{id, info, 0};
            s.start = valueOf(input.params, s);
            searched.push_back(std::move(s));
        }
    }
    return searched;
}

ParamSet with(ParamSet set, const Searched& p, double value)
{
    set.set(p.stage, p.info.name, value);
    return set;
}

/// Coordinate rounds, then random moves, until the budget is spent or the search is cancelled.
void searchFrom(Search& search, const std::vector<Searched>& params, ParamSet& best,
                TuneScore& best_score, TuneResult& result, SplitMix64& random)
{
    std::vector<std::size_t> order(params.size());
    for (std::size_t i = 0; i < order.size(); ++i)
        order[i] = i;
    for (int round = 0; round < 6 && !search.exhausted(); ++round) {
        for (std::size_t i = order.size(); i > 1; --i)
            std::swap(order[i - 1], order[random() % i]);
        // Switches and choices first: few candidates each, and they change the most.
        std::stable_partition(order.begin(), order.end(), [&](std::size_t k) {
            return params[k].info.kind == ParamKind::Boolean ||
                   params[k].info.kind == ParamKind::Choice;
        });
        bool improved = false;
        for (std::size_t k : order) {
            if (search.exhausted())
                break;
            const Searched& p = params[k];
            std::vector<ParamSet> sets;
            for (double v : candidates(p.info, valueOf(best, p), round, random))
                sets.push_back(with(best, p, v));
            improved = search.tryBatch(std::move(sets), best, best_score, result) || improved;
        }
        if (!improved && round >= 2)
            break;
    }
    while (!search.exhausted() && !params.empty()) {
        std::vector<ParamSet> sets;
        for (int c = 0; c < 8; ++c) {
            ParamSet set = best;
            const int moves = 2 + int(random() % 2);
            for (int m = 0; m < moves; ++m) {
                const Searched& p = params[random() % params.size()];
                set = with(std::move(set), p, randomMove(p.info, valueOf(set, p), random));
            }
            sets.push_back(std::move(set));
        }
        search.tryBatch(std::move(sets), best, best_score, result);
    }
}

/// Puts back every change that buys nothing on the fit frames, then works out what each of the
/// others buys (one evaluation per changed parameter each).
void pruneAndPrice(Search& search, const std::vector<Searched>& params, ParamSet& best,
                   TuneScore& best_score, TuneResult& result)
{
    for (const Searched& p : params) {
        if (valueOf(best, p) == p.start)
            continue;
        const ParamSet back = with(best, p, p.start);
        const TuneScore score = search.scoreAll({back}, search.fit(), false).front();
        if (score.total >= best_score.total) {
            best = back;
            best_score = score;
        }
    }
    for (const Searched& p : params) {
        if (valueOf(best, p) == p.start)
            continue;
        const TuneScore without =
            search.scoreAll({with(best, p, p.start)}, search.fit(), false).front();
        TuneChange change{p.stage, p.info.name, p.start, valueOf(best, p), 0, {}};
        change.gain = best_score.total - without.total;
        for (const auto& [term, value] : best_score.terms) {
            const auto other = without.terms.find(term);
            change.term_gain[term] = value - (other == without.terms.end() ? 0.0 : other->second);
        }
        result.changes.push_back(std::move(change));
    }
}

} // namespace

Result<TuneResult> tuneParams(StreamInput& input, const Annotations& truth,
                              const std::string& truth_path, const TuneOptions& options)
{
    const auto started = std::chrono::steady_clock::now();
    if (Status s = checkTuneWeights(options.weights); !s)
        return s.error();
    if (!(options.holdout >= 0 && options.holdout <= 0.9))
        return Error{"the held-out share must be between 0 and 0.9"};
    if (options.budget < 1)
        return Error{"the budget must be at least one evaluation"};
    if (input.adapt)
        return Error{"the parameters are fitted with the stream's table as it is (no --adapt)"};
    if (Status s = input.checkSettings(); !s)
        return s.error();
    auto params = searchedParams(input, options);
    if (!params)
        return params.error();
    auto frames = tuning::readScoredFrames(input, truth, truth_path, options.threads);
    if (!frames)
        return frames.error();

    TuneResult result;
    result.parameters = int(params.value().size());
    const std::vector<bool> held =
        holdoutFrames(frames.value().size(), options.holdout, options.seed);
    std::vector<std::size_t> fit;
    std::vector<std::size_t> holdout;
    for (std::size_t i = 0; i < held.size(); ++i) {
        (held[i] ? holdout : fit).push_back(i);
        (held[i] ? result.holdout_frames : result.fit_frames).push_back(frames.value()[i].name);
    }

    result.start = input.params;
    ParamSet best = input.params;
    try {
        Search search(input, frames.value(), fit, options);
        TuneScore best_score = search.scoreAll({best}, fit, true).front();
        result.history.emplace_back(search.evaluations(), best_score.total);
        SplitMix64 random(options.seed);
        searchFrom(search, params.value(), best, best_score, result, random);
        result.cancelled = options.cancel && options.cancel->load();
        pruneAndPrice(search, params.value(), best, best_score, result);
        result.evaluations = search.evaluations();
        result.start_fit = search.scoreAll({input.params}, fit, false).front();
        result.tuned_fit = best_score;
        if (!holdout.empty()) {
            const auto scores = search.scoreAll({input.params, best}, holdout, false);
            result.start_holdout = scores[0];
            result.tuned_holdout = scores[1];
        }
    } catch (const std::invalid_argument& e) {
        return Error{input.stream + ": " + e.what()};
    }
    // What differs from the defaults, and every change: a value put back to its default where
    // the stream's own file set another must be written too, or the stream's file would win.
    result.params = differingFromDefaults(best, *input.pipeline);
    for (const TuneChange& c : result.changes)
        result.params.set(c.stage, c.name, c.after);
    result.seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    return result;
}

} // namespace fieldsight
