#include "ui/status_line.h"

#include "ui/document/editing_session.h"
#include "ui/frame_view/frame_view.h"
#include "ui/stream_navigator/annotation_strip.h"
#include "ui/stream_navigator/effect_strip.h"
#include "ui/stream_navigator/timeline.h"
#include "ui/tools/tool_manager.h"

#include <QLabel>
#include <QStatusBar>

namespace fieldsight::ui {

StatusLine::StatusLine(QStatusBar& bar, EditingSession& session, const Timeline& timeline,
                       FrameView& view, ToolManager& tools)
    : QObject(&bar), m_bar(bar), m_session(session), m_tools(tools)
{
    auto* zoom = new QLabel(&bar);
    m_time = new QLabel(&bar);
    m_effect = new QLabel(&bar);
    m_effect->setObjectName(QStringLiteral("effect_summary"));
    // Ignored width: a long summary is cut at the timing field, not pushed into it (the whole
    // text is the tooltip).
    m_effect->setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Preferred);
    bar.addWidget(m_effect, 1);
    auto* annotation = new QLabel(&bar);
    annotation->setObjectName(QStringLiteral("annotation_status"));
    bar.addPermanentWidget(annotation);
    connect(&timeline.annotationStrip(), &AnnotationStrip::statusChanged, annotation,
            &QLabel::setText);
    bar.addPermanentWidget(m_time);
    bar.addPermanentWidget(zoom);
    EffectStrip& effect = timeline.effectStrip();
    const auto showEffect = [this, e = &effect] {
        m_effect->setText(e->summary());
        m_effect->setToolTip(e->summary());
    };
    connect(&session.effectScan(), &EditEffectScan::updated, this, showEffect);
    connect(&session.lightScan(), &LightScan::enabledChanged, this, showEffect);
    connect(&view, &FrameView::zoomChanged, zoom,
            [zoom](double z) { zoom->setText(tr("zoom %1%").arg(z * 100, 0, 'f', 0)); });
    connect(&session.stream(), &StreamDocument::frameReady, this, &StatusLine::showTimes);
    connect(&tools, &ToolManager::previewChanged, this, &StatusLine::showPreview);
}

void StatusLine::showTimes()
{
    if (const auto& out = m_session.stream().current())
        m_time->setText(tr("core %1 ms · worker %2 ms")
                            .arg(out->result.report.total_ms, 0, 'f', 3)
                            .arg(out->worker_ms, 0, 'f', 2));
}

void StatusLine::showPreview()
{
    const QString text = m_tools.preview().text;
    if (!text.isEmpty())
        m_bar.showMessage(text);
    else if (!m_preview_shown.isEmpty() && m_bar.currentMessage() == m_preview_shown)
        m_bar.clearMessage();
    m_preview_shown = text;
}

} // namespace fieldsight::ui
