#include "ui/tools/annotate_tool.h"

#include "ui/adapters/text.h"
#include "ui/document/editing_session.h"
#include "ui/tools/annotation_selection.h"
#include "ui/tools/shape_geometry.h"

#include "visioncore/services/annotation_tracks.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace fieldsight::ui {

namespace {

/// How near an object a click must be to take it, screen px.
constexpr double kNearScreenPx = 6;
/// A polyline's end this near the image's left or right edge is put on it, screen px (a
/// polyline is scored over x = 0..width-1).
constexpr double kEdgeSnapScreenPx = 12;

PointF pointOf(QPoint p)
{
    return {double(p.x()), double(p.y())};
}

/// Where `event` is for a shape of `form`: a circle (a ball's centre and radius, which the
/// detector gives to a fraction of a pixel) to a tenth of a pixel, the other forms whole pixels
/// (the box fields are whole pixels anyway).
PointF pointOf(const ToolEvent& event, ShapeForm form)
{
    if (form != ShapeForm::Circle)
        return pointOf(event.point);
    const auto tenth = [](double v) { return std::round(v * 10) / 10; };
    return {tenth(event.position.x()), tenth(event.position.y())};
}

QString formName(ShapeForm form)
{
    switch (form) {
    case ShapeForm::Circle:
        return QStringLiteral("circle");
    case ShapeForm::Box:
        return QStringLiteral("box");
    case ShapeForm::Polyline:
        return QStringLiteral("polyline");
    case ShapeForm::Segment:
        return QStringLiteral("segment");
    case ShapeForm::None:
        break;
    }
    return {};
}

} // namespace

AnnotateTool::AnnotateTool(ToolContext& context, const PerceptKind& kind, int ordinal)
    : Tool(context), m_kind(kind), m_ordinal(ordinal)
{
    EditingSession& session = context.session;
    m_frame = currentFrameName(session);
    connect(&session.annotations(), &AnnotationsDocument::changed, this, [this] {
        if (const auto index = selected(); index && *index >= currentShapes().size())
            m_context.selection.clear();
        emit previewChanged();
    });
    connect(&session.stream(), &StreamDocument::currentIndexChanged, this, [this] {
        cancel();
        followTrack();
        emit previewChanged();
    });
    connect(&session.stream(), &StreamDocument::streamChanged, this, [this] {
        cancel();
        if (m_context.selection.object() && m_context.selection.object()->kind == &m_kind)
            m_context.selection.clear();
        m_frame = currentFrameName(m_context.session);
        emit previewChanged();
    });
    connect(&context.selection, &AnnotationSelection::changed, this, &Tool::previewChanged);
}

ToolInfo AnnotateTool::info() const
{
    const QString title = toQString(m_kind.title);
    const QString edit = tr("Click one to select it, drag it to move it, drag a handle to resize "
                            "it; Delete removes it");
    QString how;
    switch (m_kind.form) {
    case ShapeForm::Circle:
        how = tr("press at the centre and drag to the rim. %1").arg(edit);
        break;
    case ShapeForm::Box:
        how = tr("drag from corner to corner. %1").arg(edit);
        break;
    case ShapeForm::Segment:
        how = tr("drag from end to end. %1").arg(edit);
        break;
    case ShapeForm::Polyline:
        how = tr("click its points from side to side, double-click or Enter to end (Escape drops "
                 "it). One a frame: drag a point to move it, click the line to add one; Delete "
                 "removes it");
        break;
    case ShapeForm::None:
        break;
    }
    ToolInfo info{QStringLiteral("annotate.%1").arg(toQString(m_kind.truth_key)),
                  title,
                  tr("Annotate %1: %2").arg(title, how),
                  QKeySequence(),
                  QStringLiteral("annotate-%1").arg(formName(m_kind.form)),
                  QStringLiteral("annotate")};
    if (m_ordinal >= 1 && m_ordinal <= 9)
        info.shortcut = QKeySequence(Qt::SHIFT | Qt::Key(Qt::Key_0 + m_ordinal));
    return info;
}

std::vector<EditShape> AnnotateTool::currentShapes() const
{
    const FrameAnnotation* frame =
        m_context.session.annotations().frame(currentFrameName(m_context.session));
    return frame ? shapesOf(*frame, m_kind) : std::vector<EditShape>{};
}

std::optional<std::size_t> AnnotateTool::selected() const
{
    return m_context.selection.indexOf(m_kind, currentFrameName(m_context.session));
}

void AnnotateTool::select(std::size_t index)
{
    m_context.selection.select(currentFrameName(m_context.session), m_kind, index);
}

std::optional<std::size_t> AnnotateTool::objectAt(const std::vector<EditShape>& shapes, PointF p,
                                                  double tolerance) const
{
    std::optional<std::size_t> best;
    double best_distance = 0;
    double best_area = 0;
    for (std::size_t i = 0; i < shapes.size(); ++i) {
        const double d = distanceTo(m_kind.form, shapes[i], p);
        const double area = areaOf(m_kind.form, shapes[i]);
        if (d > tolerance)
            continue;
        if (!best || d < best_distance || (d == best_distance && area < best_area)) {
            best = i;
            best_distance = d;
            best_area = area;
        }
    }
    return best;
}

ObjectFlags AnnotateTool::touched(ObjectFlags flags) const
{
    if (!tracksInterpolate(m_kind) || flags.keyframe)
        return flags;
    bool keyed = flags.interpolated;
    for (const auto& [name, frame] : m_context.session.annotations().annotations().frames) {
        if (keyed || flags.track <= 0)
            break;
        const auto index = findTrack(frame, m_kind, flags.track);
        keyed = index && frame.flagsOf(m_kind.truth_key, *index).keyframe;
    }
    if (keyed) {
        flags.keyframe = true;
        flags.interpolated = false;
    }
    return flags;
}

void AnnotateTool::press(const ToolEvent& event)
{
    if (event.button != Qt::LeftButton)
        return;
    m_frame = currentFrameName(m_context.session);
    if (m_frame.empty())
        return;
    AnnotationsDocument& doc = m_context.session.annotations();
    const PointF p = pointOf(event, m_kind.form);
    m_zoom = std::max(event.zoom, 1e-3);
    const double near = std::max(1.5, kNearScreenPx / m_zoom);
    if (!m_draft.empty()) {
        if (event.double_click)
            finishDraft();
        else
            m_draft.push_back(p);
        emit previewChanged();
        return;
    }
    const std::vector<EditShape> shapes = currentShapes();
    const bool polyline = m_kind.form == ShapeForm::Polyline;
    m_point.reset();
    // The selected object's handles first; a polyline's points are always handles.
    std::optional<std::size_t> index = polyline && !shapes.empty() ? 0 : selected();
    const auto startDrag = [&](std::size_t i, std::optional<std::size_t> handle,
                               const QString& what) {
        const FrameAnnotation* frame = doc.frame(m_frame);
        m_drag = Drag{i,
                      handle,
                      p,
                      shapes[i],
                      touched(frame->flagsOf(m_kind.truth_key, i)),
                      what.arg(toQString(m_kind.title)),
                      doc.newMerge()};
        select(i);
        if (polyline)
            m_point = handle;
    };
    if (index && *index < shapes.size()) {
        if (const auto handle = handleAt(handlesOf(m_kind.form, shapes[*index]), p, near)) {
            startDrag(*index, handle, tr("%1: resize"));
            emit previewChanged();
            return;
        }
    }
    if (const auto hit = objectAt(shapes, p, near)) {
        if (!polyline) {
            startDrag(*hit, std::nullopt, tr("%1: move"));
        } else {
            // A click on the line adds a point there, which the drag then moves.
            EditShape with = shapes[*hit];
            const auto segment = nearestSegment(with, p);
            const std::size_t at = segment ? segment->first + 1 : with.points.size();
            with.points.insert(with.points.begin() + std::ptrdiff_t(at), p);
            startDrag(*hit, at, tr("%1: add a point"));
            m_drag->start = with;
            dragTo(with);
        }
    } else {
        m_context.selection.clear();
        if (!polyline) {
            m_create_from = p;
            m_create_to = p;
        } else if (shapes.empty()) {
            m_draft = {p};
        }
    }
    emit previewChanged();
}

void AnnotateTool::move(const ToolEvent& event)
{
    const PointF p = pointOf(event, m_kind.form);
    if (!m_draft.empty()) {
        m_draft.back() = p; // the point just clicked follows the drag
        emit previewChanged();
    } else if (m_create_from) {
        m_create_to = p;
        emit previewChanged();
    } else if (m_drag) {
        dragTo(m_drag->handle ? dragHandle(m_kind.form, m_drag->start, *m_drag->handle, p)
                              : moved(m_drag->start, {p.x - m_drag->from.x, p.y - m_drag->from.y}));
    }
}

void AnnotateTool::dragTo(const EditShape& shape)
{
    AnnotationsDocument& doc = m_context.session.annotations();
    const FrameAnnotation* now = doc.frame(m_frame);
    if (!m_drag || !now || m_drag->index >= shapesOf(*now, m_kind).size())
        return;
    FrameAnnotation after = *now;
    setShape(after, m_kind, m_drag->index, shape);
    after.setFlags(m_kind.truth_key, m_drag->index, m_drag->flags);
    if (doc.editFrame(m_frame, std::move(after), m_drag->text, m_drag->merge))
        m_drag->edited = true;
}

void AnnotateTool::release(const ToolEvent& event)
{
    if (event.button != Qt::LeftButton)
        return;
    if (m_create_from) {
        const auto shape =
            shapeFromDrag(m_kind.form, *std::exchange(m_create_from, std::nullopt), m_create_to);
        AnnotationsDocument& doc = m_context.session.annotations();
        const FrameAnnotation* now = doc.frame(m_frame);
        if (shape && currentFrameName(m_context.session) == m_frame) {
            FrameAnnotation after = now ? *now : FrameAnnotation{};
            ObjectFlags flags;
            flags.track = freshTrack(doc.annotations()); // a track of its own
            const std::size_t index = addObject(after, m_kind, {*shape, flags});
            if (doc.editFrame(m_frame, std::move(after),
                              tr("%1: add").arg(toQString(m_kind.title))))
                select(index);
        }
    } else if (m_drag) {
        finishDrag();
    }
    emit previewChanged();
}

void AnnotateTool::finishDrag()
{
    const Drag drag = *std::exchange(m_drag, std::nullopt);
    if (!drag.edited || !drag.flags.keyframe)
        return;
    AnnotationChanges changes(m_context.session.annotations().annotations());
    interpolateTrack(changes, annotationFrameKeys(m_context.session), m_kind, drag.flags.track);
    m_context.session.annotations().edit(drag.text, changes.frames(), drag.merge);
}

void AnnotateTool::finishDraft()
{
    std::vector<PointF> points = std::exchange(m_draft, {});
    while (points.size() >= 2 && points.back() == points[points.size() - 2])
        points.pop_back();
    if (points.size() < 2)
        return;
    std::sort(points.begin(), points.end(),
              [](const PointF& a, const PointF& b) { return a.x < b.x; });
    const auto& out = m_context.session.stream().current();
    const int width = out ? out->frame.ycbcr.cols : 0;
    const double snap = kEdgeSnapScreenPx / m_zoom;
    if (points.front().x <= snap)
        points.front().x = 0;
    if (width > 0 && points.back().x >= width - 1 - snap)
        points.back().x = width - 1;
    AnnotationsDocument& doc = m_context.session.annotations();
    const FrameAnnotation* now = doc.frame(m_frame);
    FrameAnnotation after = now ? *now : FrameAnnotation{};
    const EditShape shape{points, 0};
    if (!shapesOf(after, m_kind).empty())
        setShape(after, m_kind, 0, shape);
    else // one a frame: no track to follow
        addObject(after, m_kind, {shape, {}});
    if (doc.editFrame(m_frame, std::move(after), tr("%1: draw").arg(toQString(m_kind.title))))
        select(0);
}

void AnnotateTool::cancel()
{
    m_point.reset();
    m_draft.clear();
    m_create_from.reset();
    m_drag.reset();
}

void AnnotateTool::followTrack()
{
    const std::string now = currentFrameName(m_context.session);
    const std::string before = std::exchange(m_frame, now);
    const auto index = m_context.selection.indexOf(m_kind, before);
    if (!index || before == now)
        return;
    const AnnotationsDocument& doc = m_context.session.annotations();
    const FrameAnnotation* old = doc.frame(before);
    const FrameAnnotation* next = doc.frame(now);
    const int track = old ? old->flagsOf(m_kind.truth_key, *index).track : 0;
    if (const auto there = next ? findTrack(*next, m_kind, track) : std::nullopt)
        m_context.selection.select(now, m_kind, *there);
    else
        m_context.selection.clear();
}

void AnnotateTool::hover(std::optional<QPoint> pixel)
{
    m_hover = pixel ? std::optional(pointOf(*pixel)) : std::nullopt;
    if (!m_draft.empty())
        emit previewChanged(); // the line to the pointer
}

bool AnnotateTool::key(int key)
{
    if ((key == Qt::Key_Return || key == Qt::Key_Enter) && !m_draft.empty()) {
        finishDraft();
    } else if (key == Qt::Key_Escape && (!m_draft.empty() || m_create_from)) {
        cancel();
    } else if (key == Qt::Key_Escape && selected()) {
        m_context.selection.clear();
    } else {
        return false;
    }
    emit previewChanged();
    return true;
}

void AnnotateTool::deactivate()
{
    cancel();
    if (m_context.selection.object() && m_context.selection.object()->kind == &m_kind)
        m_context.selection.clear();
    emit previewChanged();
}

bool AnnotateTool::deleteSelection()
{
    const auto index = selected();
    if (!index)
        return false;
    AnnotationsDocument& doc = m_context.session.annotations();
    if (const auto point = std::exchange(m_point, std::nullopt)) {
        // A chosen point of a line of more than two: that point alone goes.
        std::vector<EditShape> shapes = currentShapes();
        if (*index < shapes.size() && *point < shapes[*index].points.size() &&
            shapes[*index].points.size() > 2) {
            FrameAnnotation after = *doc.frame(m_frame);
            shapes[*index].points.erase(shapes[*index].points.begin() + std::ptrdiff_t(*point));
            setShape(after, m_kind, *index, shapes[*index]);
            doc.editFrame(m_frame, std::move(after),
                          tr("%1: delete a point").arg(toQString(m_kind.title)));
            return true;
        }
    }
    AnnotationChanges changes(doc.annotations());
    const std::vector<std::string> frames = annotationFrameKeys(m_context.session);
    const std::string key = doc.keyOf(currentFrameName(m_context.session));
    const auto at = std::find(frames.begin(), frames.end(), key);
    if (at == frames.end())
        return false;
    removeFromTrack(changes, frames, std::size_t(at - frames.begin()), m_kind, *index);
    m_context.selection.clear();
    doc.edit(tr("%1: delete").arg(toQString(m_kind.title)), changes.frames());
    return true;
}

ToolFactory annotateTools()
{
    return [](ToolContext& context) {
        std::vector<std::unique_ptr<Tool>> tools;
        int ordinal = 0;
        for (const PerceptKind* kind : context.session.annotations().kinds())
            if (kind->form != ShapeForm::None)
                tools.push_back(std::make_unique<AnnotateTool>(context, *kind, ++ordinal));
        return tools;
    };
}

} // namespace fieldsight::ui
