// The annotated object the annotation tools have selected (frame, kind, index), for the actions on
// one object (the Object menu); and how they name the stream's frames in the annotations.
#pragma once

#include "visioncore/percepts/percept_set.h"

#include <QObject>

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace fieldsight::ui {

class EditingSession;

class AnnotationSelection : public QObject
{
    Q_OBJECT
public:
    struct Object
    {
        std::string frame; ///< the stream's name of the frame (AnnotationsDocument finds it)
        const PerceptKind* kind = nullptr;
        std::size_t index = 0; ///< in the frame's list of `kind`
    };

    using QObject::QObject;
    const std::optional<Object>& object() const { return m_object; }
    /// The selected object's index when it is one of `kind` on `frame`.
    std::optional<std::size_t> indexOf(const PerceptKind& kind, const std::string& frame) const;
    void select(const std::string& frame, const PerceptKind& kind, std::size_t index);
    void clear();
    /// How many frames the Object menu last propagated an object (either way), offered again.
    int propagateFrames() const { return m_propagate_frames; }
    void setPropagateFrames(int frames) { m_propagate_frames = frames; }

signals:
    void changed();

private:
    std::optional<Object> m_object;
    int m_propagate_frames = 10;
};

/// The name of the frame shown, as the stream names it (empty: no stream, or a camera).
std::string currentFrameName(EditingSession& session);
/// Every frame of the stream in order, named as the annotations key it (AnnotationsDocument::
/// keyOf), for the actions over frames (interpolation, propagation).
std::vector<std::string> annotationFrameKeys(EditingSession& session);

} // namespace fieldsight::ui
