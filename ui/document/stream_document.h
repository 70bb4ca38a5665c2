// The stream document: the open stream, the frame shown and its results. It hands each run to the
// FrameWorker as a request with the immutable versions the LUT and settings documents hold (it
// owns neither), and the newest result comes back by signal. Turning the stream's pictures
// upright (its orientation) is a command on its own undo stack.
#pragma once

#include "ui/document/document.h"
#include "ui/scans/scan_gate.h"
#include "ui/worker/frame_worker.h"
#include "visioncore/basics/file_fingerprint.h"
#include "visioncore/io/annotations.h"

#include <QString>
#include <QStringList>
#include <QThread>

#include <functional>
#include <map>
#include <memory>

namespace fieldsight::ui {

/// A stream opened and indexed (on any thread), ready for StreamDocument::adopt().
struct OpenedStream
{
    QString spec;
    StreamInfo info;
    std::vector<std::string> names; ///< every frame's name (none for a camera)
    QString lut_path;               ///< empty when no LUT was found
    std::shared_ptr<const ColourLut> lut;
    std::shared_ptr<FrameSource> source;
    QStringList warnings;     ///< what was not found or could not be read, the stream still opens
    bool lut_problem = false; ///< no table was found or it was damaged: an empty one is used
    QString annotations_path; ///< where the stream keeps its annotations (empty: a camera)
    Annotations annotations;  ///< as read from there (none when absent or damaged)
    QString annotations_problem; ///< why the file there could not be read
    /// The table's and the annotations' files as they were just before they were read, so a
    /// write during the open is still a change to the window's documents.
    FileFingerprint lut_read;
    FileFingerprint annotations_read;
    FileFingerprint params_read;   ///< the stream's own parameter file (info.params), likewise
    FileFingerprint manifest_read; ///< an image folder's stream.json (its orientation), likewise
    /// The stream's own stage parameters (its manifest's "params"; empty: none), or none when
    /// its file could not be used (said in the warnings).
    std::optional<ParamSet> params;
};

class LutDocument;
class PipelineSettings;

/// How a session's documents name the stream `spec` in their recovery files: a folder or file as
/// its absolute path, a live camera as its spec.
QString sessionStreamName(const QString& spec);

class StreamDocument : public Document
{
    Q_OBJECT
public:
    /// Frames are run with `lut`'s current table and `settings`' values: the document observes
    /// both and runs the current frame again when either changes. (The truth over a frame is
    /// the annotations document's, drawn by the view: an annotation edit runs nothing.)
    StreamDocument(const Pipeline& pipeline, LutDocument& lut, PipelineSettings& settings,
                   QObject* parent = nullptr);
    ~StreamDocument() override;

    const Pipeline& pipeline() const { return m_pipeline; }

    /// Opens and indexes `spec` with the LUT `lut` (or the stream's default LUT, or an empty one
    /// with a warning) and its annotations, if it has any. Safe on any thread; errors name the
    /// file and the problem.
    static Result<std::shared_ptr<OpenedStream>> openSource(const QString& spec, const QString& lut,
                                                            const Pipeline& pipeline,
                                                            const StreamOptions& options = {});
    /// Makes `opened` the document's stream and runs its first frame (the table it was opened
    /// with is the LUT document's to take: EditingSession::adopt).
    void adopt(std::shared_ptr<OpenedStream> opened);

    bool hasStream() const { return m_stream != nullptr; }
    QString streamSpec() const { return m_stream ? m_stream->spec : QString(); }
    const StreamInfo& info() const;
    /// The stream's manifest now names `path` as its parameter file (it was just written there;
    /// whether it changed on disk since is the pipeline settings' to tell).
    void setParamsFile(const std::string& path);
    /// The window itself just rewrote another key of the stream's stream.json (its table or its
    /// parameter file): that is no other writer's change to the orientation's file.
    void manifestWritten();
    bool live() const { return m_stream && m_stream->info.kind == StreamKind::Camera; }
    /// Frames of the stream (0 for a camera).
    std::size_t frameCount() const { return m_stream ? m_stream->names.size() : 0; }
    QString frameName(std::size_t index) const;
    QStringList warnings() const { return m_stream ? m_stream->warnings : QStringList(); }
    /// What opens another reader of the stream shown, serving the same frames turned as shown,
    /// for a task of its own: call it on that task's thread (StreamReader::reopen, which shares
    /// the reader's index). Empty for a camera or when no stream is open.
    std::function<Result<std::unique_ptr<StreamReader>>()> reopener() const;
    /// The stream opened with an empty table because its own was missing or damaged.
    bool lutProblem() const { return m_stream && m_stream->lut_problem; }

    /// How far the stream's stored pictures are turned clockwise before anything sees them (the
    /// frames, results, tools and scans are all in that upright frame).
    Orientation orientation() const { return info().orientation; }
    /// Turns the stream's pictures by `o` instead (an undoable command): the current frame is
    /// run again, upright. Not for a live camera; an Error names the stream and the problem (the
    /// orientation is then as it was).
    Status setOrientation(Orientation o);
    /// The stream's manifest (stream.json) can keep its orientation: an image folder.
    bool canSaveOrientation() const;
    /// Writes the orientation in use into the stream's stream.json (atomically, other keys kept),
    /// so it opens that way next time: the document's save(), its file the folder's stream.json.
    /// A read-only folder, a manifest that cannot be read, or one another window or program
    /// wrote since the stream was opened (or saved here) is refused with the reason, nothing
    /// written.
    Status saveOrientation() { return save(); }
    /// The orientation in use is not the one the stream's manifest says.
    bool orientationUnsaved() const
    {
        return hasStream() && info().orientation != info().stream_orientation;
    }
    // undoStack() holds the orientation changes of the open stream; problem() says an undo or
    // redo could not reopen the stream (it stays as it was).

    std::size_t currentIndex() const { return m_index; }
    /// Shows frame `index` (clamped to the stream); the newest request supersedes older ones.
    /// A step to another frame holds scanGate() for its quiet time.
    void setCurrentIndex(std::size_t index);
    /// What the whole-stream scans pass before each frame: held while the user steps, so the
    /// frames stepped to are read and run without the scans' decoding beside them.
    const std::shared_ptr<ScanGate>& scanGate() const { return m_scan_gate; }
    /// Where the frames made current came from (decoded, read ahead, or kept from lately).
    const FrameWorker::LoadCounts& frameLoads() const { return m_worker->loadCounts(); }
    /// Runs the current frame again (after a change of settings).
    void rerun();
    /// "Follow the light": every frame's light (null: none), used from the next run on.
    void setLight(std::shared_ptr<const LightTrack> light);
    const std::shared_ptr<const LightTrack>& light() const { return m_light; }
    /// The layers shown (ids of the pipeline's registry; the stage layers among them count): the
    /// core draws only those, and one newly shown runs the frame shown again to draw it. Every
    /// stage layer until this is called.
    void setLayersShown(const LayerSet& layers);
    /// Every stage layer is drawn while `all` (the pixel inspector lists each stage's shapes
    /// under the pointer, shown or not).
    void setAllLayersWanted(bool all);
    /// The stage layers each run draws.
    const LayerSet& layers() const { return m_layers; }

    /// The newest frame result (null before the first).
    const std::shared_ptr<const FrameOutput>& current() const { return m_current; }
    /// The frame the worker has run ahead with the current settings (a step there is answered at
    /// once), if any.
    std::optional<std::size_t> preparedAhead() const;
    /// A request has not been answered yet.
    bool waiting() const { return m_answered < m_serial; }
    std::uint64_t lastSerial() const { return m_serial; }

    /// Mean time per stage over the frames run since the stream was opened (or reset).
    struct StageMean
    {
        double sum_ms = 0;
        std::size_t frames = 0;
        double mean() const { return frames ? sum_ms / double(frames) : 0; }
    };
    const std::map<std::string, StageMean, std::less<>>& stageMeans() const { return m_means; }
    /// Mean of all stages together.
    const StageMean& totalMean() const { return m_total_mean; }
    void resetMeans();

signals:
    void streamChanged();
    /// The pictures are turned another way (or the orientation was saved); a frame follows.
    void orientationChanged();
    void currentIndexChanged(std::size_t index);
    void frameReady();
    void meansReset();

protected:
    Status writeFile(const QString& path) override;
    QString noFileMessage() const override;

private:
    friend class OrientationCommand;
    /// Makes `reader` (the stream opened turned another way; null: open it here with `o`) the
    /// one frames are read from, keeping the frame shown.
    Status applyOrientation(Orientation o, std::unique_ptr<StreamReader> reader = nullptr);
    void submit();
    /// What the current frame with the current table and settings asks of the worker.
    FrameRequest request() const;
    void onFrameDone(std::shared_ptr<const FrameOutput> output);
    /// m_layers from what is shown and wanted; runs the frame shown again for a layer it lacks.
    void updateLayers();

    const Pipeline& m_pipeline;
    LutDocument& m_lut;
    PipelineSettings& m_settings;
    QThread m_thread;
    FrameWorker* m_worker = nullptr;
    std::shared_ptr<ScanGate> m_scan_gate = std::make_shared<ScanGate>();

    std::shared_ptr<OpenedStream> m_stream;
    std::size_t m_index = 0;

    std::uint64_t m_serial = 0;
    std::uint64_t m_answered = 0;
    std::uint64_t m_first_serial = 0; ///< the first request of the open stream
    StageMean m_total_mean;
    std::shared_ptr<const FrameOutput> m_current;
    std::shared_ptr<const LightTrack> m_light;
    LayerSet m_shown_layers; ///< setLayersShown (stage layers only)
    bool m_all_layers = false;
    LayerSet m_layers; ///< what a request asks the core to draw
    std::map<std::string, StageMean, std::less<>> m_means;
};

} // namespace fieldsight::ui
