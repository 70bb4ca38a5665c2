// A/B comparison over a stream's scored frames: two runs, each frame matched by matchFrame() (the
// one matching path), and per class the frames whose verdict changed.
#include "visioncore/services/ab_compare.h"

#include <algorithm>
#include <map>

namespace fieldsight {
namespace {

/// The percepts of every frame of a run, by stream index.
std::map<std::size_t, PerceptSet> byIndex(StreamRun run)
{
    std::map<std::size_t, PerceptSet> out;
    for (FrameResult& f : run.frames)
        out.emplace(f.index, std::move(f.percepts));
    return out;
}

/// Progress of one of the two runs as a share of both.
RunHooks halfOf(const RunHooks& hooks, int half)
{
    RunHooks h;
    h.cancel = hooks.cancel;
    if (hooks.progress)
        h.progress = [&hooks, half](std::size_t done, std::size_t total) {
            hooks.progress(std::size_t(half) * total + done, 2 * total);
        };
    return h;
}

/// Runs the pipeline over `indices` with side `b`'s table and parameters swapped in for the run.
Result<StreamRun> runSideB(StreamInput& input, const AbSide& b,
                           const std::vector<std::size_t>& indices, int threads,
                           const RunHooks& hooks)
{
    const auto a_lut = input.lut;
    ParamSet a_params = input.params;
    if (b.lut)
        input.lut = b.lut;
    input.params = b.params;
    auto run = runStream(input, indices, threads, hooks);
    input.lut = a_lut;
    input.params = std::move(a_params);
    return run;
}

/// The score of each kind of one frame's matching, by kind (absent: not complete there).
std::map<const PerceptKind*, ClassScore> scoresOf(const FrameMatch& match)
{
    std::map<const PerceptKind*, ClassScore> out;
    for (const KindMatch& k : match.kinds)
        out.emplace(k.kind, k.score);
    return out;
}

/// Adds one frame's verdicts on both sides to the classes.
void addFrame(std::size_t index, const std::string& name, const FrameMatch& a, const FrameMatch& b,
              std::vector<AbClass>& classes)
{
    const auto scores_a = scoresOf(a);
    const auto scores_b = scoresOf(b);
    for (AbClass& out : classes) {
        const auto sa = scores_a.find(out.kind);
        if (sa == scores_a.end())
            continue; // the class's truth is not complete on this frame
        const AbFrame frame{index, name, sa->second, scores_b.at(out.kind)};
        ++out.frames;
        out.a += frame.a;
        out.b += frame.b;
        // Per class, by the number of errors: a frame of many lines is rarely all right on either
        // side, and B finding eight of its ten lines where A found one is a fix.
        const int errors_a = AbFrame::errors(frame.a), errors_b = AbFrame::errors(frame.b);
        if (errors_b < errors_a)
            out.fixed.push_back(frame);
        else if (errors_b > errors_a)
            out.broken.push_back(frame);
        else if (errors_a > 0)
            ++out.wrong_both;
    }
}

} // namespace

Result<AbComparison> compareAb(StreamInput& input, const AbSide& b, const Annotations& truth,
                               const std::string& truth_path, int threads, const RunHooks& hooks)
{
    auto names = scoredFrameIndices(input, truth, truth_path);
    if (!names)
        return names.error();
    std::vector<std::pair<std::size_t, std::string>> frames;
    for (const auto& [name, index] : names.value())
        frames.emplace_back(index, name);
    std::sort(frames.begin(), frames.end());
    std::vector<std::size_t> indices;
    for (const auto& [index, name] : frames)
        indices.push_back(index);
    indices.erase(std::unique(indices.begin(), indices.end()), indices.end());

    AbComparison result;
    auto run_a = runStream(input, indices, threads, halfOf(hooks, 0));
    if (!run_a)
        return run_a.error();
    if (run_a.value().cancelled) {
        result.cancelled = true;
        return result;
    }
    auto run_b = runSideB(input, b, indices, threads, halfOf(hooks, 1));
    if (!run_b)
        return run_b.error();
    if (run_b.value().cancelled) {
        result.cancelled = true;
        return result;
    }
    const auto detected_a = byIndex(std::move(run_a).value());
    const auto detected_b = byIndex(std::move(run_b).value());

    const int width = input.info().width;
    const int height = input.info().height;
    const std::vector<const PerceptKind*> kinds = scoredKinds(input.pipeline->perceptKinds());
    for (const PerceptKind* kind : kinds)
        result.classes.push_back({kind, scoredClassName(*kind), 0, {}, {}, {}, {}, 0});
    EvaluationScores boundary_a, boundary_b;
    for (const auto& [index, name] : frames) {
        const FrameAnnotation& annotation = truth.frames.at(name);
        const FrameMatch a = matchFrame(detected_a.at(index), annotation, width, height, kinds);
        const FrameMatch bm = matchFrame(detected_b.at(index), annotation, width, height, kinds);
        ++result.frames;
        addFrame(index, name, a, bm, result.classes);
        for (auto [match, sum] : {std::pair{&a, &boundary_a}, std::pair{&bm, &boundary_b}})
            if (match->boundary_error >= 0) {
                sum->boundary_error_sum += match->boundary_error;
                ++sum->boundary_frames;
            }
    }
    result.boundary_a = boundary_a.boundaryMeanError();
    result.boundary_b = boundary_b.boundaryMeanError();
    result.boundary_frames_a = boundary_a.boundary_frames;
    result.boundary_frames_b = boundary_b.boundary_frames;
    return result;
}

} // namespace fieldsight
