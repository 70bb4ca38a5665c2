#include "ui/document/stream_document.h"

#include "ui/adapters/local_path.h"
#include "ui/document/annotations_document.h"
#include "ui/document/lut_document.h"
#include "ui/document/pipeline_settings.h"

#include "visioncore/io/lut_import.h"
#include "visioncore/services/evaluation.h"

#include <QDir>
#include <QFileInfo>
#include <QTimer>

#include <algorithm>

#include <filesystem>

namespace fieldsight::ui {

namespace {

/// After a step answered from the look-ahead, the worker starts on the next frame this much
/// later, so decoding it does not compete with painting this one.
constexpr int kLookAheadDelayMs = 12;

std::string local(const QString& s)
{
    return toLocalPath(s);
}

/// An image folder's manifest, where its orientation is kept.
QString manifestPath(const QString& folder)
{
    return QDir(folder).filePath(QStringLiteral("stream.json"));
}

QString orientationName(Orientation o)
{
    switch (o) {
    case Orientation::Upright:
        return QObject::tr("as stored");
    case Orientation::Clockwise90:
        return QObject::tr("90° clockwise");
    case Orientation::Half:
        return QObject::tr("180°");
    case Orientation::Clockwise270:
        return QObject::tr("90° anticlockwise");
    }
    return {};
}

} // namespace

/// Turning the open stream's pictures: redo and undo open it turned the other way.
class OrientationCommand : public QUndoCommand
{
public:
    OrientationCommand(StreamDocument& doc, Orientation from, Orientation to,
                       std::unique_ptr<StreamReader> opened)
        : QUndoCommand(QObject::tr("Orientation: %1").arg(orientationName(to))), m_doc(doc),
          m_from(from), m_to(to), m_opened(std::move(opened))
    {
    }
    void redo() override { turn(m_to); }
    void undo() override { turn(m_from); }

private:
    void turn(Orientation o)
    {
        // The first redo uses the reader opened (and checked) before the command was pushed.
        if (Status s = m_doc.applyOrientation(o, std::move(m_opened)); !s)
            emit m_doc.problem(QString::fromStdString(s.error().message));
    }

    StreamDocument& m_doc;
    Orientation m_from, m_to;
    std::unique_ptr<StreamReader> m_opened;
};

QString sessionStreamName(const QString& spec)
{
    return spec.startsWith(QLatin1String("camera:")) ? spec : QFileInfo(spec).absoluteFilePath();
}

StreamDocument::StreamDocument(const Pipeline& pipeline, LutDocument& lut,
                               PipelineSettings& settings, QObject* parent)
    : Document(Saving::None, parent), m_pipeline(pipeline), m_lut(lut), m_settings(settings)
{
    for (const LayerInfo& layer : pipeline.layers())
        m_shown_layers.insert(layer.id);
    m_layers = m_shown_layers;
    connect(&m_lut, &LutDocument::changed, this, &StreamDocument::submit);
    connect(&m_settings, &PipelineSettings::changed, this, &StreamDocument::submit);
    qRegisterMetaType<std::shared_ptr<const FrameOutput>>();
    m_worker = new FrameWorker(pipeline);
    m_worker->moveToThread(&m_thread);
    connect(m_worker, &FrameWorker::frameDone, this, &StreamDocument::onFrameDone);
    m_thread.setObjectName(QStringLiteral("fieldsight frame worker"));
    m_thread.start();
}

StreamDocument::~StreamDocument()
{
    m_thread.quit();
    m_thread.wait();
    delete m_worker;
}

Result<std::shared_ptr<OpenedStream>> StreamDocument::openSource(const QString& spec,
                                                                 const QString& lut,
                                                                 const Pipeline& pipeline,
                                                                 const StreamOptions& options)
{
    // An image folder's manifest as it was before it is read (the orientation's file).
    std::error_code folder_error;
    const bool folder = std::filesystem::is_directory(local(spec), folder_error);
    const FileFingerprint manifest_read =
        folder ? fingerprintFile(local(manifestPath(spec))) : FileFingerprint{};
    auto reader = openStream(local(spec), options);
    if (!reader)
        return reader.error();
    auto opened = std::make_shared<OpenedStream>();
    opened->manifest_read = manifest_read;
    opened->spec = spec;
    opened->source = std::make_shared<FrameSource>();
    std::unique_ptr<StreamReader> r = std::move(reader).value();
    opened->info = r->info();
    for (const std::string& warning : opened->info.warnings)
        opened->warnings << QString::fromStdString(warning);
    if (opened->info.kind != StreamKind::Camera) {
        opened->names.reserve(opened->info.frame_count);
        for (std::size_t i = 0; i < opened->info.frame_count; ++i)
            opened->names.push_back(r->frameName(i));
    }

    opened->lut_path = lut.isEmpty() ? fromLocalPath(opened->info.default_lut) : lut;
    if (opened->lut_path.isEmpty()) {
        opened->lut = std::make_shared<const ColourLut>();
        opened->warnings << spec + QStringLiteral(": no LUT given and none beside the stream; "
                                                  "every pixel is unclassified");
        opened->lut_problem = true;
    } else if (opened->lut_read = fingerprintFile(local(opened->lut_path));
               auto table = importLut(local(opened->lut_path))) {
        opened->lut = std::make_shared<const ColourLut>(std::move(table).value());
    } else if (lut.isEmpty()) {
        // The stream's own table is damaged: the stream still opens, with an empty table that
        // is not tied to the damaged file, so no save can write over it without asking.
        opened->warnings << QString::fromStdString(table.error().message) +
                                QStringLiteral("; the stream opened with an empty table, and that "
                                               "file is left as it is (Save LUT As writes "
                                               "another, or replaces it if you choose it)");
        opened->lut_path.clear();
        opened->lut = std::make_shared<const ColourLut>();
        opened->lut_problem = true;
    } else {
        return table.error(); // a table the user chose: say why it cannot be used
    }
    // A live camera gets its own DataWrapper, capturing from here on; a file stream its reader.
    if (opened->info.kind == StreamKind::Camera)
        opened->source->camera = std::make_unique<CameraDataWrapper>(std::move(r), opened->lut);
    else
        opened->source->reader = std::move(r);

    // The stream's own parameters: a bad file is said, and the stream opens without them.
    if (!opened->info.params.empty())
        opened->params_read = fingerprintFile(opened->info.params);
    if (auto params = streamParams(opened->info, pipeline); params)
        opened->params = std::move(params).value();
    else if (opened->info.kind != StreamKind::Camera)
        opened->warnings << QString::fromStdString(params.error().message) +
                                tr("; the stream opened with the parameters in use");

    opened->annotations_path = AnnotationsDocument::defaultPath(spec);
    if (!opened->annotations_path.isEmpty())
        opened->annotations_read = fingerprintFile(local(opened->annotations_path));
    std::error_code ec;
    if (!opened->annotations_path.isEmpty() &&
        std::filesystem::exists(local(opened->annotations_path), ec)) {
        auto annotations = Annotations::load(local(opened->annotations_path),
                                             pipeline.perceptKinds(), opened->info.frame_count);
        if (annotations) {
            opened->annotations = std::move(annotations).value();
        } else {
            opened->annotations_problem = QString::fromStdString(annotations.error().message);
            opened->warnings << opened->annotations_problem +
                                    tr(" (it is not written over: save the annotations under "
                                       "another name)");
        }
    }
    return opened;
}

std::function<Result<std::unique_ptr<StreamReader>>()> StreamDocument::reopener() const
{
    if (!m_stream || !m_stream->source || !m_stream->source->reader)
        return {};
    // The source is kept alive by the task; reopen() reads only what the reader fixed when it
    // opened, so it runs beside the worker's reads.
    return [source = m_stream->source] { return source->reader->reopen(); };
}

void StreamDocument::adopt(std::shared_ptr<OpenedStream> opened)
{
    if (m_stream)
        m_worker->release(std::move(m_stream->source)); // closed on the worker thread
    m_stream = std::move(opened);
    m_stream->lut.reset(); // the LUT document's now
    undoStack().clear();   // the orientations of the stream before
    m_index = 0;
    m_current.reset();
    m_light.reset(); // the stream before's
    m_answered = m_serial;
    m_first_serial = m_serial + 1; // what the worker still does for the stream before is dropped
    resetMeans();
    // The orientation's file: an image folder's stream.json, as it was before it was read.
    std::error_code ec;
    if (m_stream->info.kind == StreamKind::ImageFolder &&
        std::filesystem::is_directory(local(m_stream->spec), ec))
        setFile(manifestPath(m_stream->spec), m_stream->manifest_read);
    else
        setFile(QString());
    emit streamChanged();
    emit currentIndexChanged(m_index);
    submit();
}

const StreamInfo& StreamDocument::info() const
{
    static const StreamInfo none;
    return m_stream ? m_stream->info : none;
}

void StreamDocument::setParamsFile(const std::string& path)
{
    if (!m_stream)
        return;
    m_stream->info.params = path;
}

void StreamDocument::manifestWritten()
{
    if (!path().isEmpty())
        setFile(path());
}

QString StreamDocument::frameName(std::size_t index) const
{
    if (!m_stream || index >= m_stream->names.size())
        return QString();
    return fromLocalPath(m_stream->names[index]);
}

Status StreamDocument::setOrientation(Orientation o)
{
    if (!m_stream)
        return Error{"no stream is open to turn"};
    if (live())
        return Error{local(m_stream->spec) + ": a live camera's frames cannot be turned"};
    if (o == orientation())
        return {};
    // Opened first, so a stream that can no longer be read leaves no command behind.
    auto reader = openStream(local(m_stream->spec), StreamOptions{o});
    if (!reader)
        return reader.error();
    undoStack().push(new OrientationCommand(*this, orientation(), o, std::move(reader).value()));
    return {};
}

Status StreamDocument::applyOrientation(Orientation o, std::unique_ptr<StreamReader> reader)
{
    if (!m_stream || live())
        return Error{"no stream is open to turn"};
    if (!reader) {
        auto opened = openStream(local(m_stream->spec), StreamOptions{o});
        if (!opened)
            return opened.error();
        reader = std::move(opened).value();
    }
    // The frames, bookmarks and the navigator keep their indices only over the same frames.
    if (reader->info().frame_count != m_stream->info.frame_count)
        return Error{local(m_stream->spec) + ": the stream has changed since it was opened (" +
                     std::to_string(reader->info().frame_count) + " frames, was " +
                     std::to_string(m_stream->info.frame_count) + "); open it again to turn it"};
    // A new source: what the worker prepared or keeps for the old one is never shown again.
    auto stream = std::make_shared<OpenedStream>(*m_stream);
    stream->source = std::make_shared<FrameSource>();
    stream->info = reader->info();
    stream->names.clear();
    for (std::size_t i = 0; i < stream->info.frame_count; ++i)
        stream->names.push_back(reader->frameName(i));
    stream->source->reader = std::move(reader);
    m_worker->release(std::move(m_stream->source));
    m_stream = std::move(stream);
    m_first_serial = m_serial + 1; // answers for the old source are dropped
    m_light.reset();               // followed in the old turn: the scan follows it again
    emit orientationChanged();
    submit();
    return {};
}

bool StreamDocument::canSaveOrientation() const
{
    return hasStream() && info().kind == StreamKind::ImageFolder &&
           std::filesystem::is_directory(local(m_stream->spec));
}

QString StreamDocument::noFileMessage() const
{
    return QString::fromStdString(m_stream ? local(m_stream->spec) : std::string("no stream")) +
           tr(": only a folder of images has a stream.json to keep the orientation in; give "
              "--orientation to the commands instead");
}

Status StreamDocument::writeFile(const QString& path)
{
    if (!canSaveOrientation() || path != manifestPath(m_stream->spec))
        return Error{noFileMessage().toStdString()};
    if (Status s = writeStreamOrientation(local(m_stream->spec), orientation()); !s)
        return s;
    m_stream->info.stream_orientation = orientation();
    emit orientationChanged();
    return {};
}

void StreamDocument::setCurrentIndex(std::size_t index)
{
    if (!m_stream)
        return;
    if (!live() && frameCount() > 0)
        index = std::min(index, frameCount() - 1);
    const bool moved = index != m_index;
    m_index = index;
    if (moved && !live())
        m_scan_gate->hold(); // the scans wait: this frame and the next ones decode first
    if (moved)
        emit currentIndexChanged(m_index);
    submit();
}

void StreamDocument::rerun()
{
    submit();
}

void StreamDocument::setLight(std::shared_ptr<const LightTrack> light)
{
    if (light == m_light)
        return;
    m_light = std::move(light);
    submit();
}

void StreamDocument::setLayersShown(const LayerSet& layers)
{
    m_shown_layers.clear();
    for (const LayerInfo& layer : m_pipeline.layers())
        if (layers.count(layer.id))
            m_shown_layers.insert(layer.id);
    updateLayers();
}

void StreamDocument::setAllLayersWanted(bool all)
{
    m_all_layers = all;
    updateLayers();
}

void StreamDocument::updateLayers()
{
    LayerSet layers;
    for (const LayerInfo& layer : m_pipeline.layers())
        if (m_all_layers || m_shown_layers.count(layer.id))
            layers.insert(layer.id);
    if (layers == m_layers)
        return;
    m_layers = std::move(layers);
    // A layer hidden needs nothing (the view leaves it out); one the frame shown was run without
    // is drawn by running the frame again.
    const bool drawn =
        m_current && std::includes(m_current->layers.begin(), m_current->layers.end(),
                                   m_layers.begin(), m_layers.end());
    if (!drawn)
        submit();
}

FrameRequest StreamDocument::request() const
{
    FrameRequest request;
    request.index = m_index;
    request.source = m_stream->source;
    request.lut = m_lut.version();
    request.params = m_settings.paramVersion();
    request.skip = m_settings.skippedStages();
    request.layers = m_layers;
    request.light = m_light;
    return request;
}

std::optional<std::size_t> StreamDocument::preparedAhead() const
{
    return m_stream ? m_worker->aheadIndex(request()) : std::nullopt;
}

void StreamDocument::submit()
{
    if (!m_stream)
        return;
    const bool answered = !waiting(); // every request before this one
    FrameRequest request = this->request();
    request.serial = ++m_serial;
    // Prepared while the frame before was shown (and nothing older is still running, whose
    // answer would come after it): answered here, no thread hop on the way. The worker moves on
    // to the frame after it once this one is painted.
    if (std::shared_ptr<FrameOutput> ready = answered ? m_worker->takeAhead(request) : nullptr) {
        ready->serial = request.serial;
        request.look_ahead_only = true;
        QTimer::singleShot(kLookAheadDelayMs, this, [this, request = std::move(request)]() mutable {
            if (request.serial == m_serial) // not superseded meanwhile
                m_worker->submit(std::move(request));
        });
        onFrameDone(std::move(ready));
        return;
    }
    m_worker->submit(std::move(request));
}

void StreamDocument::onFrameDone(std::shared_ptr<const FrameOutput> output)
{
    m_answered = std::max(m_answered, output->serial);
    if (!m_stream || output->serial < m_first_serial ||
        (m_current && output->serial < m_current->serial))
        return; // the stream before, or older than what is shown
    m_current = std::move(output);
    if (m_current->error.isEmpty()) {
        for (const StageTiming& t : m_current->result.report.stages) {
            if (!t.ran)
                continue;
            StageMean& mean = m_means[t.stage];
            mean.sum_ms += t.ms;
            ++mean.frames;
        }
        m_total_mean.sum_ms += m_current->result.report.total_ms;
        ++m_total_mean.frames;
    }
    emit frameReady();
}

void StreamDocument::resetMeans()
{
    m_means.clear();
    m_total_mean = {};
    emit meansReset();
}

} // namespace fieldsight::ui
