#include "ui/tools/annotation_selection.h"

#include "ui/adapters/local_path.h"
#include "ui/document/editing_session.h"

namespace fieldsight::ui {

std::optional<std::size_t> AnnotationSelection::indexOf(const PerceptKind& kind,
                                                        const std::string& frame) const
{
    if (!m_object || m_object->kind != &kind || m_object->frame != frame)
        return std::nullopt;
    return m_object->index;
}

void AnnotationSelection::select(const std::string& frame, const PerceptKind& kind,
                                 std::size_t index)
{
    if (m_object && m_object->frame == frame && m_object->kind == &kind && m_object->index == index)
        return;
    m_object = Object{frame, &kind, index};
    emit changed();
}

void AnnotationSelection::clear()
{
    if (!m_object)
        return;
    m_object.reset();
    emit changed();
}

std::string currentFrameName(EditingSession& session)
{
    StreamDocument& stream = session.stream();
    if (stream.frameCount() == 0)
        return {};
    return toLocalPath(stream.frameName(stream.currentIndex()));
}

std::vector<std::string> annotationFrameKeys(EditingSession& session)
{
    StreamDocument& stream = session.stream();
    const AnnotationsDocument& doc = session.annotations();
    std::vector<std::string> keys;
    keys.reserve(stream.frameCount());
    for (std::size_t i = 0; i < stream.frameCount(); ++i)
        keys.push_back(doc.keyOf(toLocalPath(stream.frameName(i))));
    return keys;
}

} // namespace fieldsight::ui
