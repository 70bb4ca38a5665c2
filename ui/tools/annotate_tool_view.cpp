// What an annotation tool shows: the frame's objects of its kind over the image (the selected
// one with its handles, interpolated ones dashed, concealed ones faint, the shape being drawn)
// and a status line on the selected object or the drawing.
#include "ui/tools/annotate_tool.h"

#include "ui/adapters/image_adapter.h"
#include "ui/adapters/text.h"
#include "ui/document/editing_session.h"
#include "ui/tools/annotation_selection.h"
#include "ui/tools/shape_geometry.h"

#include "visioncore/services/annotation_tracks.h"

#include <QStringList>

#include <cmath>

namespace fieldsight::ui {

namespace {

QString number(double v)
{
    return QString::number(v, 'f', v == std::round(v) ? 0 : 1);
}

QString pointCount(std::size_t n)
{
    return n == 1 ? AnnotateTool::tr("1 point") : AnnotateTool::tr("%1 points").arg(n);
}

QString pointText(PointF p)
{
    return QStringLiteral("(%1, %2)").arg(number(p.x), number(p.y));
}

} // namespace

ToolOutline AnnotateTool::outline() const
{
    ToolOutline outline;
    const QColor colour = toQColor(m_kind.colour);
    const auto shapeOf = [this, &colour](const EditShape& shape, bool selected) {
        OutlineShape s;
        for (const PointF& p : outlinePoints(m_kind.form, shape))
            s.polygon << QPointF(p.x, p.y);
        if (m_kind.form == ShapeForm::Circle)
            s.radius = shape.radius;
        s.closed = m_kind.form == ShapeForm::Box;
        s.colour = colour;
        s.selected = selected;
        if (selected)
            for (const PointF& p : handlesOf(m_kind.form, shape))
                s.handles << QPointF(p.x, p.y);
        return s;
    };
    const FrameAnnotation* frame =
        m_context.session.annotations().frame(currentFrameName(m_context.session));
    const std::vector<EditShape> shapes =
        frame ? shapesOf(*frame, m_kind) : std::vector<EditShape>{};
    const auto chosen = selected();
    for (std::size_t i = 0; i < shapes.size(); ++i) {
        OutlineShape s = shapeOf(shapes[i], chosen == i);
        if (chosen == i && m_point && *m_point < std::size_t(s.handles.size()))
            s.chosen_handle = int(*m_point);
        const ObjectFlags flags = frame->flagsOf(m_kind.truth_key, i);
        s.dashed = flags.interpolated;
        if (flags.concealed) // partly hidden: drawn faint
            s.colour.setAlpha(120);
        outline.shapes.push_back(std::move(s));
    }
    if (m_create_from)
        if (const auto shape = shapeFromDrag(m_kind.form, *m_create_from, m_create_to))
            outline.shapes.push_back(shapeOf(*shape, true));
    if (!m_draft.empty()) {
        EditShape line{m_draft, 0};
        OutlineShape s = shapeOf(line, true);
        if (m_hover && !(m_hover == m_draft.back()))
            s.polygon << QPointF(m_hover->x, m_hover->y);
        outline.shapes.push_back(std::move(s));
    }
    return outline;
}

ToolPreview AnnotateTool::preview(std::optional<QPoint>) const
{
    ToolPreview p;
    const QString title = toQString(m_kind.title);
    const auto describe = [this](const EditShape& s) -> QString {
        if (s.points.empty())
            return {};
        switch (m_kind.form) {
        case ShapeForm::Circle:
            return tr("centre %1, radius %2").arg(pointText(s.points[0]), number(s.radius));
        case ShapeForm::Box:
        case ShapeForm::Segment:
            return s.points.size() < 2 ? QString()
                                       : QStringLiteral("%1 – %2").arg(pointText(s.points[0]),
                                                                       pointText(s.points[1]));
        case ShapeForm::Polyline:
            return pointCount(s.points.size());
        case ShapeForm::None:
            break;
        }
        return {};
    };
    if (!m_draft.empty()) {
        p.text = tr("%1: %2; double-click or Enter ends the line, Escape drops it")
                     .arg(title, pointCount(m_draft.size()));
    } else if (m_create_from) {
        if (const auto shape = shapeFromDrag(m_kind.form, *m_create_from, m_create_to))
            p.text = QStringLiteral("%1: %2").arg(title, describe(*shape));
    } else if (const auto index = selected()) {
        const std::vector<EditShape> shapes = currentShapes();
        const FrameAnnotation* frame =
            m_context.session.annotations().frame(currentFrameName(m_context.session));
        if (*index < shapes.size() && frame) {
            const ObjectFlags f = frame->flagsOf(m_kind.truth_key, *index);
            QStringList parts{QStringLiteral("%1 #%2: %3")
                                  .arg(title)
                                  .arg(*index + 1)
                                  .arg(describe(shapes[*index]))};
            if (f.track > 0)
                parts << tr("track %1").arg(f.track);
            if (f.keyframe)
                parts << (f.interpolate ? tr("keyframe") : tr("keyframe, not interpolated"));
            if (f.interpolated)
                parts << tr("interpolated");
            if (f.concealed)
                parts << tr("concealed");
            if (m_point && m_kind.form == ShapeForm::Polyline)
                parts << tr("point %1 chosen: Delete removes it").arg(*m_point + 1);
            p.text = parts.join(QStringLiteral(" · "));
        }
    }
    return p;
}

} // namespace fieldsight::ui
