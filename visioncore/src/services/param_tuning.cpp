// The parameter search (docs/formats.md, "fieldsight tune"): a best-first sweep of every
// searched parameter's coarse candidates, coordinate rounds (ever finer steps around the best
// value, switches and choices tried again each round), then random moves of a few parameters at
// once until the budget is spent; the changes that buy nothing are put back. Candidates are
// scored in batches whose make-up depends only on the seed (param_search.h), so the result is
// the same on any number of cores.
#include "param_search.h"
#include "param_tuning_eval.h"

#include "visioncore/basics/splitmix.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>

namespace fieldsight {

namespace {

using tuning::HeldFrame;
using tuning::Search;

/// A searched parameter, with where it started.
struct Searched
{
    std::string stage;
    ParamInfo info;
    double start = 0;
    std::size_t position = 0; ///< the stage's place in the pipeline
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

/// The parameters searched: those of `options.stages` (every stage when empty) not skipped.
Result<std::vector<Searched>> searchedParams(const StreamInput& input, const TuneOptions& options)
{
    for (const std::string& id : options.stages)
        if (!input.pipeline->find(id))
            return Error{"unknown stage '" + id + "' (stages: " + input.pipeline->idList() + ")"};
    std::vector<Searched> searched;
    std::size_t position = 0;
    for (const StageDescriptor& stage : input.pipeline->descriptors()) {
        ++position;
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
            Searched s{id, info, 0, position - 1};
            // Within twice the default's cost, unless allowed (the start's value always is).
            if (!options.allow_costly && info.work > 0)
                s.info.max =
                    std::max(std::min(info.max, 2 * info.default_value), valueOf(input.params, s));
            if (!options.allow_costly && info.work < 0)
                s.info.min = std::min(std::max(info.min, std::ceil(info.default_value / 2)),
                                      valueOf(input.params, s));
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

/// The first round, best first: every parameter's coarse candidates scored from the start, then
/// each parameter's best move, in the order of what it gained, tried again from the best set so
/// far. Taken in a random order instead, an early move of small gain could shut out a larger
/// one (on the B-Human log, an obstacle rule before the field's edge lines kept the boundary at
/// 2-3.5 px where the lines alone bring it to 1 px). False, having scored nothing, when the
/// candidates would take more than three quarters of what is left of the budget.
bool sweepBestFirst(Search& search, const std::vector<Searched>& params, ParamSet& best,
                    TuneScore& best_score, TuneResult& result, SplitMix64& random, int room)
{
    std::vector<ParamSet> sets;
    std::vector<std::size_t> splits;
    std::vector<std::pair<std::size_t, double>> moves; // parameter, value
    for (std::size_t k = 0; k < params.size(); ++k)
        for (double v : candidates(params[k].info, valueOf(best, params[k]), 0, random)) {
            sets.push_back(with(best, params[k], v));
            splits.push_back(params[k].position);
            moves.emplace_back(k, v);
        }
    if (4 * sets.size() > 3 * std::size_t(std::max(room, 0)))
        return false;
    const std::vector<double> gain = search.gains(sets, splits, best_score);
    // Each parameter's best move that gained (the first of equals).
    std::vector<std::size_t> chosen(params.size(), moves.size());
    for (std::size_t i = 0; i < moves.size(); ++i) {
        std::size_t& c = chosen[moves[i].first];
        if (gain[i] > 1e-9 && (c == moves.size() || gain[i] > gain[c]))
            c = i;
    }
    std::vector<std::size_t> order;
    for (std::size_t c : chosen)
        if (c != moves.size())
            order.push_back(c);
    std::stable_sort(order.begin(), order.end(),
                     [&](std::size_t a, std::size_t b) { return gain[a] > gain[b]; });
    for (std::size_t i : order) {
        if (search.exhausted())
            break;
        const Searched& p = params[moves[i].first];
        search.tryBatch({with(best, p, moves[i].second)}, {p.position}, best, best_score, result);
    }
    return true;
}

/// A best-first sweep, coordinate rounds, then random moves, until the budget is spent or the
/// search is cancelled.
void searchFrom(Search& search, const std::vector<Searched>& params, ParamSet& best,
                TuneScore& best_score, TuneResult& result, SplitMix64& random)
{
    std::vector<std::size_t> order(params.size());
    for (std::size_t i = 0; i < order.size(); ++i)
        order[i] = i;
    // The sweep draws the random values of no round; a small budget keeps the greedy first round.
    SplitMix64 sweep_random(random());
    const int first =
        sweepBestFirst(search, params, best, best_score, result, sweep_random, search.room()) ? 1
                                                                                              : 0;
    for (int round = first; round < 6 && !search.exhausted(); ++round) {
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
            std::vector<std::size_t> splits(sets.size(), p.position);
            improved =
                search.tryBatch(std::move(sets), std::move(splits), best, best_score, result) ||
                improved;
        }
        if (!improved && round >= 2)
            break;
    }
    while (!search.exhausted() && !params.empty()) {
        std::vector<ParamSet> sets;
        std::vector<std::size_t> splits;
        for (int c = 0; c < 8; ++c) {
            ParamSet set = best;
            std::size_t split = std::size_t(-1);
            // Parameters of one stage work together (a rule and its threshold): move a few of
            // the same stage's.
            const std::size_t stage_of = random() % params.size();
            std::vector<std::size_t> same;
            for (std::size_t k = 0; k < params.size(); ++k)
                if (params[k].position == params[stage_of].position)
                    same.push_back(k);
            const int moves = 2 + int(random() % 2);
            for (int m = 0; m < moves; ++m) {
                const Searched& p = params[same[random() % same.size()]];
                set = with(std::move(set), p, randomMove(p.info, valueOf(set, p), random));
                split = std::min(split, p.position);
            }
            sets.push_back(std::move(set));
            splits.push_back(split);
        }
        search.tryBatch(std::move(sets), std::move(splits), best, best_score, result);
    }
}

/// Puts back every change, or as much of it as loses nothing on the fit frames, then works out
/// what each change left buys (up to five evaluations per changed parameter).
void pruneAndPrice(Search& search, const std::vector<Searched>& params, ParamSet& best,
                   TuneScore& best_score, TuneResult& result)
{
    // The smallest change that keeps the fit score: each change put back, or else moved a
    // quarter, a half, three quarters of the way back (the first that loses nothing), so a
    // coarse grid's step (a minimum radius of 12.5 where 4 does as well) is not kept for nothing.
    for (const Searched& p : params) {
        const double now = valueOf(best, p);
        if (now == p.start)
            continue;
        std::vector<double> back{p.start};
        if (p.info.kind == ParamKind::Integer || p.info.kind == ParamKind::Real)
            for (double t : {0.75, 0.5, 0.25}) {
                const double v = legal(p.info, p.start + (1 - t) * (now - p.start));
                if (v != now && std::find(back.begin(), back.end(), v) == back.end())
                    back.push_back(v);
            }
        for (double v : back) {
            const ParamSet moved = with(best, p, v);
            const TuneScore score = search.scoreAll({moved}, search.fit(), false).front();
            if (score.total >= best_score.total) {
                best = moved;
                best_score = score;
                break;
            }
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

/// One whole search on the frames at `fit`: the best set, priced, with its history.
struct Fitted
{
    ParamSet best;
    TuneScore score;
    std::vector<TuneChange> changes;
    std::vector<std::pair<int, double>> history;
    int evaluations = 0;
    bool cancelled = false;
};

Fitted fitOn(const StreamInput& input, const std::vector<HeldFrame>& frames,
             const std::vector<std::size_t>& fit, const std::vector<Searched>& params,
             const TuneOptions& options, std::uint64_t seed, int progress_offset,
             int progress_total)
{
    Search search(input, frames, fit, options, progress_offset, progress_total);
    TuneResult priced; // searchFrom and pruneAndPrice fill its history and changes
    Fitted fitted;
    fitted.best = input.params;
    std::vector<std::vector<double>> groups;
    fitted.score = search.scoreAll({fitted.best}, fit, true, {}, &groups).front();
    search.setBestGroups(groups.front());
    priced.history.emplace_back(search.evaluations(), fitted.score.total);
    SplitMix64 random(seed);
    searchFrom(search, params, fitted.best, fitted.score, priced, random);
    fitted.cancelled = options.cancel && options.cancel->load();
    pruneAndPrice(search, params, fitted.best, fitted.score, priced);
    fitted.changes = std::move(priced.changes);
    fitted.history = std::move(priced.history);
    fitted.evaluations = search.evaluations();
    return fitted;
}

} // namespace

Result<TuneResult> tuneParams(StreamInput& input, const Annotations& truth,
                              const std::string& truth_path, const TuneOptions& options)
{
    return tuneStreams(input, truth, truth_path, options, {});
}

Result<TuneResult> tuneStreams(StreamInput& input, const Annotations& truth,
                               const std::string& truth_path, const TuneOptions& options,
                               const std::vector<TuneStream>& more)
{
    const auto started = std::chrono::steady_clock::now();
    if (Status s = checkTuneWeights(options.weights, scoredKinds(input.pipeline->perceptKinds()));
        !s)
        return s.error();
    if (!(options.holdout >= 0 && options.holdout <= 0.9))
        return Error{"the held-out share must be between 0 and 0.9"};
    if (options.budget < 1)
        return Error{"the budget must be at least one evaluation"};
    if (options.folds == 1 || options.folds < 0 || options.folds > 20)
        return Error{"the folds must be 0 (one held-out share) or 2 to 20"};
    if (input.adapt)
        return Error{"the parameters are fitted with the stream's table as it is (no --adapt)"};
    if (Status s = input.checkSettings(); !s)
        return s.error();
    auto params = searchedParams(input, options);
    if (!params)
        return params.error();
    const bool want_folds = options.folds >= 2;
    auto read = tuning::readStreams(input, truth, truth_path, options, more, want_folds);
    if (!read)
        return read.error();
    const std::vector<HeldFrame>& frames = read.value().first;
    const std::vector<tuning::FrameRole>& roles = read.value().second;
    std::vector<std::size_t> fit;
    std::vector<std::size_t> holdout;
    std::vector<std::size_t> validation;
    TuneResult result;
    for (std::size_t i = 0; i < frames.size(); ++i) {
        const bool aside = roles[i] == tuning::FrameRole::Validation;
        const bool held = roles[i] == tuning::FrameRole::Held;
        (aside ? validation : held ? holdout : fit).push_back(i);
        (aside  ? result.validation_frames
         : held ? result.holdout_frames
                : result.fit_frames)
            .push_back(frames[i].name);
    }
    // The folds cut the fitted streams' frames (the validation streams' stay aside).
    const std::size_t n = fit.size() + holdout.size();
    const bool cross = want_folds && n >= 2;
    const std::size_t folds = cross ? std::min<std::size_t>(std::size_t(options.folds), n) : 0;
    if (fit.empty())
        return Error{input.stream + ": no frame to fit (every scored frame is held out)"};

    result.parameters = int(params.value().size());
    result.start = input.params;
    result.folds = int(folds);
    const int total = options.budget * int(1 + folds);
    ParamSet best;
    try {
        Fitted fitted = fitOn(input, frames, fit, params.value(), options, options.seed, 0, total);
        best = fitted.best;
        result.changes = std::move(fitted.changes);
        result.history = std::move(fitted.history);
        result.evaluations = fitted.evaluations;
        result.cancelled = fitted.cancelled;
        Search scorer(input, frames, fit, options);
        // Both run whole (the search may have resumed frames), so their core time compares.
        const std::vector<TuneScore> on_fit = scorer.scoreAll({input.params, best}, fit, false);
        result.start_fit = on_fit[0];
        result.tuned_fit = on_fit[1];
        tuning::Tally start_held;
        tuning::Tally tuned_held;
        if (!holdout.empty()) {
            start_held = scorer.tallyOf(input.params, holdout);
            tuned_held = scorer.tallyOf(best, holdout);
        }
        // Cross-validation: each fold (a contiguous block) scored with the parameters fitted on
        // the others, so every frame is held out once.
        for (std::size_t k = 0; k < folds && !result.cancelled; ++k) {
            std::vector<std::size_t> others;
            std::vector<std::size_t> fold;
            for (std::size_t j = 0; j < n; ++j)
                (j * folds / n == k ? fold : others).push_back(fit[j]);
            const Fitted f = fitOn(input, frames, others, params.value(), options,
                                   options.seed + 1 + k, options.budget * int(1 + k), total);
            result.evaluations += f.evaluations;
            if (f.cancelled) {
                result.cancelled = true;
                break;
            }
            start_held += scorer.tallyOf(input.params, fold);
            tuned_held += scorer.tallyOf(f.best, fold);
            for (std::size_t i : fold)
                result.holdout_frames.push_back(frames[i].name);
        }
        result.start_holdout = tuning::scoreOf(start_held, options.weights);
        result.tuned_holdout = tuning::scoreOf(tuned_held, options.weights);
        if (!validation.empty()) { // like the held-out frames, the best so far after a cancel
            result.start_validation =
                tuning::scoreOf(scorer.tallyOf(input.params, validation), options.weights);
            result.tuned_validation =
                tuning::scoreOf(scorer.tallyOf(best, validation), options.weights);
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
