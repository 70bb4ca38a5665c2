#include "ui/document/annotations_document.h"

#include "ui/adapters/local_path.h"
#include "ui/recovery/recovery_meta.h"

#include "visioncore/basics/atomic_file.h"
#include "visioncore/basics/json_text.h"
#include "visioncore/services/annotation_editing.h"
#include "visioncore/services/annotation_tracks.h"
#include "visioncore/services/evaluation.h"

#include <QCryptographicHash>
#include <QDir>
#include <QFile>
#include <QUndoCommand>

#include <filesystem>

namespace fieldsight::ui {

namespace {
constexpr const char* kRecoveryFormat = "fieldsight-annotations-recovery/1";

/// The largest recovery file read: the annotations' own cap for a long stream.
constexpr std::size_t kMaxRecoveryFrames = 100000;
} // namespace

/// One edit: each changed frame's annotation before and after, so undo restores it exactly.
class AnnotationsCommand : public QUndoCommand
{
public:
    AnnotationsCommand(AnnotationsDocument& doc, const QString& text,
                       AnnotationsDocument::FrameEdits before,
                       AnnotationsDocument::FrameEdits after, int merge)
        : QUndoCommand(text), m_doc(doc), m_before(std::move(before)), m_after(std::move(after)),
          m_merge(merge)
    {
    }
    void redo() override { m_doc.apply(m_after); }
    void undo() override { m_doc.apply(m_before); }
    int id() const override { return m_merge > 0 ? 1 : -1; }
    bool mergeWith(const QUndoCommand* other) override
    {
        const auto* next = static_cast<const AnnotationsCommand*>(other);
        if (next->m_merge != m_merge)
            return false;
        // The first state before stays; the newest state after wins.
        for (const auto& [name, before] : next->m_before)
            m_before.emplace(name, before);
        for (const auto& [name, after] : next->m_after)
            m_after[name] = after;
        return true;
    }

private:
    AnnotationsDocument& m_doc;
    AnnotationsDocument::FrameEdits m_before;
    AnnotationsDocument::FrameEdits m_after;
    int m_merge;
};

AnnotationsDocument::AnnotationsDocument(const Pipeline& pipeline, QObject* parent)
    : Document(Saving::ByUser, parent), m_kinds(pipeline.perceptKinds())
{
}

QString AnnotationsDocument::defaultPath(const QString& stream)
{
    return stream.isEmpty() ? QString() : fromLocalPath(defaultTruthPath(toLocalPath(stream)));
}

void AnnotationsDocument::reset()
{
    m_key_by_stem.clear();
    for (const auto& [name, frame] : m_annotations.frames)
        m_key_by_stem.emplace(frameStem(name), name);
    m_version.reset();
    clearHistory();
    resetMerge();
}

void AnnotationsDocument::adopt(const QString& stream, const QString& path, Annotations annotations,
                                const QString& load_problem,
                                const std::optional<FileFingerprint>& read)
{
    m_stream = stream;
    m_load_problem = load_problem;
    m_annotations = std::move(annotations);
    setFile(path, read);
    reset();
    m_offered_recovery = findRecovery().has_value();
    emit changed({});
    emit modifiedChanged(false);
}

Status AnnotationsDocument::setStream(const QString& stream, std::size_t frames)
{
    const QString path = defaultPath(stream);
    std::error_code ec;
    if (path.isEmpty() || !std::filesystem::exists(toLocalPath(path), ec)) {
        adopt(stream, path, {});
        return {};
    }
    auto loaded = Annotations::load(toLocalPath(path), m_kinds, frames);
    if (!loaded) {
        adopt(stream, path, {}, QString::fromStdString(loaded.error().message));
        return loaded.error();
    }
    adopt(stream, path, std::move(loaded).value());
    return {};
}

std::string AnnotationsDocument::keyOf(const std::string& name) const
{
    if (m_annotations.frames.count(name))
        return name;
    const auto it = m_key_by_stem.find(frameStem(name));
    return it != m_key_by_stem.end() ? it->second : name;
}

const FrameAnnotation* AnnotationsDocument::frame(const std::string& name) const
{
    const auto it = m_annotations.frames.find(keyOf(name));
    return it != m_annotations.frames.end() ? &it->second : nullptr;
}

std::shared_ptr<const AnnotationsVersion> AnnotationsDocument::version() const
{
    if (!m_version) {
        auto v = std::make_shared<AnnotationsVersion>();
        v->annotations = m_annotations;
        v->truth = v->annotations.truthByStem();
        m_version = std::move(v);
    }
    return m_version;
}

bool AnnotationsDocument::edit(const QString& text, FrameEdits after, int merge)
{
    FrameEdits keyed;
    FrameEdits before;
    for (auto& [name, annotation] : after) {
        const std::string key = keyOf(name);
        const FrameAnnotation* now = frame(key);
        const bool same = now ? annotation && *annotation == *now : !annotation;
        if (same)
            continue;
        before.emplace(key, now ? std::optional<FrameAnnotation>(*now) : std::nullopt);
        keyed.emplace(key, std::move(annotation));
    }
    if (keyed.empty())
        return false;
    pushEdit(new AnnotationsCommand(*this, text, std::move(before), std::move(keyed), merge),
             merge);
    return true;
}

bool AnnotationsDocument::editFrame(const std::string& name, FrameAnnotation after,
                                    const QString& text, int merge)
{
    FrameEdits edits;
    edits.emplace(name, std::move(after));
    return edit(text, std::move(edits), merge);
}

AnnotationsDocument::Copy AnnotationsDocument::copyPrevious(const std::vector<std::string>& frames,
                                                            std::size_t index)
{
    Copy copy;
    const FrameStates states = frameStates(frames, m_annotations);
    copy.from = previousAnnotated(states.annotated, index);
    if (!copy.from)
        return copy;
    const FrameAnnotation copied = copiedAnnotation(*frame(frames[*copy.from]));
    copy.objects = objectCount(copied);
    copy.changed =
        editFrame(frames[index], copied, tr("Copy frame %1's annotations").arg(*copy.from));
    return copy;
}

std::optional<std::size_t> AnnotationsDocument::takeDetections(
    const std::vector<std::string>& frames, std::size_t index, const PerceptSet& detections,
    const std::vector<const PerceptKind*>& kinds, const QString& which)
{
    const FrameAnnotation* now = frame(frames[index]);
    const FrameAnnotation after =
        detectionsAsTruth(now ? *now : FrameAnnotation{}, detections, kinds);
    if (!editFrame(frames[index], after,
                   tr("Detections to annotations: %1 (frame %2)").arg(which).arg(index)))
        return std::nullopt;
    return objectCount(after);
}

namespace {

/// A kind's title, for an undo step's name.
QString annotatedKindTitle(const PerceptKind& kind)
{
    return QString::fromUtf8(kind.title.data(), qsizetype(kind.title.size()));
}

} // namespace

std::size_t AnnotationsDocument::propagate(const std::vector<std::string>& frames, std::size_t at,
                                           const PerceptKind& kind, std::size_t object, int count)
{
    AnnotationChanges changes(m_annotations);
    const std::size_t made = fieldsight::propagate(changes, frames, at, kind, object, count);
    const QString title = annotatedKindTitle(kind);
    edit(tr("%1: propagated to %n frame(s)", nullptr, int(made)).arg(title), changes.frames());
    return made;
}

void AnnotationsDocument::setConcealed(const std::vector<std::string>& frames, std::size_t at,
                                       const PerceptKind& kind, std::size_t object, bool concealed)
{
    if (at >= frames.size())
        return;
    const std::string key = keyOf(frames[at]);
    const FrameAnnotation* frame = this->frame(key);
    if (!frame || object >= shapesOf(*frame, kind).size())
        return;
    AnnotationChanges changes(m_annotations);
    ObjectFlags flags = frame->flagsOf(kind.truth_key, object);
    flags.concealed = concealed;
    changes.edit(key).setFlags(kind.truth_key, object, flags);
    edit((concealed ? tr("%1: concealed") : tr("%1: not concealed")).arg(annotatedKindTitle(kind)),
         changes.frames());
}

bool AnnotationsDocument::setKeyframe(const std::vector<std::string>& frames, std::size_t at,
                                      const PerceptKind& kind, std::size_t object, bool keyframe)
{
    AnnotationChanges changes(m_annotations);
    if (!fieldsight::setKeyframe(changes, frames, at, kind, object, keyframe))
        return false;
    edit((keyframe ? tr("%1: keyframe") : tr("%1: no keyframe")).arg(annotatedKindTitle(kind)),
         changes.frames());
    return true;
}

bool AnnotationsDocument::setInterpolate(const std::vector<std::string>& frames, std::size_t at,
                                         const PerceptKind& kind, std::size_t object,
                                         bool interpolate)
{
    AnnotationChanges changes(m_annotations);
    if (!fieldsight::setInterpolate(changes, frames, at, kind, object, interpolate))
        return false;
    edit((interpolate ? tr("%1: interpolate") : tr("%1: do not interpolate"))
             .arg(annotatedKindTitle(kind)),
         changes.frames());
    return true;
}

void AnnotationsDocument::apply(const FrameEdits& edits)
{
    QStringList names;
    for (const auto& [name, annotation] : edits) {
        if (annotation) {
            m_annotations.frames[name] = *annotation;
            m_key_by_stem.emplace(frameStem(name), name);
        } else {
            m_annotations.frames.erase(name);
            m_key_by_stem.erase(frameStem(name));
        }
        names << QString::fromStdString(name);
    }
    m_version.reset();
    noteEdit();
    emit changed(names);
}

QString AnnotationsDocument::noFileMessage() const
{
    return QStringLiteral("the annotations have no file yet: use Save Annotations As");
}

QString AnnotationsDocument::saveRefusal() const
{
    if (m_load_problem.isEmpty())
        return {};
    return QStringLiteral(": could not be read when the stream opened, so it is not written over; "
                          "save the annotations under another name");
}

Status AnnotationsDocument::reload(std::size_t frames)
{
    // Noted before reading: a write during the read is a change still to be seen.
    DiskState read;
    read.remember(path());
    Annotations disk;
    if (!path().isEmpty() && localPathExists(path())) {
        auto loaded = Annotations::load(toLocalPath(path()), m_kinds, frames);
        if (!loaded)
            return loaded.error();
        disk = std::move(loaded).value();
    }
    FrameEdits edits;
    for (const auto& [name, annotation] : m_annotations.frames)
        if (!disk.frames.count(name))
            edits.emplace(name, std::nullopt);
    for (auto& [name, annotation] : disk.frames)
        edits.emplace(name, std::move(annotation));
    edit(tr("Reload annotations from disk"), std::move(edits));
    endMerge();
    m_load_problem.clear();
    setDisk(read);
    markClean();
    return {};
}

Status AnnotationsDocument::writeFile(const QString& to)
{
    if (Status s = m_annotations.save(toLocalPath(to), m_kinds); !s)
        return s;
    if (to != path())
        m_load_problem.clear();
    return {};
}

QString AnnotationsDocument::recoveryFile(const QString& stream) const
{
    const QByteArray hash = QCryptographicHash::hash(QByteArray::fromStdString(toLocalPath(stream)),
                                                     QCryptographicHash::Sha1)
                                .toHex()
                                .left(16);
    return QDir(recoveryDir())
        .filePath(QStringLiteral("annotations-recovery-%1.json").arg(QString::fromLatin1(hash)));
}

Status AnnotationsDocument::writeRecovery()
{
    if (m_stream.isEmpty())
        return Error{"a live camera's annotations have no stream to be recovered onto"};
    if (m_offered_recovery)
        return {}; // the earlier session's file is not written over before the user chooses
    if (!makeLocalFolder(recoveryDir()))
        return Error{toLocalPath(recoveryDir()) + ": cannot create the recovery folder"};
    auto root = parseJson<nlohmann::ordered_json>(m_annotations.toJson(m_kinds), "").value();
    nlohmann::ordered_json meta{{"format", kRecoveryFormat}};
    putPath(meta, "path", path());
    putPath(meta, "stream", m_stream);
    meta["saved_at"] = recoveryTimestamp();
    root["recovery"] = std::move(meta);
    return writeFileAtomically(toLocalPath(recoveryFile(m_stream)), jsonText(root, 1) + '\n');
}

std::optional<AnnotationsRecovery> AnnotationsDocument::findRecovery(const QString& stream) const
{
    const QString of = stream.isEmpty() ? m_stream : stream;
    if (of.isEmpty())
        return std::nullopt;
    const QString file = recoveryFile(of);
    if (!localPathExists(file))
        return std::nullopt;
    const Result<std::string> text =
        readWholeFile(toLocalPath(file), maxAnnotationsBytes(kMaxRecoveryFrames));
    if (!text)
        return std::nullopt;
    const auto root = jsonOrDiscarded(text.value());
    if (!root.is_object() || !root.contains("recovery") || !root["recovery"].is_object())
        return std::nullopt;
    const nlohmann::json& meta = root["recovery"];
    if (stringAt(meta, "format") != kRecoveryFormat || pathAt(meta, "stream") != of)
        return std::nullopt; // another stream's file of the same hash: never offered here
    AnnotationsRecovery r;
    r.file = file;
    r.path = pathAt(meta, "path");
    r.stream = of;
    r.saved_at = QString::fromStdString(stringAt(meta, "saved_at"));
    if (const auto frames = root.find("frames"); frames != root.end() && frames->is_object())
        r.frames = frames->size();
    return r;
}

Status AnnotationsDocument::recover(const AnnotationsRecovery& recovery)
{
    if (recovery.stream != m_stream)
        return Error{toLocalPath(recovery.file) + ": these annotation edits belong to " +
                     toLocalPath(recovery.stream) + ", not to the open stream " +
                     toLocalPath(m_stream)};
    auto text = readWholeFile(toLocalPath(recovery.file), maxAnnotationsBytes(kMaxRecoveryFrames));
    if (!text)
        return text.error();
    auto annotations = Annotations::fromJson(text.value(), toLocalPath(recovery.file), m_kinds);
    if (!annotations)
        return annotations.error();
    m_annotations = std::move(annotations).value();
    m_load_problem.clear();
    setFile(recovery.path);
    reset();
    m_offered_recovery = false;
    setRecovered();
    emit changed({});
    emit modifiedChanged(true);
    return {};
}

void AnnotationsDocument::discardOwnRecovery()
{
    if (!m_offered_recovery) // an earlier session's edits stay on offer until the user chooses
        discardRecovery();
}

void AnnotationsDocument::discardRecovery()
{
    m_offered_recovery = false;
    if (!m_stream.isEmpty())
        QFile::remove(recoveryFile(m_stream));
}

} // namespace fieldsight::ui
