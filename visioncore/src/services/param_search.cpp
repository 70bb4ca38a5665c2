// Parameter sets scored in batches whose make-up depends only on the caller, each set on one
// worker, so a search's result is the same on any number of cores.
#include "param_search.h"

#include "visioncore/services/worker_pool.h"

#include <algorithm>
#include <stdexcept>

namespace fieldsight::tuning {

Search::Search(const StreamInput& input, const std::vector<HeldFrame>& frames,
               std::vector<std::size_t> fit, const TuneOptions& options, int progress_offset,
               int progress_total)
    : m_frames(frames), m_fit(std::move(fit)), m_options(options),
      m_progress_offset(progress_offset),
      m_progress_total(progress_total > 0 ? progress_total : options.budget)
{
    const int workers = workerCount(options.threads, 64);
    for (int w = 0; w < workers; ++w)
        m_scorers.push_back(std::make_unique<Scorer>(input, options.reuse_stages));
    const std::size_t groups = std::clamp<std::size_t>(std::size_t(std::max(options.agree, 1)), 1,
                                                       std::max<std::size_t>(m_fit.size(), 1));
    m_group_count = groups;
    for (std::size_t j = 0; j < m_fit.size(); ++j)
        m_group_of.push_back(j * groups / m_fit.size());
}

std::vector<TuneScore> Search::scoreAll(const std::vector<ParamSet>& sets,
                                        const std::vector<std::size_t>& positions, bool count,
                                        const std::vector<std::size_t>& splits,
                                        std::vector<std::vector<double>>* groups)
{
    std::vector<TuneScore> scores(sets.size());
    if (groups)
        groups->assign(sets.size(), std::vector<double>(m_group_count, 0.0));
    const int workers = int(std::min(m_scorers.size(), std::max<std::size_t>(sets.size(), 1)));
    std::vector<std::string> problems(static_cast<std::size_t>(workers));
    runOnWorkers(workers, [&](int w) {
        try {
            for (std::size_t i = std::size_t(w); i < sets.size(); i += std::size_t(workers)) {
                const std::vector<Tally> each = m_scorers[std::size_t(w)]->tallies(
                    sets[i], m_frames, positions, splits.empty() ? 0 : splits[i]);
                Tally sum;
                std::vector<Tally> by_group(m_group_count);
                for (std::size_t j = 0; j < each.size(); ++j) {
                    sum += each[j];
                    if (groups)
                        by_group[m_group_of[j]] += each[j];
                }
                scores[i] = scoreOf(sum, m_options.weights);
                if (groups)
                    for (std::size_t g = 0; g < m_group_count; ++g)
                        (*groups)[i][g] = scoreOf(by_group[g], m_options.weights).total;
            }
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

bool Search::keepsEveryBlock(const std::vector<double>& groups) const
{
    if (m_best_groups.size() != groups.size())
        return false;
    for (std::size_t g = 0; g < groups.size(); ++g)
        if (groups[g] < m_best_groups[g] - 1e-9)
            return false;
    return true;
}

std::vector<double> Search::gains(const std::vector<ParamSet>& sets,
                                  const std::vector<std::size_t>& splits,
                                  const TuneScore& best_score)
{
    std::vector<double> out(sets.size(), -1.0);
    if (exhausted())
        return out;
    const std::size_t n = std::min(std::size_t(room()), sets.size());
    std::vector<std::vector<double>> groups;
    const std::vector<TuneScore> scores =
        scoreAll({sets.begin(), sets.begin() + std::ptrdiff_t(n)}, m_fit, true,
                 {splits.begin(), splits.begin() + std::ptrdiff_t(n)}, &groups);
    for (std::size_t i = 0; i < n; ++i)
        if (keepsEveryBlock(groups[i]))
            out[i] = scores[i].total - best_score.total;
    return out;
}

bool Search::tryBatch(std::vector<ParamSet> sets, std::vector<std::size_t> splits, ParamSet& best,
                      TuneScore& best_score, TuneResult& result)
{
    if (room() <= 0 || sets.empty())
        return false;
    if (int(sets.size()) > room()) {
        sets.resize(std::size_t(room()));
        splits.resize(std::size_t(room()));
    }
    std::vector<std::vector<double>> groups;
    const std::vector<TuneScore> scores = scoreAll(sets, m_fit, true, splits, &groups);
    std::size_t winner = sets.size();
    double top = best_score.total + 1e-9;
    for (std::size_t i = 0; i < scores.size(); ++i)
        if (keepsEveryBlock(groups[i]) && scores[i].total > top) {
            top = scores[i].total;
            winner = i;
        }
    if (m_options.progress)
        m_options.progress(
            {m_progress_offset + m_evaluations, m_progress_total, std::max(top, best_score.total)});
    if (winner == sets.size())
        return false;
    best = sets[winner];
    best_score = scores[winner];
    m_best_groups = groups[winner];
    result.history.emplace_back(m_evaluations, best_score.total);
    return true;
}

} // namespace fieldsight::tuning
