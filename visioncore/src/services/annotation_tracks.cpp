#include "visioncore/services/annotation_tracks.h"

#include <algorithm>
#include <cstdlib>
#include <set>

namespace fieldsight {

namespace {

/// The shape `t` of the way from `a` to `b` (0: a, 1: b), point by point.
EditShape lerp(const EditShape& a, const EditShape& b, double t)
{
    EditShape out;
    out.radius = a.radius + (b.radius - a.radius) * t;
    for (std::size_t i = 0; i < a.points.size(); ++i)
        out.points.push_back({a.points[i].x + (b.points[i].x - a.points[i].x) * t,
                              a.points[i].y + (b.points[i].y - a.points[i].y) * t});
    return out;
}

/// The frame holds nothing worth keeping: no object, not done, no kind reviewed.
bool saysNothing(const FrameAnnotation& frame)
{
    if (frame.done || !frame.reviewed.empty())
        return false;
    for (const PerceptEntry* entry : frame.truth.entries())
        if (entry->size() > 0)
            return false;
    return true;
}

int highestTrack(const FrameAnnotation& frame)
{
    int highest = 0;
    for (const auto& [key, list] : frame.flags)
        for (const ObjectFlags& f : list)
            highest = std::max(highest, f.track);
    return highest;
}

} // namespace

std::vector<EditShape> shapesOf(const FrameAnnotation& frame, const PerceptKind& kind)
{
    const PerceptEntry* entry = frame.truth.find(kind);
    return entry && entry->present() ? entry->shapes() : std::vector<EditShape>{};
}

std::size_t addObject(FrameAnnotation& frame, const PerceptKind& kind,
                      const AnnotatedObject& object)
{
    PerceptEntry& entry = frame.truth.entry(kind);
    std::vector<EditShape> shapes = entry.present() ? entry.shapes() : std::vector<EditShape>{};
    shapes.push_back(object.shape);
    entry.setShapes(shapes);
    frame.truth.markPresent(entry);
    const std::size_t index = shapes.size() - 1;
    frame.setFlags(kind.truth_key, index, object.flags);
    return index;
}

void setShape(FrameAnnotation& frame, const PerceptKind& kind, std::size_t index,
              const EditShape& shape)
{
    PerceptEntry& entry = frame.truth.entry(kind);
    std::vector<EditShape> shapes = entry.shapes();
    if (index >= shapes.size())
        return;
    shapes[index] = shape;
    entry.setShapes(shapes);
}

void removeObject(FrameAnnotation& frame, const PerceptKind& kind, std::size_t index)
{
    PerceptEntry& entry = frame.truth.entry(kind);
    std::vector<EditShape> shapes = entry.shapes();
    if (index >= shapes.size())
        return;
    shapes.erase(shapes.begin() + std::ptrdiff_t(index));
    entry.setShapes(shapes);
    frame.eraseFlags(kind.truth_key, index);
}

std::optional<std::size_t> findTrack(const FrameAnnotation& frame, const PerceptKind& kind,
                                     int track)
{
    if (track <= 0)
        return std::nullopt;
    const PerceptEntry* entry = frame.truth.find(kind);
    const std::size_t count = entry && entry->present() ? entry->size() : 0;
    for (std::size_t i = 0; i < count; ++i)
        if (frame.flagsOf(kind.truth_key, i).track == track)
            return i;
    return std::nullopt;
}

int freshTrack(const Annotations& annotations)
{
    int highest = 0;
    for (const auto& [name, frame] : annotations.frames)
        highest = std::max(highest, highestTrack(frame));
    return highest + 1;
}

bool tracksInterpolate(const PerceptKind& kind)
{
    return kind.form == ShapeForm::Circle || kind.form == ShapeForm::Box ||
           kind.form == ShapeForm::Segment;
}

const FrameAnnotation* AnnotationChanges::find(const std::string& frame) const
{
    if (const auto it = m_changed.find(frame); it != m_changed.end())
        return &it->second;
    const auto it = m_base.frames.find(frame);
    return it != m_base.frames.end() ? &it->second : nullptr;
}

FrameAnnotation& AnnotationChanges::edit(const std::string& frame)
{
    if (const auto it = m_changed.find(frame); it != m_changed.end())
        return it->second;
    const auto base = m_base.frames.find(frame);
    return m_changed.emplace(frame, base != m_base.frames.end() ? base->second : FrameAnnotation{})
        .first->second;
}

std::map<std::string, std::optional<FrameAnnotation>> AnnotationChanges::frames() const
{
    std::map<std::string, std::optional<FrameAnnotation>> out;
    for (const auto& [name, frame] : m_changed)
        out.emplace(name, saysNothing(frame) ? std::nullopt : std::optional(frame));
    return out;
}

int AnnotationChanges::freshTrack() const
{
    int highest = 0;
    for (const auto& [name, frame] : m_base.frames)
        if (!m_changed.count(name))
            highest = std::max(highest, highestTrack(frame));
    for (const auto& [name, frame] : m_changed)
        highest = std::max(highest, highestTrack(frame));
    return highest + 1;
}

void interpolateTrack(AnnotationChanges& changes, const std::vector<std::string>& frames,
                      const PerceptKind& kind, int track)
{
    if (!tracksInterpolate(kind) || track <= 0)
        return;
    struct Key
    {
        std::size_t at;
        ObjectFlags flags;
        EditShape shape;
    };
    std::vector<Key> keys;
    for (std::size_t at = 0; at < frames.size(); ++at) {
        const FrameAnnotation* frame = changes.find(frames[at]);
        const auto index = frame ? findTrack(*frame, kind, track) : std::nullopt;
        if (!index)
            continue;
        const ObjectFlags flags = frame->flagsOf(kind.truth_key, *index);
        if (flags.keyframe)
            keys.push_back({at, flags, shapesOf(*frame, kind)[*index]});
    }

    std::set<std::size_t> filled;
    for (std::size_t k = 1; k < keys.size(); ++k) {
        const Key& a = keys[k - 1];
        const Key& b = keys[k];
        if (!b.flags.interpolate || b.at - a.at < 2 ||
            a.shape.points.size() != b.shape.points.size())
            continue;
        for (std::size_t at = a.at + 1; at < b.at; ++at) {
            const double t = double(at - a.at) / double(b.at - a.at);
            const EditShape shape = lerp(a.shape, b.shape, t);
            FrameAnnotation& frame = changes.edit(frames[at]);
            ObjectFlags flags;
            flags.track = track;
            flags.interpolated = true;
            if (const auto index = findTrack(frame, kind, track)) {
                flags.concealed = frame.flagsOf(kind.truth_key, *index).concealed;
                setShape(frame, kind, *index, shape);
                frame.setFlags(kind.truth_key, *index, flags);
            } else {
                flags.concealed = a.flags.concealed && b.flags.concealed;
                addObject(frame, kind, {shape, flags});
            }
            filled.insert(at);
        }
    }

    // What an earlier interpolation made outside today's spans goes.
    for (std::size_t at = 0; at < frames.size(); ++at) {
        if (filled.count(at))
            continue;
        const FrameAnnotation* frame = changes.find(frames[at]);
        const auto index = frame ? findTrack(*frame, kind, track) : std::nullopt;
        if (!index || !frame->flagsOf(kind.truth_key, *index).interpolated)
            continue;
        FrameAnnotation& edited = changes.edit(frames[at]);
        for (auto i = findTrack(edited, kind, track);
             i && edited.flagsOf(kind.truth_key, *i).interpolated;
             i = findTrack(edited, kind, track))
            removeObject(edited, kind, *i);
    }
}

namespace {

/// Object `index` of `kind` on `frames[at]`, if there is one.
std::optional<AnnotatedObject> objectAt(const AnnotationChanges& changes,
                                        const std::vector<std::string>& frames, std::size_t at,
                                        const PerceptKind& kind, std::size_t index)
{
    const FrameAnnotation* frame = at < frames.size() ? changes.find(frames[at]) : nullptr;
    if (!frame)
        return std::nullopt;
    const std::vector<EditShape> shapes = shapesOf(*frame, kind);
    if (index >= shapes.size())
        return std::nullopt;
    return AnnotatedObject{shapes[index], frame->flagsOf(kind.truth_key, index)};
}

} // namespace

bool setKeyframe(AnnotationChanges& changes, const std::vector<std::string>& frames, std::size_t at,
                 const PerceptKind& kind, std::size_t index, bool keyframe)
{
    const auto object = objectAt(changes, frames, at, kind, index);
    if (!object || !tracksInterpolate(kind))
        return false;
    ObjectFlags flags = object->flags;
    if (flags.track == 0)
        flags.track = changes.freshTrack();
    flags.keyframe = keyframe;
    if (keyframe)
        flags.interpolated = false;
    changes.edit(frames[at]).setFlags(kind.truth_key, index, flags);
    interpolateTrack(changes, frames, kind, flags.track);
    return true;
}

bool setInterpolate(AnnotationChanges& changes, const std::vector<std::string>& frames,
                    std::size_t at, const PerceptKind& kind, std::size_t index, bool interpolate)
{
    const auto object = objectAt(changes, frames, at, kind, index);
    if (!object || !object->flags.keyframe || !tracksInterpolate(kind))
        return false;
    ObjectFlags flags = object->flags;
    flags.interpolate = interpolate;
    changes.edit(frames[at]).setFlags(kind.truth_key, index, flags);
    interpolateTrack(changes, frames, kind, flags.track);
    return true;
}

bool removeFromTrack(AnnotationChanges& changes, const std::vector<std::string>& frames,
                     std::size_t at, const PerceptKind& kind, std::size_t index)
{
    const auto object = objectAt(changes, frames, at, kind, index);
    if (!object)
        return false;
    const ObjectFlags flags = object->flags;
    removeObject(changes.edit(frames[at]), kind, index);
    if (flags.track <= 0)
        return true;
    if (flags.interpolated) {
        // Walk out from the deleted object to the keyframes around it: the objects between keep
        // their shapes as plain objects of the track; the later keyframe stops interpolating.
        const auto settle = [&](std::size_t i) {
            const FrameAnnotation* frame = changes.find(frames[i]);
            const auto there = frame ? findTrack(*frame, kind, flags.track) : std::nullopt;
            if (!there)
                return false;
            ObjectFlags f = frame->flagsOf(kind.truth_key, *there);
            const bool keyframe = f.keyframe;
            if (keyframe && i > at)
                f.interpolate = false;
            f.interpolated = false;
            changes.edit(frames[i]).setFlags(kind.truth_key, *there, f);
            return keyframe;
        };
        for (std::size_t i = at; i-- > 0 && !settle(i);) {
        }
        for (std::size_t i = at + 1; i < frames.size() && !settle(i); ++i) {
        }
    }
    interpolateTrack(changes, frames, kind, flags.track);
    return true;
}

std::size_t propagate(AnnotationChanges& changes, const std::vector<std::string>& frames,
                      std::size_t at, const PerceptKind& kind, std::size_t index, int count)
{
    const auto object = objectAt(changes, frames, at, kind, index);
    if (!object || count == 0)
        return 0;
    const bool one_a_frame = kind.form == ShapeForm::Polyline;
    ObjectFlags source = object->flags;
    if (source.track == 0 && !one_a_frame) {
        source.track = changes.freshTrack();
        changes.edit(frames[at]).setFlags(kind.truth_key, index, source);
    }
    ObjectFlags copy;
    copy.concealed = source.concealed;
    copy.track = source.track;
    std::size_t made = 0;
    for (int k = 1; k <= std::abs(count); ++k) {
        const long long to = (long long)at + (count > 0 ? k : -k);
        if (to < 0 || to >= (long long)frames.size())
            break;
        FrameAnnotation& frame = changes.edit(frames[std::size_t(to)]);
        std::optional<std::size_t> there = findTrack(frame, kind, source.track);
        if (one_a_frame && !shapesOf(frame, kind).empty())
            there = 0;
        if (there && frame.flagsOf(kind.truth_key, *there).keyframe)
            continue; // placed by hand: kept
        if (there) {
            setShape(frame, kind, *there, object->shape);
            frame.setFlags(kind.truth_key, *there, copy);
        } else {
            addObject(frame, kind, {object->shape, copy});
        }
        ++made;
    }
    interpolateTrack(changes, frames, kind, source.track);
    return made;
}

} // namespace fieldsight
