// The strips under the navigator's slider, over one editing session: what the last change did to
// the evaluation's scores, what it did to every frame (the edit effect), the annotated frames, the
// frames where detections and truth disagree and how far the light has moved; a click on a strip
// goes to its frame.
#pragma once

#include <QString>

#include <cstddef>
#include <map>

class QLabel;

namespace fieldsight::ui {

class AnnotationStrip;
class EditingSession;
class EffectStrip;
class FrameMarksStrip;
class LightStrip;
class StreamNavigator;

class Timeline
{
public:
    /// Adds the strips to `navigator`'s timeline (they are its children).
    Timeline(EditingSession& session, StreamNavigator& navigator);

    EffectStrip& effectStrip() const { return *m_effect; }
    AnnotationStrip& annotationStrip() const { return *m_annotations; }
    /// The marks of the frames where detections and truth disagree.
    FrameMarksStrip& disagreementStrip() const { return *m_disagreements; }
    LightStrip& lightStrip() const { return *m_light; }

    /// A new evaluation: its frames where detections and truth disagree, and what the last change
    /// did to its scores (`change`; empty: none yet, and the line stays hidden).
    void showEvaluation(std::map<std::size_t, QString> marks, const QString& change);

private:
    EditingSession& m_session;
    QLabel* m_scores_change = nullptr;
    EffectStrip* m_effect = nullptr;
    AnnotationStrip* m_annotations = nullptr;
    FrameMarksStrip* m_disagreements = nullptr;
    LightStrip* m_light = nullptr;
};

} // namespace fieldsight::ui
