// One editing session: the open documents, each the single owner of its data (the stream and its
// frame results, the colour table, the pipeline settings, the bookmarks, the LUT samples; the
// annotations join them), the observers that follow them (the frame worker inside the stream
// document, the whole-stream edit-effect scan, the evaluation against the annotations), and the
// undo group whose active stack Edit > Undo
// follows. Opening a stream (in the background) and a table goes through here, so every document
// changes together.
#pragma once

#include "ui/document/annotations_document.h"
#include "ui/document/bookmarks_document.h"
#include "ui/scans/edit_effect_scan.h"
#include "ui/scans/evaluation_scan.h"
#include "ui/scans/light_scan.h"
#include "ui/document/lut_document.h"
#include "ui/document/samples_document.h"
#include "ui/document/pipeline_settings.h"
#include "ui/document/stream_document.h"

#include <QObject>
#include <QUndoGroup>

#include <functional>
#include <map>
#include <memory>
#include <vector>

namespace fieldsight::ui {

/// A document with an undo stack, as the history dock lists them.
struct UndoDocument
{
    QString name;
    QUndoStack* stack = nullptr;
};

class EditingSession : public QObject
{
    Q_OBJECT
public:
    explicit EditingSession(const Pipeline& pipeline = Pipeline::standard(),
                            QObject* parent = nullptr);
    /// Lets a background open finish first (it reads the pipeline), but waits for it at most
    /// kOpenWaitOnClose: an open stuck in the system (a file system that does not answer) is
    /// left to end with the process, never keeping it alive.
    ~EditingSession() override;

    /// What a background open runs: StreamDocument::openSource with the session's pipeline,
    /// unless replaced (a test gives one that blocks).
    using SourceOpener = std::function<Result<std::shared_ptr<OpenedStream>>(const QString& spec,
                                                                             const QString& lut)>;
    void setSourceOpener(SourceOpener opener) { m_opener = std::move(opener); }
    static constexpr int kOpenWaitOnCloseMs = 2000;

    const Pipeline& pipeline() const { return m_pipeline; }
    StreamDocument& stream() { return *m_stream; }
    LutDocument& lut() { return *m_lut; }
    PipelineSettings& settings() { return *m_settings; }
    BookmarksDocument& bookmarks() { return *m_bookmarks; }
    SamplesDocument& samples() { return *m_samples; }
    AnnotationsDocument& annotations() { return *m_annotations; }
    EditEffectScan& effectScan() { return *m_effect; }
    EvaluationScan& evaluation() { return *m_evaluation; }
    /// "Follow the light": the whole stream's light, followed in the background.
    LightScan& lightScan() { return *m_light; }

    /// Edit > Undo and Redo act on the active stack; the document edited last becomes active.
    QUndoGroup& undoGroup() { return m_undo_group; }
    const std::vector<UndoDocument>& undoDocuments() const { return m_undo_documents; }
    /// What Edit > Undo takes back: the active document's last step, or, when it has none left,
    /// that of the document edited most recently that has one (null: nothing to undo anywhere).
    QUndoStack* undoTarget() const;
    /// The history dock's name of the document of `stack`.
    QString undoDocumentName(const QUndoStack* stack) const;
    /// Undoes undoTarget()'s last step; its document becomes the active one.
    void undo();

    /// Opens `spec` in the background (with the table `lut`, or the stream's own); opened()
    /// tells how it went. False, with the reason in `why`, while another open runs.
    bool openStream(const QString& spec, const QString& lut = {});
    /// The same on this thread (tests, scripts); an Error names the file and the problem.
    Status open(const QString& spec, const QString& lut = {});
    /// Drops the running open: the stream before stays (the open ends unseen).
    void cancelOpening();
    bool opening() const { return m_job != nullptr; }
    QString openingSpec() const { return m_opening; }
    /// Makes an opened stream the session's: every document follows it.
    void adopt(std::shared_ptr<OpenedStream> opened);
    /// What the last open could not find or read (the stream still opened), and the annotated
    /// frames the stream lacks (missingAnnotatedFrames()).
    QStringList warnings() const { return m_warnings; }
    /// "annotations.json names 2 frames this stream lacks, the first frame_000099.png …" (empty
    /// when the stream has every annotated frame): `fieldsight eval` refuses such a file.
    QString missingAnnotatedFrames() const;

    /// The window's title for what is open: the stream, the table and, when they have unsaved
    /// edits, the annotations, with a [*] after each document with unsaved edits (after the
    /// table when none has).
    QString title() const;
    /// The table or the open stream's annotations have unsaved edits.
    bool unsavedEdits() const;

    /// Loads a table in any importable format as the LUT document's (clean, new history).
    Status openLut(const QString& path);

    /// Parameters that win over every stream's own (the window's --params and --set), applied
    /// at each open over the stream's. Checked by the caller.
    void setParamOverrides(const ParamSet& params) { m_param_overrides = params; }

signals:
    /// undoTarget() or its step's text may have changed.
    void undoTargetChanged();
    /// A background open ended: the stream is in (ok), or `error` says why not (or that the
    /// user cancelled it).
    void opened(bool ok, bool cancelled, const QString& error);
    /// A document's problem that is not the failure of a call (a save in a command's redo).
    void problem(const QString& message);
    void notice(const QString& message);

private:
    /// `document` joins the undo group and the history dock as `name`; its problems are the
    /// session's.
    void addDocument(const QString& name, Document& document);
    /// The annotations document's current truth, for the evaluation.
    std::shared_ptr<const Annotations> truthVersion() const;

    struct Opening
    {
        std::shared_ptr<OpenedStream> stream;
        QString error;
    };
    /// One background open, shared with the thread that runs it; `session` is who gets its
    /// result, cleared when the open is dropped (cancelled, or the session destroyed).
    struct OpenJob;
    void finishOpening(const std::shared_ptr<OpenJob>& job, const Opening& result);

    const Pipeline& m_pipeline;
    LutDocument* m_lut = nullptr;
    PipelineSettings* m_settings = nullptr;
    StreamDocument* m_stream = nullptr;
    BookmarksDocument* m_bookmarks = nullptr;
    SamplesDocument* m_samples = nullptr;
    AnnotationsDocument* m_annotations = nullptr;
    EditEffectScan* m_effect = nullptr;
    EvaluationScan* m_evaluation = nullptr;
    LightScan* m_light = nullptr;
    QUndoGroup m_undo_group;
    std::vector<UndoDocument> m_undo_documents;
    std::map<const QUndoStack*, quint64> m_touched; ///< when each stack last changed
    quint64 m_touch_serial = 0;
    QStringList m_warnings;
    std::shared_ptr<OpenJob> m_job;
    SourceOpener m_opener;
    QString m_opening;
    ParamSet m_param_overrides; ///< setParamOverrides
};

} // namespace fieldsight::ui
