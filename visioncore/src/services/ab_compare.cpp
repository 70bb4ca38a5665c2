// A/B comparison over a stream's annotated frames: two runs, each frame scored by scoreFrame
// (the one matching of SPEC §5.3), and per class the frames whose verdict changed.
#include "visioncore/services/ab_compare.h"

#include "visioncore/percepts/ball.h"
#include "visioncore/percepts/field_boundary.h"
#include "visioncore/percepts/goalpost.h"
#include "visioncore/percepts/obstacle.h"

#include <algorithm>
#include <map>

namespace fieldsight {
namespace {

/// The classes scoreFrame scores, with the names `eval` prints them by.
struct ScoredClass
{
    const PerceptKind* kind;
    const char* name;
    ClassScore EvaluationScores::*score;
};

const std::vector<ScoredClass>& scoredClasses()
{
    static const std::vector<ScoredClass> classes{
        {&perceptKind<Ball>(), "ball", &EvaluationScores::balls},
        {&perceptKind<Goalpost>(), "goalpost", &EvaluationScores::goalposts},
        {&perceptKind<Obstacle>(), "obstacle", &EvaluationScores::obstacles},
    };
    return classes;
}

bool anyComplete(const FrameAnnotation& frame)
{
    if (frame.complete(perceptKind<FieldBoundary>().truth_key))
        return true;
    return std::any_of(scoredClasses().begin(), scoredClasses().end(),
                       [&](const ScoredClass& c) { return frame.complete(c.kind->truth_key); });
}

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

} // namespace

Result<std::vector<std::pair<std::size_t, std::string>>>
completeFrames(const StreamReader& reader, const std::string& stream, const Annotations& truth,
               const std::string& truth_path)
{
    std::map<std::string, std::size_t> by_name;
    std::map<std::string, std::size_t> by_stem;
    for (std::size_t i = 0; i < reader.info().frame_count; ++i) {
        const std::string name = reader.frameName(i);
        by_name.emplace(name, i);
        by_stem.emplace(frameStem(name), i);
    }
    std::vector<std::pair<std::size_t, std::string>> frames;
    for (const auto& [name, annotation] : truth.frames) {
        if (!anyComplete(annotation))
            continue;
        if (auto it = by_name.find(name); it != by_name.end())
            frames.emplace_back(it->second, name);
        else if (auto st = by_stem.find(frameStem(name)); st != by_stem.end())
            frames.emplace_back(st->second, name);
        else
            return Error{truth_path + ": frame '" + name + "' is annotated but " + stream +
                         " has no such frame"};
    }
    std::sort(frames.begin(), frames.end());
    return frames;
}

Result<AbComparison> compareAb(StreamInput& input, const AbSide& b, const Annotations& truth,
                               const std::string& truth_path, int threads, const RunHooks& hooks)
{
    auto frames = completeFrames(*input.reader, input.stream, truth, truth_path);
    if (!frames)
        return frames.error();
    std::vector<std::size_t> indices;
    for (const auto& [index, name] : frames.value())
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
    // Side B on the same input, its table and parameters swapped in for the run only.
    const auto a_lut = input.lut;
    ParamSet a_params = input.params;
    if (b.lut)
        input.lut = b.lut;
    input.params = b.params;
    auto run_b = runStream(input, indices, threads, halfOf(hooks, 1));
    input.lut = a_lut;
    input.params = std::move(a_params);
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
    for (const ScoredClass& c : scoredClasses())
        result.classes.push_back({c.kind, c.name, 0, {}, {}, {}, {}, 0});
    EvaluationScores boundary_a, boundary_b;
    for (const auto& [index, name] : frames.value()) {
        const FrameAnnotation& annotation = truth.frames.at(name);
        EvaluationScores a, bs;
        scoreFrame(detected_a.at(index), annotation.truth, width, height, a);
        scoreFrame(detected_b.at(index), annotation.truth, width, height, bs);
        ++result.frames;
        for (std::size_t k = 0; k < scoredClasses().size(); ++k) {
            const ScoredClass& c = scoredClasses()[k];
            if (!annotation.complete(c.kind->truth_key))
                continue;
            AbClass& out = result.classes[k];
            const AbFrame frame{index, name, a.*c.score, bs.*c.score};
            ++out.frames;
            out.a += frame.a;
            out.b += frame.b;
            const bool wrong_a = AbFrame::wrong(frame.a), wrong_b = AbFrame::wrong(frame.b);
            if (wrong_a && !wrong_b)
                out.fixed.push_back(frame);
            else if (!wrong_a && wrong_b)
                out.broken.push_back(frame);
            else if (wrong_a && wrong_b)
                ++out.wrong_both;
        }
        if (annotation.complete(perceptKind<FieldBoundary>().truth_key)) {
            boundary_a.boundary_error_sum += a.boundary_error_sum;
            boundary_a.boundary_frames += a.boundary_frames;
            boundary_b.boundary_error_sum += bs.boundary_error_sum;
            boundary_b.boundary_frames += bs.boundary_frames;
        }
    }
    result.boundary_a = boundary_a.boundaryMeanError();
    result.boundary_b = boundary_b.boundaryMeanError();
    result.boundary_frames_a = boundary_a.boundary_frames;
    result.boundary_frames_b = boundary_b.boundary_frames;
    return result;
}

} // namespace fieldsight
