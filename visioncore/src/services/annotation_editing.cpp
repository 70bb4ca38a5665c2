#include "visioncore/services/annotation_editing.h"

#include <algorithm>
#include <map>

namespace fieldsight {

FrameStates frameStates(const std::vector<std::string>& names, const Annotations& annotations)
{
    std::map<std::string, const FrameAnnotation*> by_stem;
    for (const auto& [name, frame] : annotations.frames)
        by_stem.emplace(frameStem(name), &frame);
    FrameStates states;
    states.annotated.assign(names.size(), false);
    states.done.assign(names.size(), false);
    for (std::size_t i = 0; i < names.size(); ++i) {
        auto it = annotations.frames.find(names[i]);
        const FrameAnnotation* frame = it != annotations.frames.end() ? &it->second : nullptr;
        if (!frame)
            if (const auto s = by_stem.find(frameStem(names[i])); s != by_stem.end())
                frame = s->second;
        states.annotated[i] = frame != nullptr;
        states.done[i] = frame && frame->done;
    }
    return states;
}

FrameAnnotation copiedAnnotation(const FrameAnnotation& from)
{
    FrameAnnotation copy = from;
    copy.done = false;
    copy.reviewed.clear();
    return copy;
}

std::optional<std::size_t> previousAnnotated(const std::vector<bool>& annotated, std::size_t index)
{
    for (std::size_t i = std::min(index, annotated.size()); i-- > 0;)
        if (annotated[i])
            return i;
    return std::nullopt;
}

FrameAnnotation detectionsAsTruth(FrameAnnotation frame, const PerceptSet& detections,
                                  const std::vector<const PerceptKind*>& kinds)
{
    for (const PerceptKind* kind : kinds) {
        const PerceptEntry* found = detections.find(*kind);
        if (kind->form == ShapeForm::None || !found || !found->present())
            continue;
        PerceptEntry& truth = frame.truth.entry(*kind);
        truth.setShapes(found->shapes());
        frame.truth.markPresent(truth);
        frame.flags.erase(std::string(kind->truth_key));
        frame.reviewed.erase(std::string(kind->truth_key));
    }
    frame.done = false;
    return frame;
}

FrameAnnotation reviewedNothingHere(FrameAnnotation frame, const PerceptKind& kind)
{
    PerceptEntry& list = frame.truth.entry(kind);
    list.clear();
    frame.truth.markPresent(list);
    frame.flags.erase(std::string(kind.truth_key));
    frame.reviewed.emplace(kind.truth_key);
    return frame;
}

std::size_t objectCount(const FrameAnnotation& frame)
{
    std::size_t n = 0;
    for (const PerceptEntry* entry : frame.truth.entries())
        n += entry->size();
    return n;
}

std::optional<NotDoneHit> nextNotDone(const std::vector<bool>& done, std::size_t from,
                                      int direction)
{
    const std::size_t n = done.size();
    if (n == 0)
        return std::nullopt;
    from = std::min(from, n - 1);
    const std::size_t step = direction < 0 ? n - 1 : 1; // -1 modulo n
    for (std::size_t k = 1; k <= n; ++k) {
        const std::size_t i = (from + k * step) % n;
        if (!done[i])
            return NotDoneHit{i, direction < 0 ? i >= from : i <= from};
    }
    return std::nullopt;
}

} // namespace fieldsight
