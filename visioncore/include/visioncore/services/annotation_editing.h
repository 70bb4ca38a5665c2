// Frame-level annotation edits, Qt-free, as the window's Annotate menu makes them: a frame's
// annotations carried onto another, a frame's detections made its truth, a kind marked "reviewed,
// nothing here", and finding the next frame not yet done. Each returns the frame's new
// annotation; the caller applies it (as one undo step in the window).
#pragma once

#include "visioncore/io/annotations.h"

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace fieldsight {

/// What the annotations say of each frame of a stream, by index (frames matched by frameStem()).
struct FrameStates
{
    std::vector<bool> annotated; ///< the frame has an annotation (of any content)
    std::vector<bool> done;      ///< ... marked done
};
FrameStates frameStates(const std::vector<std::string>& names, const Annotations& annotations);

/// `from`'s annotation as the start of another frame's: the same objects with their flags (track
/// ids kept, so a track goes on), but not done and no kind reviewed: the copy is still to be
/// checked on its new frame.
FrameAnnotation copiedAnnotation(const FrameAnnotation& from);

/// The nearest frame before `index` with an annotation (`annotated` as frameStates gives it).
std::optional<std::size_t> previousAnnotated(const std::vector<bool>& annotated, std::size_t index);

/// `frame` with `detections` as its truth, for the annotator to correct. Replaces, kind by kind:
/// every kind of `kinds` drawn by hand (form != None) whose list `detections` has (its stage
/// ran) gets exactly the detected objects as geometry, with default flags and no longer
/// reviewed; the other kinds keep their truth. Merging would double every object already
/// annotated that the detector also found; a replaced list is one undo away. The frame is no
/// longer done (its truth is now the detector's).
FrameAnnotation detectionsAsTruth(FrameAnnotation frame, const PerceptSet& detections,
                                  const std::vector<const PerceptKind*>& kinds);

/// `frame` with `kind`'s list present and empty and the kind reviewed: "reviewed, nothing here".
FrameAnnotation reviewedNothingHere(FrameAnnotation frame, const PerceptKind& kind);

/// The objects of `frame` (every present list's size).
std::size_t objectCount(const FrameAnnotation& frame);

/// The frame the next-not-done search lands on.
struct NotDoneHit
{
    std::size_t index = 0;
    bool wrapped = false; ///< past the stream's end (or start) and round again
};
/// The first frame after `from` (`direction` > 0) or before it (< 0) that is not done, going round
/// the stream's end; `from` itself last, when it is the only one. None when every frame is done.
std::optional<NotDoneHit> nextNotDone(const std::vector<bool>& done, std::size_t from,
                                      int direction);

} // namespace fieldsight
