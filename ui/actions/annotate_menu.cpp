// Annotate: the frame-level annotation edits, a key each so a stream is annotated without leaving
// the keyboard: copy the previous annotated frame's objects here (V), this frame's detections as
// its annotations (A; or one kind's alone, from its submenu), done / not done (D), "reviewed,
// nothing here" per kind (Ctrl+Alt+1..., in the kinds' order), and the next / previous frame not
// done (N / Shift+N). Each edit is one undo step on the annotations document; the rules are
// services/annotation_editing's.
#include "ui/actions/menus.h"
#include "ui/document/annotations_document.h"
#include "ui/document/editing_session.h"
#include "ui/tools/tool_manager.h"
#include "visioncore/services/annotation_editing.h"

#include <QMenuBar>

#include <optional>

namespace fieldsight::ui {

namespace {

QString tr(const char* text, int n = -1)
{
    return QObject::tr(text, nullptr, n);
}

QString titleOf(const PerceptKind& kind)
{
    return QString::fromUtf8(kind.title.data(), qsizetype(kind.title.size()));
}

/// The frame shown, when the open stream has frames to annotate; else says why not.
std::optional<std::size_t> shownFrame(const MenuTarget& w)
{
    const StreamDocument& stream = w.session.stream();
    if (!stream.hasStream() || stream.live() || stream.frameCount() == 0) {
        w.showMessage(tr("Annotations are made on the frames of a stream (a live camera has "
                         "none to come back to)"),
                      false);
        return std::nullopt;
    }
    return stream.currentIndex();
}

std::string nameOf(const MenuTarget& w, std::size_t index)
{
    return w.session.stream().frameName(index).toStdString();
}

std::vector<std::string> frameNames(const StreamDocument& stream)
{
    std::vector<std::string> names;
    names.reserve(stream.frameCount());
    for (std::size_t i = 0; i < stream.frameCount(); ++i)
        names.push_back(stream.frameName(i).toStdString());
    return names;
}

/// A note in the status bar: what an action did.
void tell(const MenuTarget& w, const QString& text)
{
    w.showStatus(text, 6000);
}

void copyPrevious(const MenuTarget& w)
{
    const auto index = shownFrame(w);
    if (!index)
        return;
    const AnnotationsDocument::Copy copy =
        w.session.annotations().copyPrevious(frameNames(w.session.stream()), *index);
    if (!copy.from) {
        w.showMessage(tr("No frame before this one has annotations to copy"), false);
        return;
    }
    if (!copy.changed) {
        tell(w, tr("This frame's annotations already equal frame %1's").arg(*copy.from));
        return;
    }
    tell(w, tr("Copied frame %1's annotations (%n object(s)) onto frame %2, not done yet",
               int(copy.objects))
                .arg(*copy.from)
                .arg(*index));
}

/// Makes the detections of `kinds` this frame's annotations; the other kinds keep theirs (a
/// keyframed track of another kind survives).
void detectionsToTruth(const MenuTarget& w, const std::vector<const PerceptKind*>& kinds,
                       const QString& which)
{
    const auto index = shownFrame(w);
    if (!index)
        return;
    const std::shared_ptr<const FrameOutput>& out = w.session.stream().current();
    if (!out || out->index != *index) {
        w.showMessage(tr("This frame's detections are not in yet; try again when it is shown"),
                      false);
        return;
    }
    if (!out->error.isEmpty()) {
        w.showMessage(tr("This frame has no detections to take: %1").arg(out->error));
        return;
    }
    const std::optional<std::size_t> objects = w.session.annotations().takeDetections(
        frameNames(w.session.stream()), *index, out->result.percepts, kinds, which);
    if (!objects) {
        tell(w, tr("This frame's annotations (%1) already equal its detections").arg(which));
        return;
    }
    tell(w, tr("This frame's detections (%1) are its annotations now (%n object(s) on the frame): "
               "correct them, then mark the frame done (D)",
               int(*objects))
                .arg(which));
}

void toggleDone(const MenuTarget& w)
{
    const auto index = shownFrame(w);
    if (!index)
        return;
    AnnotationsDocument& doc = w.session.annotations();
    const std::string name = nameOf(w, *index);
    const FrameAnnotation* now = doc.frame(name);
    FrameAnnotation after = now ? *now : FrameAnnotation{};
    after.done = !after.done;
    doc.editFrame(name, after,
                  after.done ? tr("Frame %1 done").arg(*index)
                             : tr("Frame %1 not done").arg(*index));
}

void toggleReviewed(const MenuTarget& w, const PerceptKind& kind)
{
    const auto index = shownFrame(w);
    if (!index)
        return;
    AnnotationsDocument& doc = w.session.annotations();
    const std::string name = nameOf(w, *index);
    const FrameAnnotation* now = doc.frame(name);
    const FrameAnnotation before = now ? *now : FrameAnnotation{};
    const PerceptEntry* list = before.truth.find(kind);
    const bool nothing_here = before.reviewed.count(kind.truth_key) && (!list || list->size() == 0);
    if (nothing_here) { // pressed again: no longer reviewed
        FrameAnnotation after = before;
        after.reviewed.erase(std::string(kind.truth_key));
        doc.editFrame(name, after, tr("%1 not reviewed (frame %2)").arg(titleOf(kind)).arg(*index));
        return;
    }
    const std::size_t removed = list ? list->size() : 0;
    doc.editFrame(name, reviewedNothingHere(before, kind),
                  tr("%1 reviewed, nothing here (frame %2)").arg(titleOf(kind)).arg(*index));
    if (removed > 0)
        tell(w, tr("%1: none on this frame (%n object(s) removed; Ctrl+Z brings them back)",
                   int(removed))
                    .arg(titleOf(kind)));
}

void jumpNotDone(const MenuTarget& w, int direction)
{
    const auto index = shownFrame(w);
    if (!index)
        return;
    StreamDocument& stream = w.session.stream();
    const FrameStates states =
        frameStates(frameNames(stream), w.session.annotations().annotations());
    const std::optional<NotDoneHit> hit = nextNotDone(states.done, *index, direction);
    if (!hit) {
        w.showMessage(tr("Every frame is done (%1 frames)").arg(qulonglong(states.done.size())),
                      false);
        return;
    }
    stream.setCurrentIndex(hit->index);
    if (hit->index == *index)
        tell(w, tr("This is the only frame not done"));
    else if (hit->wrapped)
        tell(w, direction > 0
                    ? tr("Frame %1, the first not done (from the start again)").arg(hit->index)
                    : tr("Frame %1, the last not done (from the end again)").arg(hit->index));
    else
        tell(w, tr("Frame %1 is not done").arg(hit->index));
}

} // namespace

void addAnnotateMenu(QMenuBar& bar, const MenuTarget& w)
{
    QMenu* menu = bar.addMenu(QObject::tr("&Annotate"));
    menu->setObjectName(QStringLiteral("annotate_menu"));
    const auto item = [&](const QString& text, const QKeySequence& key, const char* name, auto fn) {
        QAction* a = addMenuItem(menu, text, key, w.parent, fn);
        a->setObjectName(QLatin1String(name));
        return a;
    };
    QList<QAction*> edits;
    edits << item(tr("Copy the previous annotated frame here"), QKeySequence(Qt::Key_V),
                  "annotate.copy_previous", [w] { copyPrevious(w); });
    // One item per kind drawn by hand, from the registry, and all of them (A): taking one kind
    // leaves the others' annotations (a keyframed track) as they are.
    QMenu* take = menu->addMenu(tr("Detections to annotations"));
    take->setObjectName(QStringLiteral("annotate.detections_menu"));
    QAction* all = addMenuItem(take, tr("All kinds"), QKeySequence(Qt::Key_A), w.parent, [w] {
        detectionsToTruth(w, w.session.annotations().kinds(), tr("all kinds"));
    });
    all->setObjectName(QStringLiteral("annotate.detections"));
    edits << all;
    take->addSeparator();
    for (const PerceptKind* kind : w.session.annotations().kinds()) {
        if (kind->form == ShapeForm::None)
            continue;
        QAction* a = take->addAction(tr("%1 only").arg(titleOf(*kind)));
        a->setObjectName(
            QStringLiteral("annotate.detections.") +
            QString::fromUtf8(kind->truth_key.data(), qsizetype(kind->truth_key.size())));
        QObject::connect(a, &QAction::triggered, w.parent,
                         [w, kind] { detectionsToTruth(w, {kind}, titleOf(*kind)); });
        edits << a;
    }
    QAction* done =
        item(tr("Frame done"), QKeySequence(Qt::Key_D), "annotate.done", [w] { toggleDone(w); });
    done->setCheckable(true);
    edits << done;

    menu->addSection(tr("Reviewed, nothing here"));
    std::vector<std::pair<QAction*, const PerceptKind*>> reviewed;
    int key = Qt::Key_1;
    for (const PerceptKind* kind : w.session.annotations().kinds()) {
        if (kind->form == ShapeForm::None)
            continue;
        QAction* a = menu->addAction(tr("%1: reviewed, nothing here").arg(titleOf(*kind)));
        a->setObjectName(
            QStringLiteral("annotate.reviewed.") +
            QString::fromUtf8(kind->truth_key.data(), qsizetype(kind->truth_key.size())));
        if (key <= Qt::Key_9)
            a->setShortcut(QKeyCombination(Qt::ControlModifier | Qt::AltModifier, Qt::Key(key++)));
        a->setCheckable(true);
        a->setToolTip(tr("Empties this frame's list and marks it complete; again: not reviewed"));
        QObject::connect(a, &QAction::triggered, w.parent, [w, kind] { toggleReviewed(w, *kind); });
        reviewed.emplace_back(a, kind);
        edits << a;
    }
    menu->addSeparator();
    edits << item(tr("Next frame not done"), QKeySequence(Qt::Key_N), "annotate.next_not_done",
                  [w] { jumpNotDone(w, 1); });
    edits << item(tr("Previous frame not done"), QKeySequence(Qt::SHIFT | Qt::Key_N),
                  "annotate.previous_not_done", [w] { jumpNotDone(w, -1); });

    // The checks follow the frame shown; the items need a stream of frames.
    const auto refresh = [w, done, reviewed, edits] {
        StreamDocument& stream = w.session.stream();
        const bool frames = stream.hasStream() && !stream.live() && stream.frameCount() > 0;
        for (QAction* a : edits)
            a->setEnabled(frames);
        const FrameAnnotation* frame =
            frames ? w.session.annotations().frame(nameOf(w, stream.currentIndex())) : nullptr;
        done->setChecked(frame && frame->done);
        for (const auto& [action, kind] : reviewed) {
            const PerceptEntry* list = frame ? frame->truth.find(*kind) : nullptr;
            action->setChecked(frame && frame->reviewed.count(kind->truth_key) &&
                               (!list || list->size() == 0));
        }
    };
    StreamDocument& stream = w.session.stream();
    QObject::connect(&stream, &StreamDocument::streamChanged, menu, refresh);
    QObject::connect(&stream, &StreamDocument::currentIndexChanged, menu, refresh);
    QObject::connect(&w.session.annotations(), &AnnotationsDocument::changed, menu, refresh);
    refresh();
}

} // namespace fieldsight::ui
