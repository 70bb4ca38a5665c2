// The LUT samples document: rectangles of frames marked with a colour class, kept beside
// the stream (lut_samples.json, saved at every change) so the table can be built again after the
// light changes; each added or removed sample is an undoable command of its own stack. Building
// reads every sampled frame (and, as an option, the stream's annotations as samples) in the
// background, with progress and cancel, and the new table becomes one undoable LUT edit.
#pragma once

#include "ui/document/document.h"
#include "ui/document/lut_document.h"
#include "visioncore/services/lut_building.h"

#include <QFutureWatcher>
#include <QRect>

#include <atomic>
#include <optional>

namespace fieldsight::ui {

class SamplesDocument : public Document
{
    Q_OBJECT
public:
    explicit SamplesDocument(LutDocument& lut, QObject* parent = nullptr);
    ~SamplesDocument() override;

    /// The stream the samples belong to: its samples file is read if there is one (a bad file
    /// is an Error naming it, kept as loadProblem(); the samples are then empty and the file is
    /// set aside, not overwritten, by the first save).
    Status setStream(const QString& spec);
    /// Why the stream's samples file could not be read (empty when it could, or there is none).
    QString loadProblem() const { return m_load_problem; }
    /// How builds open the stream: turned as the window shows it, so the samples' rectangles
    /// (drawn on the shown frames) cover the same pixels.
    void setStreamOptions(StreamOptions options) { m_options = options; }
    const LutSamples& samples() const { return m_samples; }
    /// Adds a rectangle of frame `frame` whose pixels show `colour` (undoable; saved at once).
    void addRect(const QString& frame, Colour colour, const QRect& rect);
    /// Replaces every sample (undoable; saved at once).
    void setSamples(std::vector<LutSample> samples, const QString& text);

    // The samples file written (or made, or removed) by someone else since it was read or saved
    // here (changedOnDisk()): a change is then kept in memory, not written over it, until
    // reload() or overwrite().
    /// Reads the samples file again (a clean reload: the samples made here since are dropped
    /// and the history starts again).
    Status reload() { return setStream(m_stream); }
    /// Writes the samples in memory over the file, whatever it holds now.
    void overwrite();

    /// Builds from the samples (and the stream's annotations as samples) on a worker thread;
    /// buildReady() then says a built table waits to be applied (or dropped).
    void build(bool with_annotations);
    /// How a built table goes into the LUT.
    enum class BuildMode {
        OnlyUnclassified, ///< fills the cells the LUT leaves unclassified; others stay
        Replace,          ///< the LUT becomes the built table
    };
    bool hasBuild() const { return m_pending.has_value(); }
    /// What applying the waiting build in `mode` would change in the LUT.
    std::vector<CellChange> buildChanges(BuildMode mode) const;
    /// Applies the waiting build as one undoable LUT edit; built() reports it.
    void applyBuild(BuildMode mode);
    /// Drops the waiting build: the LUT is unchanged.
    void dropBuild();
    bool building() const { return m_watcher.isRunning(); }
    void cancel() { m_cancel = true; }
    /// Frames read so far and frames to read, while building.
    std::pair<std::size_t, std::size_t> progress() const { return {m_done, m_total}; }
    /// The cells two classes' samples both claim, from the last build.
    const std::vector<AmbiguousCell>& ambiguous() const { return m_ambiguous; }

    struct Built
    {
        ColourLut table;
        std::vector<AmbiguousCell> ambiguous;
        std::size_t samples = 0;
        std::size_t frames = 0;
        std::size_t pixels = 0;
        bool cancelled = false;
    };
    /// The build itself (any thread): reads the stream, votes, smooths.
    static Result<Built> buildTable(const std::string& stream, const LutSamples& samples,
                                    bool with_annotations, std::atomic<bool>* cancel,
                                    std::atomic<std::size_t>* done, std::atomic<std::size_t>* total,
                                    const StreamOptions& stream_options = {});

signals:
    void samplesChanged();
    /// A build finished and waits for applyBuild() or dropBuild().
    void buildReady();
    /// A build finished (`summary` says what it did), or failed (`summary` says why).
    void built(bool ok, const QString& summary);

private:
    friend class SamplesCommand;
    void store(std::vector<LutSample> samples);
    void write();

    LutDocument& m_lut;
    QString m_stream;
    StreamOptions m_options;
    QString m_load_problem;
    LutSamples m_samples;
    QFutureWatcher<Result<Built>> m_watcher;
    std::atomic<bool> m_cancel{false};
    std::atomic<std::size_t> m_done{0};
    std::atomic<std::size_t> m_total{0};
    std::vector<AmbiguousCell> m_ambiguous;
    std::optional<Built> m_pending;
};

} // namespace fieldsight::ui
