// Object: what is set on the one annotated object an annotation tool selected: concealed, a
// keyframe of its track and whether the frames since the previous keyframe are interpolated, and
// the object propagated to the next or previous frames. Each is one undoable edit of the
// annotations document (AnnotationsDocument; the Qt-free rules are in
// visioncore/services/annotation_tracks.h).
#include "ui/actions/menus.h"
#include "ui/dialogs/dialogs.h"
#include "ui/document/editing_session.h"
#include "ui/tools/tool_manager.h"
#include "ui/tools/annotation_selection.h"

#include "visioncore/services/annotation_tracks.h"

#include <QMenuBar>

#include <memory>

namespace fieldsight::ui {

namespace {

/// The selected object, on the frame shown.
struct Target
{
    std::size_t at = 0; ///< the frame's index in the stream
    const PerceptKind* kind = nullptr;
    std::size_t index = 0; ///< in the frame's list of `kind`
    ObjectFlags flags;
    QString title; ///< the kind's, for the undo step's name
};

std::optional<Target> target(const MenuTarget& w)
{
    EditingSession& session = w.session;
    const auto& object = w.tools.selection().object();
    if (!object || object->frame != currentFrameName(session))
        return std::nullopt;
    const FrameAnnotation* frame = session.annotations().frame(object->frame);
    if (!frame || object->index >= shapesOf(*frame, *object->kind).size())
        return std::nullopt;
    return Target{
        session.stream().currentIndex(), object->kind, object->index,
        frame->flagsOf(object->kind->truth_key, object->index),
        QString::fromUtf8(object->kind->title.data(), qsizetype(object->kind->title.size()))};
}

/// The selected object, or a word in the status bar on how to select one.
std::optional<Target> targetOrHint(const MenuTarget& w)
{
    auto t = target(w);
    if (!t)
        w.showStatus(QObject::tr("Select an object first: click it with its annotation tool"),
                     5000);
    return t;
}

void toggleConcealed(const MenuTarget& w)
{
    if (const auto t = targetOrHint(w))
        w.session.annotations().setConcealed(annotationFrameKeys(w.session), t->at, *t->kind,
                                             t->index, !t->flags.concealed);
}

void toggleKeyframe(const MenuTarget& w)
{
    const auto t = targetOrHint(w);
    if (t && !w.session.annotations().setKeyframe(annotationFrameKeys(w.session), t->at, *t->kind,
                                                  t->index, !t->flags.keyframe))
        w.showStatus(
            QObject::tr("%1: this kind has no keyframes (propagate it instead)").arg(t->title),
            5000);
}

void toggleInterpolation(const MenuTarget& w)
{
    const auto t = targetOrHint(w);
    if (t && !w.session.annotations().setInterpolate(annotationFrameKeys(w.session), t->at,
                                                     *t->kind, t->index, !t->flags.interpolate))
        w.showStatus(
            QObject::tr("Only a keyframe is interpolated from the one before: mark it first (K)"),
            5000);
}

/// Asks how many frames (starting from the last answer, which the selection keeps and the
/// window's settings between sessions) and propagates the selected object that many frames
/// forward (`direction` 1) or back (-1).
void propagateSelected(const MenuTarget& w, int direction)
{
    const auto t = targetOrHint(w);
    if (!t)
        return;
    const std::optional<int> count = Dialogs::current().number(
        w.parent,
        direction > 0 ? QObject::tr("Propagate to the next frames")
                      : QObject::tr("Propagate to the previous frames"),
        QObject::tr("Copy the selected object to how many frames %1 this one?")
            .arg(direction > 0 ? QObject::tr("after") : QObject::tr("before")),
        std::clamp(w.tools.selection().propagateFrames(), 1, 100000), 1, 100000);
    if (!count)
        return;
    w.tools.selection().setPropagateFrames(*count);
    w.session.annotations().propagate(annotationFrameKeys(w.session), t->at, *t->kind, t->index,
                                      direction * *count);
}

} // namespace

void addObjectMenu(QMenuBar& bar, const MenuTarget& w)
{
    QMenu* menu = bar.addMenu(QObject::tr("&Object"));
    QAction* concealed = addMenuItem(menu, QObject::tr("Concealed"), QKeySequence(Qt::Key_Q),
                                     w.parent, [w] { toggleConcealed(w); });
    QAction* keyframe = addMenuItem(menu, QObject::tr("Keyframe"), QKeySequence(Qt::Key_K),
                                    w.parent, [w] { toggleKeyframe(w); });
    QAction* interpolate =
        addMenuItem(menu, QObject::tr("Interpolated from the previous keyframe"),
                    QKeySequence(Qt::SHIFT | Qt::Key_K), w.parent, [w] { toggleInterpolation(w); });
    concealed->setObjectName(QStringLiteral("object.concealed"));
    keyframe->setObjectName(QStringLiteral("object.keyframe"));
    interpolate->setObjectName(QStringLiteral("object.interpolate"));
    menu->addSeparator();
    addMenuItem(menu, QObject::tr("Propagate to the next frames…"),
                QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_P), w.parent,
                [w] { propagateSelected(w, 1); })
        ->setObjectName(QStringLiteral("object.propagate_next"));
    addMenuItem(menu, QObject::tr("Propagate to the previous frames…"),
                QKeySequence(Qt::CTRL | Qt::ALT | Qt::Key_P), w.parent,
                [w] { propagateSelected(w, -1); })
        ->setObjectName(QStringLiteral("object.propagate_previous"));

    // The checks show the selected object's flags (none selected: all clear).
    const auto sync = [w, concealed, keyframe, interpolate] {
        const auto t = target(w);
        concealed->setChecked(t && t->flags.concealed);
        keyframe->setChecked(t && t->flags.keyframe);
        interpolate->setChecked(t && t->flags.keyframe && t->flags.interpolate);
    };
    for (QAction* a : {concealed, keyframe, interpolate}) {
        a->setCheckable(true);
        QObject::connect(a, &QAction::triggered, w.parent, sync); // also when nothing changed
    }
    QObject::connect(&w.tools.selection(), &AnnotationSelection::changed, w.parent, sync);
    QObject::connect(&w.session.annotations(), &AnnotationsDocument::changed, w.parent, sync);
    sync();
}

} // namespace fieldsight::ui
