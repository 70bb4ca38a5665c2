// The document under the window: the open stream, its LUT, the pipeline settings (stage switches,
// parameter values) and the current frame's results. Widgets show it and send it commands; it
// hands each run to the FrameWorker as a request with immutable versions of the LUT and the
// settings, and the newest result comes back by signal.
#pragma once

#include "ui/document/bookmarks.h"
#include "ui/document/frame_worker.h"

#include <QObject>
#include <QString>
#include <QStringList>
#include <QThread>

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
    QStringList warnings; ///< what was not found or could not be read, the stream still opens
};

class StreamDocument : public QObject
{
    Q_OBJECT
public:
    explicit StreamDocument(const Pipeline& pipeline = Pipeline::standard(),
                            QObject* parent = nullptr);
    ~StreamDocument() override;

    const Pipeline& pipeline() const { return m_pipeline; }

    /// Opens and indexes `spec` with the LUT `lut` (or the stream's default LUT, or an empty one
    /// with a warning) and its annotations, if it has any. Safe on any thread; errors name the
    /// file and the problem.
    static Result<std::shared_ptr<OpenedStream>> openSource(const QString& spec, const QString& lut,
                                                            const Pipeline& pipeline);
    /// Makes `opened` the document's stream and runs its first frame.
    void adopt(std::shared_ptr<OpenedStream> opened);
    /// openSource() and adopt() on this thread.
    Status open(const QString& spec, const QString& lut = {});
    /// Loads a LUT in any importable format and re-runs the current frame.
    Status openLut(const QString& path);
    /// An edited version of the LUT (from the LUT editor): re-runs the current frame. lutChanged
    /// is not emitted (that means another table was loaded).
    void setEditedLut(std::shared_ptr<const ColourLut> lut);
    /// The LUT was saved under another name.
    void setLutPath(const QString& path);

    bool hasStream() const { return m_stream != nullptr; }
    QString streamSpec() const { return m_stream ? m_stream->spec : QString(); }
    QString lutPath() const { return m_stream ? m_stream->lut_path : QString(); }
    std::shared_ptr<const ColourLut> lut() const { return m_stream ? m_stream->lut : nullptr; }
    const StreamInfo& info() const;
    bool live() const { return m_stream && m_stream->info.kind == StreamKind::Camera; }
    /// Frames of the stream (0 for a camera).
    std::size_t frameCount() const { return m_stream ? m_stream->names.size() : 0; }
    QString frameName(std::size_t index) const;
    QStringList warnings() const { return m_stream ? m_stream->warnings : QStringList(); }

    std::size_t currentIndex() const { return m_index; }
    /// Shows frame `index` (clamped to the stream); the newest request supersedes older ones.
    void setCurrentIndex(std::size_t index);
    /// Runs the current frame again (after a change of settings).
    void rerun();

    bool stageEnabled(std::string_view stage_id) const { return m_skip.count(stage_id) == 0; }
    Status setStageEnabled(std::string_view stage_id, bool enabled);
    const std::set<std::string, std::less<>>& skippedStages() const { return m_skip; }

    /// The value in use: the one set, or the default.
    double paramValue(std::string_view stage_id, std::string_view name) const;
    bool paramChanged(std::string_view stage_id, std::string_view name) const;
    Status setParam(std::string_view stage_id, std::string_view name, double value);
    void resetParam(std::string_view stage_id, std::string_view name);
    void resetStage(std::string_view stage_id);
    /// Values that differ from the defaults.
    const ParamSet& paramChanges() const { return *m_params; }
    /// Replaces every change at once, checked first (nothing changes on error).
    Status setParamChanges(const ParamSet& params);

    /// The newest frame result (null before the first).
    const std::shared_ptr<const FrameOutput>& current() const { return m_current; }
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

    const Bookmarks& bookmarks() const { return m_bookmarks; }
    QString bookmarksPath() const;
    /// Adds or changes the bookmark of `frame` and saves the sidecar (the mark stays in memory
    /// when saving fails; the error says why).
    Status setBookmark(std::size_t frame, const QString& note);
    Status removeBookmark(std::size_t frame);

signals:
    void streamChanged();
    void lutChanged();
    void settingsChanged();
    void currentIndexChanged(std::size_t index);
    void frameReady();
    void bookmarksChanged();
    /// Something the user must read that is not a failure of the call that caused it.
    void notice(const QString& message);

private:
    void submit();
    void onFrameDone(std::shared_ptr<const FrameOutput> output);
    const ParamInfo* paramInfo(std::string_view stage_id, std::string_view name) const;
    Status saveBookmarks();

    const Pipeline& m_pipeline;
    QThread m_thread;
    FrameWorker* m_worker = nullptr;

    std::shared_ptr<OpenedStream> m_stream;
    std::size_t m_index = 0;
    std::set<std::string, std::less<>> m_skip;
    std::shared_ptr<const ParamSet> m_params = std::make_shared<ParamSet>();

    std::uint64_t m_serial = 0;
    std::uint64_t m_answered = 0;
    std::uint64_t m_first_serial = 0; ///< the first request of the open stream
    StageMean m_total_mean;
    std::shared_ptr<const FrameOutput> m_current;
    std::map<std::string, StageMean, std::less<>> m_means;
    Bookmarks m_bookmarks;
    bool m_bookmarks_unreadable = false; ///< the sidecar was refused: set aside before a save
};

} // namespace fieldsight::ui
