// Annotated objects over a stream's frames: editing one object of a kind with its flags kept
// parallel, fresh track ids, keyframes with linear interpolation between them, and an object
// propagated to the frames after or before it. Every action is gathered as changed frames over
// the annotations it starts from, for the caller to apply as one step.
#pragma once

#include "visioncore/io/annotations.h"

#include <cstddef>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace fieldsight {

/// Object `index` of `kind` on one frame, as geometry with its flags.
struct AnnotatedObject
{
    EditShape shape;
    ObjectFlags flags;
};

/// The objects of `kind` on `frame`, in order (none when it has none).
std::vector<EditShape> shapesOf(const FrameAnnotation& frame, const PerceptKind& kind);
/// Appends `object` to `frame`'s list of `kind` (made present); returns its index.
std::size_t addObject(FrameAnnotation& frame, const PerceptKind& kind,
                      const AnnotatedObject& object);
/// Replaces the shape of object `index` of `kind` (its flags stay).
void setShape(FrameAnnotation& frame, const PerceptKind& kind, std::size_t index,
              const EditShape& shape);
/// Removes object `index` of `kind`; the later objects and their flags move up together.
void removeObject(FrameAnnotation& frame, const PerceptKind& kind, std::size_t index);
/// The index of the first object of `kind` on `frame` in track `track` (> 0), if any.
std::optional<std::size_t> findTrack(const FrameAnnotation& frame, const PerceptKind& kind,
                                     int track);

/// One larger than every track id in `annotations` (1 when none has a track).
int freshTrack(const Annotations& annotations);

/// Keyframes and interpolation apply to `kind`'s objects: circles, boxes and segments (a
/// polyline may change its number of points, and a frame holds at most one).
bool tracksInterpolate(const PerceptKind& kind);

/// What one action changes, frame by frame, over `base` (which it never modifies; it must
/// outlive this).
class AnnotationChanges
{
public:
    explicit AnnotationChanges(const Annotations& base) : m_base(base) {}

    /// The frame as changed so far (null: it has no annotation).
    const FrameAnnotation* find(const std::string& frame) const;
    /// The frame to change: a copy of the base's the first time (empty when it had none).
    FrameAnnotation& edit(const std::string& frame);
    /// Every frame touched, after the action; nullopt for a frame left with no object, not done
    /// and no kind reviewed (it says nothing, so it is removed).
    std::map<std::string, std::optional<FrameAnnotation>> frames() const;
    /// The highest track id in the base and the changes so far, plus one.
    int freshTrack() const;

private:
    const Annotations& m_base;
    std::map<std::string, FrameAnnotation> m_changed;
};

/// Makes the frames of track `track` of `kind` agree with its keyframes: between two keyframes
/// of the track (in the order of `frames`, the stream's frame names as the annotations key
/// them), when the later one's `interpolate` is on, every frame gets the shape linearly
/// interpolated between them, flagged `interpolated` (a non-keyframe object of the track already
/// there is replaced in place, keeping its `concealed` flag); interpolated objects outside such
/// spans are removed. Nothing for a kind that does not interpolate.
void interpolateTrack(AnnotationChanges& changes, const std::vector<std::string>& frames,
                      const PerceptKind& kind, int track);

/// Sets or clears the keyframe mark of object `index` of `kind` on `frames[at]` (an object
/// without a track gets a fresh one; a keyframe is no longer interpolated), then interpolates
/// its track again. False when there is no such object or its kind does not interpolate.
bool setKeyframe(AnnotationChanges& changes, const std::vector<std::string>& frames, std::size_t at,
                 const PerceptKind& kind, std::size_t index, bool keyframe);

/// Sets whether the frames from the track's previous keyframe to keyframe `index` are
/// interpolated, then interpolates the track again. False when the object is no keyframe.
bool setInterpolate(AnnotationChanges& changes, const std::vector<std::string>& frames,
                    std::size_t at, const PerceptKind& kind, std::size_t index, bool interpolate);

/// Deletes object `index` of `kind` on `frames[at]` so that it stays deleted. A keyframe: the
/// track is interpolated again without it. An interpolated object: its span (from the track's
/// keyframe before to the one after) stops being interpolated, the span's other objects kept as
/// they are now (no longer flagged interpolated), so a later edit of the keyframes does not bring
/// the deleted one back. Returns false when there is no such object.
bool removeFromTrack(AnnotationChanges& changes, const std::vector<std::string>& frames,
                     std::size_t at, const PerceptKind& kind, std::size_t index);

/// Copies object `index` of `kind` on `frames[at]` to the next `count` frames (the previous
/// -`count` when negative, up to the stream's ends) as objects of its track (an object without
/// a track gets a fresh one): the track's object on a frame there takes the shape, a keyframe
/// of the track is left as it is; a polyline (no track) replaces the frame's polyline. The
/// track is then interpolated again. Returns how many frames got the object.
std::size_t propagate(AnnotationChanges& changes, const std::vector<std::string>& frames,
                      std::size_t at, const PerceptKind& kind, std::size_t index, int count);

} // namespace fieldsight
