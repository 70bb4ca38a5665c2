#include "ui/document/samples_document.h"

#include "ui/adapters/image_adapter.h"
#include "ui/adapters/local_path.h"

#include "visioncore/framework/controller.h"
#include "visioncore/io/annotations.h"
#include "visioncore/basics/atomic_file.h"
#include "visioncore/services/evaluation.h"
#include "visioncore/services/lut_compare.h"

#include <QFileInfo>
#include <QUndoCommand>
#include <QtConcurrent/QtConcurrentRun>

namespace fieldsight::ui {

/// A change of the sample list: the list before and after (samples are few and small).
class SamplesCommand : public QUndoCommand
{
public:
    SamplesCommand(SamplesDocument& sampler, const QString& text, std::vector<LutSample> before,
                   std::vector<LutSample> after)
        : QUndoCommand(text), m_sampler(sampler), m_before(std::move(before)),
          m_after(std::move(after))
    {
    }
    void redo() override { m_sampler.store(m_after); }
    void undo() override { m_sampler.store(m_before); }

private:
    SamplesDocument& m_sampler;
    std::vector<LutSample> m_before;
    std::vector<LutSample> m_after;
};

SamplesDocument::SamplesDocument(LutDocument& lut, QObject* parent)
    : Document(Saving::EveryChange, parent), m_lut(lut)
{
    connect(&m_watcher, &QFutureWatcher<Result<Built>>::finished, this, [this] {
        auto result = m_watcher.result();
        if (!result) {
            emit built(false, QString::fromStdString(result.error().message));
            return;
        }
        Built& b = result.value();
        if (b.cancelled) {
            emit built(false, tr("Build cancelled; the LUT is unchanged"));
            return;
        }
        m_ambiguous = std::move(b.ambiguous);
        m_pending = std::move(b);
        emit buildReady();
    });
}

std::vector<CellChange> SamplesDocument::buildChanges(BuildMode mode) const
{
    if (!m_pending)
        return {};
    if (mode == BuildMode::Replace)
        return diffLuts(m_lut.table(), m_pending->table).cells;
    std::vector<Colour> classes;
    for (int c = 1; c < kColourCount; ++c)
        classes.push_back(Colour(c));
    return mergeChanges(m_lut.table(), m_pending->table, classes, /*keep_others=*/true);
}

void SamplesDocument::applyBuild(BuildMode mode)
{
    if (!m_pending)
        return;
    std::vector<CellChange> changes = buildChanges(mode);
    const std::size_t cells = changes.size();
    const Built b = *std::exchange(m_pending, std::nullopt);
    m_lut.edit(mode == BuildMode::Replace
                   ? tr("Build from %1 samples (replace)").arg(qulonglong(b.samples))
                   : tr("Build from %1 samples (unclassified cells)").arg(qulonglong(b.samples)),
               std::move(changes));
    emit built(true, tr("Built from %1 samples on %2 frames (%3 pixels): %4 cells changed, "
                        "%5 claimed by two classes")
                         .arg(qulonglong(b.samples))
                         .arg(qulonglong(b.frames))
                         .arg(qulonglong(b.pixels))
                         .arg(qulonglong(cells))
                         .arg(qulonglong(m_ambiguous.size())));
}

void SamplesDocument::dropBuild()
{
    m_pending.reset();
}

SamplesDocument::~SamplesDocument()
{
    m_cancel = true;
    m_watcher.waitForFinished();
}

Status SamplesDocument::setStream(const QString& spec)
{
    m_stream = spec;
    clearHistory();
    m_samples = {};
    m_ambiguous.clear();
    m_pending.reset();
    setUnreadable(false);
    m_load_problem.clear();
    setFile(spec.isEmpty() || spec.startsWith(QLatin1String("camera:"))
                ? QString()
                : fromLocalPath(defaultLutSamplesPath(toLocalPath(spec))));
    Status status;
    if (localPathExists(path())) {
        auto loaded = loadLutSamples(toLocalPath(path()));
        if (loaded) {
            m_samples = std::move(loaded).value();
        } else {
            setUnreadable(true);
            status = Error{loaded.error().message +
                           " (it is set aside, not overwritten, when a sample is saved)"};
            m_load_problem = QString::fromStdString(status.error().message);
        }
    }
    emit samplesChanged();
    return status;
}

void SamplesDocument::store(std::vector<LutSample> samples)
{
    m_samples.samples = std::move(samples);
    if (changedOnDisk())
        emit problem(tr("%1 changed on disk since this window read it (another window or a "
                        "program wrote it): the samples are kept here, not written over it; "
                        "reload it or keep yours")
                         .arg(path()));
    else
        write();
    emit samplesChanged();
}

void SamplesDocument::overwrite()
{
    write();
}

void SamplesDocument::write()
{
    if (path().isEmpty())
        return;
    auto saved =
        writeAtChange([this](const std::string& file) { return saveLutSamples(file, m_samples); });
    if (!saved)
        emit problem(QString::fromStdString(saved.error().message) +
                     tr(" (the samples stay in memory)"));
    else if (!saved.value().empty())
        emit problem(QString::fromStdString(saved.value()));
}

void SamplesDocument::addRect(const QString& frame, Colour colour, const QRect& rect)
{
    const QRect r = rect.normalized();
    LutSample sample;
    sample.frame = toLocalPath(frame);
    sample.colour = colour;
    sample.polygon = {
        {r.left(), r.top()}, {r.right(), r.top()}, {r.right(), r.bottom()}, {r.left(), r.bottom()}};
    std::vector<LutSample> after = m_samples.samples;
    after.push_back(std::move(sample));
    undoStack().push(new SamplesCommand(*this,
                                        tr("Sample %1 on %2").arg(colourLabel(colour), frame),
                                        m_samples.samples, std::move(after)));
}

void SamplesDocument::setSamples(std::vector<LutSample> samples, const QString& text)
{
    undoStack().push(new SamplesCommand(*this, text, m_samples.samples, std::move(samples)));
}

Result<SamplesDocument::Built>
SamplesDocument::buildTable(const std::string& stream, const LutSamples& samples,
                            bool with_annotations, std::atomic<bool>* cancel,
                            std::atomic<std::size_t>* done, std::atomic<std::size_t>* total,
                            const StreamOptions& stream_options)
{
    auto reader = openStream(stream, stream_options);
    if (!reader)
        return reader.error();
    std::vector<LutSample> all;
    if (with_annotations) {
        const std::string truth = defaultTruthPath(stream);
        const StreamInfo& info = reader.value()->info();
        auto annotations =
            Annotations::load(truth, Pipeline::standard().perceptKinds(), info.frame_count);
        if (!annotations)
            return annotations.error();
        all = samplesFromAnnotations(annotations.value(), cv::Size(info.width, info.height));
    }
    all.insert(all.end(), samples.samples.begin(), samples.samples.end());
    if (all.empty())
        return Error{stream + ": no samples to build from (mark regions with the Sample tool)"};
    auto run = collectLutVotes(*reader.value(), all, [&](std::size_t d, std::size_t t) {
        if (done)
            *done = d;
        if (total)
            *total = t;
        return !(cancel && *cancel);
    });
    if (!run)
        return run.error();
    Built built;
    built.cancelled = run.value().cancelled;
    LutBuildOptions options;
    options.smoothing = samples.smoothing;
    built.table = run.value().votes.build(options);
    built.ambiguous = run.value().votes.ambiguousCells(options);
    built.samples = all.size();
    built.frames = run.value().frames;
    built.pixels = run.value().votes.pixels();
    return built;
}

void SamplesDocument::build(bool with_annotations)
{
    if (building() || m_stream.isEmpty())
        return;
    m_cancel = false;
    m_done = 0;
    m_total = 0;
    m_watcher.setFuture(QtConcurrent::run(&SamplesDocument::buildTable, toLocalPath(m_stream),
                                          m_samples, with_annotations, &m_cancel, &m_done, &m_total,
                                          m_options));
}

} // namespace fieldsight::ui
