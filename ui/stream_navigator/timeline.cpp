#include "ui/stream_navigator/timeline.h"

#include "ui/document/editing_session.h"
#include "ui/stream_navigator/annotation_strip.h"
#include "ui/stream_navigator/effect_strip.h"
#include "ui/stream_navigator/frame_marks_strip.h"
#include "ui/stream_navigator/light_strip.h"
#include "ui/stream_navigator/stream_navigator.h"
#include "ui/widgets/elided_label.h"

#include <QLabel>
#include <QSlider>

namespace fieldsight::ui {

Timeline::Timeline(EditingSession& session, StreamNavigator& navigator) : m_session(session)
{
    QSlider& slider = *navigator.slider();
    // What the last change did to the evaluation's scores, over the strip of what it did to
    // every frame; shown once there is such a change. A line longer than the timeline ends in
    // "…" (the tooltip has it all).
    m_scores_change = new ElidedLabel(&navigator);
    m_scores_change->setObjectName(QStringLiteral("scores_change"));
    m_scores_change->setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Preferred);
    m_scores_change->setContentsMargins(4, 1, 4, 1);
    // Its line is kept while hidden: its showing never shrinks the view above.
    QSizePolicy keep = m_scores_change->sizePolicy();
    keep.setRetainSizeWhenHidden(true);
    m_scores_change->setSizePolicy(keep);
    m_scores_change->hide();
    navigator.addTimelineStrip(m_scores_change);
    m_effect = new EffectStrip(session.effectScan(), slider, &navigator);
    navigator.addTimelineStrip(m_effect);
    QObject::connect(m_effect, &EffectStrip::frameClicked, &navigator, &StreamNavigator::goToFrame);
    QObject::connect(&slider, &QSlider::valueChanged, m_effect, qOverload<>(&QWidget::update));
    m_annotations =
        new AnnotationStrip(session.annotations(), session.stream(), slider, &navigator);
    navigator.addTimelineStrip(m_annotations);
    QObject::connect(m_annotations, &AnnotationStrip::frameClicked, &navigator,
                     &StreamNavigator::goToFrame);
    m_disagreements = new FrameMarksStrip(slider, QColor(0, 190, 255), &navigator);
    m_disagreements->setObjectName(QStringLiteral("disagreement_strip"));
    m_disagreements->setToolTip(QObject::tr("Frames where detections and truth disagree"));
    navigator.addTimelineStrip(m_disagreements);
    QObject::connect(&slider, &QSlider::valueChanged, m_disagreements,
                     qOverload<>(&QWidget::update));
    m_light = new LightStrip(session.lightScan(), slider, &navigator);
    m_light->setToolTip(QObject::tr("How far the light has moved from the table's, per frame"));
    navigator.addTimelineStrip(m_light);
    QObject::connect(m_light, &LightStrip::frameClicked, &navigator, &StreamNavigator::goToFrame);
}

void Timeline::showEvaluation(std::map<std::size_t, QString> marks, const QString& change)
{
    m_disagreements->setMarks(std::move(marks), m_session.stream().frameCount());
    m_scores_change->setText(QObject::tr("Scores after the last change: %1").arg(change));
    m_scores_change->setToolTip(m_scores_change->text());
    m_scores_change->setVisible(!change.isEmpty());
}

} // namespace fieldsight::ui
