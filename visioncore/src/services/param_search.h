// The parameter search's state shared by its steps: parameter sets scored in batches on the
// held frames (one scorer per worker), the budget, and the rule a move must keep to be taken.
#pragma once

#include "param_tuning_eval.h"

#include <memory>
#include <vector>

namespace fieldsight::tuning {

class Search
{
public:
    Search(const StreamInput& input, const std::vector<HeldFrame>& frames,
           std::vector<std::size_t> fit, const TuneOptions& options, int progress_offset = 0,
           int progress_total = 0);

    /// The best set's score on each of the fit frames' blocks, which a move must keep.
    void setBestGroups(std::vector<double> groups) { m_best_groups = std::move(groups); }

    /// Scores every set in `sets` on `positions`; counts them against the budget when `count`.
    /// `splits[i]` (when given): set i moves no parameter of the stages before that position
    /// from the best set's (Scorer::tally reuses what they made).
    /// `groups` (when given, and `positions` are the fit frames): each set's score on each block.
    std::vector<TuneScore> scoreAll(const std::vector<ParamSet>& sets,
                                    const std::vector<std::size_t>& positions, bool count,
                                    const std::vector<std::size_t>& splits = {},
                                    std::vector<std::vector<double>>* groups = nullptr);

    /// Each set's gain over `best_score` on the fit frames, or -1 where a block of the fit
    /// frames would lose (as tryBatch judges); counted against the budget, and only as many sets
    /// as it has room for are scored (the rest -1).
    std::vector<double> gains(const std::vector<ParamSet>& sets,
                              const std::vector<std::size_t>& splits, const TuneScore& best_score);

    /// Tries `sets` (moves from `best`); keeps the best if it beats `best_score`. True if so.
    bool tryBatch(std::vector<ParamSet> sets, std::vector<std::size_t> splits, ParamSet& best,
                  TuneScore& best_score, TuneResult& result);

    /// The counts of `params` on `positions` (not counted against the budget).
    Tally tallyOf(const ParamSet& params, const std::vector<std::size_t>& positions)
    {
        return m_scorers.front()->tally(params, m_frames, positions);
    }

    int evaluations() const { return m_evaluations; }
    const std::vector<std::size_t>& fit() const { return m_fit; }
    /// Evaluations left in the budget.
    int room() const { return m_options.budget - m_evaluations; }
    bool exhausted() const { return room() <= 0 || (m_options.cancel && m_options.cancel->load()); }

private:
    /// A move that costs one block of the fit frames what it buys on another fits those frames,
    /// not the scene: every block must keep the best set's score.
    bool keepsEveryBlock(const std::vector<double>& groups) const;

    const std::vector<HeldFrame>& m_frames;
    std::vector<std::size_t> m_fit;
    const TuneOptions& m_options;
    std::vector<std::unique_ptr<Scorer>> m_scorers;
    std::size_t m_group_count = 1;
    std::vector<std::size_t> m_group_of; ///< each fit frame's block
    std::vector<double> m_best_groups;   ///< the best set's score on each block
    int m_progress_offset = 0;
    int m_progress_total = 0;
    int m_evaluations = 0;
};

} // namespace fieldsight::tuning
