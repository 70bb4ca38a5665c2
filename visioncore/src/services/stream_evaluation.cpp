// Evaluating a stream: the scored frames of an annotations file found in it, run (those whose
// detections are not known already) and scored by evaluateFrames().
#include "visioncore/services/evaluation.h"

#include "visioncore/framework/controller.h"

#include <algorithm>
#include <utility>

namespace fieldsight {

std::string defaultTruthPath(const std::string& stream)
{
    return besideStream(stream, "annotations.json");
}

Result<std::map<std::string, std::size_t>> scoredFrameIndices(const StreamInput& input,
                                                              const Annotations& truth,
                                                              const std::string& truth_path)
{
    std::map<std::string, std::size_t> by_name;
    std::map<std::string, std::size_t> by_stem;
    for (std::size_t i = 0; i < input.info().frame_count; ++i) {
        const std::string name = input.reader->frameName(i);
        by_name.emplace(name, i);
        by_stem.emplace(frameStem(name), i);
    }
    const std::vector<const PerceptKind*> kinds = scoredKinds(input.pipeline->perceptKinds());
    std::map<std::string, std::size_t> indices;
    for (const auto& [name, annotation] : truth.frames) {
        if (!isScored(annotation, kinds))
            continue;
        if (auto it = by_name.find(name); it != by_name.end()) {
            indices.emplace(name, it->second);
        } else if (auto st = by_stem.find(frameStem(name)); st != by_stem.end()) {
            indices.emplace(name, st->second);
        } else {
            return Error{truth_path + ": frame '" + name + "' is " +
                         (annotation.done ? "marked done" : "reviewed") + " but " + input.stream +
                         " has no such frame"};
        }
    }
    return indices;
}

Result<EvalReport> evaluateStream(StreamInput& input, const Annotations& truth,
                                  const std::string& truth_path, int threads, const RunHooks& hooks)
{
    return evaluateStream(input, truth, truth_path, threads, hooks, {});
}

Result<EvalReport> evaluateStream(StreamInput& input, const Annotations& truth,
                                  const std::string& truth_path, int threads, const RunHooks& hooks,
                                  const std::map<std::string, PerceptSet>& known,
                                  std::size_t* frames_run)
{
    auto names = scoredFrameIndices(input, truth, truth_path);
    if (!names)
        return names.error();
    std::vector<std::size_t> indices;
    for (const auto& [name, index] : names.value())
        if (known.find(name) == known.end())
            indices.push_back(index);
    std::sort(indices.begin(), indices.end());
    indices.erase(std::unique(indices.begin(), indices.end()), indices.end());
    if (frames_run)
        *frames_run = indices.size();

    StreamRun run;
    if (!indices.empty()) {
        auto ran = runStream(input, indices, threads, hooks);
        if (!ran)
            return ran.error();
        run = std::move(ran).value();
    }
    if (run.cancelled)
        return Error{input.stream + ": evaluation cancelled"};
    std::map<std::size_t, const FrameResult*> by_index;
    for (const FrameResult& f : run.frames)
        by_index.emplace(f.index, &f);
    EvalReport report;
    for (const auto& [name, index] : names.value()) {
        const auto k = known.find(name);
        report.detected.emplace(name, k != known.end() ? k->second : by_index.at(index)->percepts);
    }
    report.stream = input.stream;
    report.lut_path = input.lut_path;
    report.truth_path = truth_path;
    Evaluation evaluation =
        evaluateFrames(report.detected, truth, input.info().width, input.info().height,
                       scoredKinds(input.pipeline->perceptKinds()));
    report.scores = evaluation.scores;
    report.disagreements = std::move(evaluation.disagreements);
    report.frame_index = std::move(names).value();
    return report;
}

} // namespace fieldsight
