// The annotations document: the open stream's ground truth (SPEC §5.2), its single owner. Every
// change is a command on its own undo stack that holds the changed frames before and after (a
// drag merges into one step); saves are atomic, to annotations.json beside the stream or a chosen
// file; unsaved edits are written to a recovery file of their own stream at most 30 s after an
// edit, and offered again only when that stream is opened.
#pragma once

#include "ui/document/document.h"
#include "visioncore/framework/controller.h"
#include "visioncore/io/annotations.h"

#include <QString>
#include <QStringList>

#include <map>
#include <memory>
#include <optional>
#include <string>

namespace fieldsight::ui {

/// An immutable copy of the annotations for the frame worker, with the truth of each frame by
/// frame stem (a .strm and the PNG folder beside it name the same frame differently).
struct AnnotationsVersion
{
    Annotations annotations;
    std::map<std::string, const PerceptSet*> truth; ///< by frameStem(), into `annotations`
};

/// A recovery file left by a session that did not save its annotation edits.
struct AnnotationsRecovery
{
    QString file;           ///< the recovery file
    QString path;           ///< the annotations file the edits belong to
    QString stream;         ///< the stream they were made on
    QString saved_at;       ///< ISO 8601
    std::size_t frames = 0; ///< annotated frames in it
};

class AnnotationsDocument : public Document
{
    Q_OBJECT
public:
    explicit AnnotationsDocument(const Pipeline& pipeline, QObject* parent = nullptr);

    /// The kinds read and written, in the order files list them (the pipeline's percept kinds).
    const std::vector<const PerceptKind*>& kinds() const { return m_kinds; }

    /// The annotations of `stream` as read from `path` (clean, new history). `load_problem` says
    /// why the file could not be read: the document is then empty, and the damaged file is
    /// never written over (save() asks for saveAs()). `read` is the file as it was before it was
    /// read (default: as it is now), what changedOnDisk() compares with.
    void adopt(const QString& stream, const QString& path, Annotations annotations,
               const QString& load_problem = {},
               const std::optional<FileFingerprint>& read = std::nullopt);
    /// Reads `stream`'s annotations file here (tests, scripts): absent is empty; an Error names
    /// a damaged file (kept as loadProblem()).
    Status setStream(const QString& stream, std::size_t frames = 0);
    /// Where `stream` keeps its annotations (annotations.json in its folder; empty for a camera).
    static QString defaultPath(const QString& stream);

    QString stream() const { return m_stream; }
    QString loadProblem() const { return m_load_problem; }
    const Annotations& annotations() const { return m_annotations; }
    /// The annotation of frame `name` (found by name, or by frame stem), null when it has none.
    const FrameAnnotation* frame(const std::string& name) const;
    /// The key frame `name` is kept under: the existing one of the same stem, or `name`.
    std::string keyOf(const std::string& name) const;
    /// The current annotations as an immutable version (one copy per change).
    std::shared_ptr<const AnnotationsVersion> version() const;

    /// Frame name -> its annotation after the edit (nullopt: the frame has none).
    using FrameEdits = std::map<std::string, std::optional<FrameAnnotation>>;
    /// Applies `after` as one undo step named `text`; edits with the same nonzero `merge` follow
    /// each other into one step (a drag while the mouse is down). False when nothing changes.
    bool edit(const QString& text, FrameEdits after, int merge = 0);
    /// The same for one frame.
    bool editFrame(const std::string& name, FrameAnnotation after, const QString& text,
                   int merge = 0);

    // The frame-level operations of the Annotate and Object menus, each one undo step (the rules
    // are services/annotation_editing's and annotation_tracks'). `frames` are the stream's frame
    // names in order (the annotations' keys for propagate()), `index` the frame's place there.
    /// What copyPrevious() did.
    struct Copy
    {
        std::optional<std::size_t> from; ///< the frame copied (none: no frame before has any)
        bool changed = false;            ///< false: the frame held the same already
        std::size_t objects = 0;         ///< objects copied
    };
    /// Frame `index` gets a copy of the objects of the annotated frame before it (not done yet).
    Copy copyPrevious(const std::vector<std::string>& frames, std::size_t index);
    /// The `detections` of `kinds` become frame `index`'s annotations; the other kinds keep theirs
    /// (a keyframed track of another kind survives). `which` names the kinds in the step. The
    /// objects on the frame after, or nullopt when it held them already.
    std::optional<std::size_t> takeDetections(const std::vector<std::string>& frames,
                                              std::size_t index, const PerceptSet& detections,
                                              const std::vector<const PerceptKind*>& kinds,
                                              const QString& which);
    /// Copies object `object` of `kind` on frame `at` to the next `count` frames (the previous
    /// -`count` when negative) as objects of its track; the frames that got it.
    std::size_t propagate(const std::vector<std::string>& frames, std::size_t at,
                          const PerceptKind& kind, std::size_t object, int count);
    /// Object `object` of `kind` on frame `at` concealed (partly hidden) or not.
    void setConcealed(const std::vector<std::string>& frames, std::size_t at,
                      const PerceptKind& kind, std::size_t object, bool concealed);
    /// Object `object` of `kind` on frame `at` a keyframe of its track or not; false (nothing
    /// changed) when the kind has no keyframes.
    bool setKeyframe(const std::vector<std::string>& frames, std::size_t at,
                     const PerceptKind& kind, std::size_t object, bool keyframe);
    /// Whether the frames since the previous keyframe are interpolated up to this keyframe; false
    /// (nothing changed) when the object is no keyframe.
    bool setInterpolate(const std::vector<std::string>& frames, std::size_t at,
                        const PerceptKind& kind, std::size_t object, bool interpolate);

    // Saved with Document::save() and saveAs(); a file that could not be read when the stream
    // opened is not written over by save().
    /// Reads path() again as one undo step ("Reload annotations from disk"; Undo brings the
    /// edits before it back, unsaved): the document is then clean and what is on disk. An absent
    /// file reads as empty; a damaged one is an Error and changes nothing.
    Status reload(std::size_t frames = 0);

    /// Writes the recovery file of the open stream now; while the file an earlier session left is
    /// still on offer (neither recovered nor discarded) it is kept, not written over.
    Status writeRecovery() override;
    /// The recovery file left for `stream` (the open one when empty), if any.
    std::optional<AnnotationsRecovery> findRecovery(const QString& stream = {}) const;
    /// Loads a recovery of the open stream (one of another stream is refused, naming both): the
    /// annotations become modified, to be saved to the path they came from.
    Status recover(const AnnotationsRecovery& recovery);
    /// Removes the open stream's recovery file (the user declines it).
    void discardRecovery() override;
    /// Removes the recovery file of this session's edits (they were saved or dropped); an earlier
    /// session's file still on offer stays.
    void discardOwnRecovery() override;

signals:
    /// The annotations of `frames` changed (an edit, undo or redo); empty: all of them (a new
    /// stream, a recovery).
    void changed(const QStringList& frames);

protected:
    Status writeFile(const QString& path) override;
    QString noFileMessage() const override;
    QString saveRefusal() const override;

private:
    friend class AnnotationsCommand;
    void apply(const FrameEdits& edits);
    QString recoveryFile(const QString& stream) const;
    void reset();

    std::vector<const PerceptKind*> m_kinds;
    Annotations m_annotations;
    std::map<std::string, std::string> m_key_by_stem;
    mutable std::shared_ptr<const AnnotationsVersion> m_version;
    QString m_stream;
    QString m_load_problem;
    bool m_offered_recovery = false; ///< an earlier session's recovery file waits for a choice
};

} // namespace fieldsight::ui
