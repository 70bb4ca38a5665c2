#include "ui/document/stream_document.h"

#include "ui/adapters/local_path.h"

#include "visioncore/basics/atomic_file.h"
#include "visioncore/io/lut_import.h"
#include "visioncore/services/evaluation.h"

#include <filesystem>

namespace fieldsight::ui {

namespace {

std::string local(const QString& s)
{
    return toLocalPath(s);
}

} // namespace

StreamDocument::StreamDocument(const Pipeline& pipeline, QObject* parent)
    : QObject(parent), m_pipeline(pipeline)
{
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

Result<std::shared_ptr<OpenedStream>>
StreamDocument::openSource(const QString& spec, const QString& lut, const Pipeline& pipeline)
{
    auto reader = openStream(local(spec));
    if (!reader)
        return reader.error();
    auto opened = std::make_shared<OpenedStream>();
    opened->spec = spec;
    opened->source = std::make_shared<FrameSource>();
    std::unique_ptr<StreamReader> r = std::move(reader).value();
    opened->info = r->info();
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
    } else {
        auto table = importLut(local(opened->lut_path));
        if (!table)
            return table.error();
        opened->lut = std::make_shared<const ColourLut>(std::move(table).value());
    }
    // A live camera gets its own DataWrapper, capturing from here on; a file stream its reader.
    if (opened->info.kind == StreamKind::Camera)
        opened->source->camera = std::make_unique<CameraDataWrapper>(std::move(r), opened->lut);
    else
        opened->source->reader = std::move(r);

    const std::string truth_path = defaultTruthPath(local(spec));
    std::error_code ec;
    if (!truth_path.empty() && std::filesystem::exists(truth_path, ec)) {
        auto annotations = Annotations::load(truth_path, pipeline.perceptKinds());
        if (annotations) {
            auto shared = std::make_shared<const Annotations>(std::move(annotations).value());
            opened->source->truth = shared->truthByStem();
            opened->source->annotations = std::move(shared);
        } else {
            opened->warnings << QString::fromStdString(annotations.error().message);
        }
    }
    return opened;
}

void StreamDocument::adopt(std::shared_ptr<OpenedStream> opened)
{
    if (m_stream)
        m_worker->release(std::move(m_stream->source)); // closed on the worker thread
    m_stream = std::move(opened);
    m_index = 0;
    m_current.reset();
    m_answered = m_serial;
    m_first_serial = m_serial + 1; // what the worker still does for the stream before is dropped
    resetMeans();
    m_bookmarks = Bookmarks{};
    m_bookmarks_unreadable = false;
    const std::string sidecar = local(bookmarksPath());
    if (!sidecar.empty()) {
        auto marks = Bookmarks::load(sidecar);
        if (marks) {
            m_bookmarks = std::move(marks).value();
        } else {
            m_bookmarks_unreadable = true;
            m_stream->warnings << QString::fromStdString(marks.error().message) +
                                      tr(" (it is set aside, not overwritten, when a bookmark is "
                                         "saved)");
        }
    }
    emit streamChanged();
    emit lutChanged();
    emit bookmarksChanged();
    emit currentIndexChanged(m_index);
    submit();
}

Status StreamDocument::open(const QString& spec, const QString& lut)
{
    auto opened = openSource(spec, lut, m_pipeline);
    if (!opened)
        return opened.error();
    adopt(std::move(opened).value());
    return {};
}

Status StreamDocument::openLut(const QString& path)
{
    if (!m_stream)
        return Error{local(path) + ": open a stream first"};
    auto table = importLut(local(path));
    if (!table)
        return table.error();
    m_stream->lut = std::make_shared<const ColourLut>(std::move(table).value());
    m_stream->lut_path = path;
    emit lutChanged();
    submit();
    return {};
}

void StreamDocument::setEditedLut(std::shared_ptr<const ColourLut> lut)
{
    if (!m_stream || !lut || lut == m_stream->lut)
        return;
    m_stream->lut = std::move(lut);
    submit();
}

void StreamDocument::setLutPath(const QString& path)
{
    if (m_stream)
        m_stream->lut_path = path;
}

const StreamInfo& StreamDocument::info() const
{
    static const StreamInfo none;
    return m_stream ? m_stream->info : none;
}

QString StreamDocument::frameName(std::size_t index) const
{
    if (!m_stream || index >= m_stream->names.size())
        return QString();
    return fromLocalPath(m_stream->names[index]);
}

void StreamDocument::setCurrentIndex(std::size_t index)
{
    if (!m_stream)
        return;
    if (!live() && frameCount() > 0)
        index = std::min(index, frameCount() - 1);
    const bool moved = index != m_index;
    m_index = index;
    if (moved)
        emit currentIndexChanged(m_index);
    submit();
}

void StreamDocument::rerun()
{
    submit();
}

void StreamDocument::submit()
{
    if (!m_stream)
        return;
    FrameRequest request;
    request.serial = ++m_serial;
    request.index = m_index;
    request.source = m_stream->source;
    request.lut = m_stream->lut;
    request.params = m_params;
    request.skip = m_skip;
    m_worker->submit(std::move(request));
}

void StreamDocument::onFrameDone(std::shared_ptr<const FrameOutput> output)
{
    m_answered = std::max(m_answered, output->serial);
    if (!m_stream || output->serial < m_first_serial)
        return;
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
}

Status StreamDocument::setStageEnabled(std::string_view stage_id, bool enabled)
{
    if (Status s = checkSkip(m_pipeline, {std::string(stage_id)}); !s)
        return s;
    if (enabled == stageEnabled(stage_id))
        return {};
    if (enabled)
        m_skip.erase(m_skip.find(stage_id));
    else
        m_skip.insert(std::string(stage_id));
    emit settingsChanged();
    submit();
    return {};
}

const ParamInfo* StreamDocument::paramInfo(std::string_view stage_id, std::string_view name) const
{
    const StageDescriptor* stage = m_pipeline.find(stage_id);
    if (!stage)
        return nullptr;
    for (const ParamInfo& p : stage->params)
        if (p.name == name)
            return &p;
    return nullptr;
}

double StreamDocument::paramValue(std::string_view stage_id, std::string_view name) const
{
    const auto stage = m_params->values.find(stage_id);
    if (stage != m_params->values.end()) {
        const auto it = stage->second.find(name);
        if (it != stage->second.end())
            return it->second;
    }
    const ParamInfo* info = paramInfo(stage_id, name);
    return info ? info->default_value : 0;
}

bool StreamDocument::paramChanged(std::string_view stage_id, std::string_view name) const
{
    const auto stage = m_params->values.find(stage_id);
    return stage != m_params->values.end() && stage->second.count(name) != 0;
}

Status StreamDocument::setParam(std::string_view stage_id, std::string_view name, double value)
{
    const ParamInfo* info = paramInfo(stage_id, name);
    if (!info)
        return Error{"unknown parameter '" + std::string(stage_id) + "." + std::string(name) + "'"};
    if (Status s = checkParamValue(*info, stage_id, value); !s)
        return s;
    auto next = std::make_shared<ParamSet>(*m_params);
    if (value == info->default_value) {
        auto& stage = next->values[std::string(stage_id)];
        stage.erase(std::string(name));
        if (stage.empty())
            next->values.erase(std::string(stage_id));
    } else {
        next->set(stage_id, name, value);
    }
    m_params = std::move(next);
    emit settingsChanged();
    submit();
    return {};
}

void StreamDocument::resetParam(std::string_view stage_id, std::string_view name)
{
    if (const ParamInfo* info = paramInfo(stage_id, name))
        (void)setParam(stage_id, name, info->default_value);
}

void StreamDocument::resetStage(std::string_view stage_id)
{
    if (m_params->values.count(stage_id) == 0)
        return;
    auto next = std::make_shared<ParamSet>(*m_params);
    next->values.erase(std::string(stage_id));
    m_params = std::move(next);
    emit settingsChanged();
    submit();
}

Status StreamDocument::setParamChanges(const ParamSet& params)
{
    if (Status s = params.check(m_pipeline); !s)
        return s;
    m_params = std::make_shared<ParamSet>(params);
    emit settingsChanged();
    submit();
    return {};
}

QString StreamDocument::bookmarksPath() const
{
    return m_stream ? fromLocalPath(Bookmarks::sidecarPath(local(m_stream->spec))) : QString();
}

Status StreamDocument::saveBookmarks()
{
    emit bookmarksChanged();
    const std::string path = local(bookmarksPath());
    if (path.empty())
        return Error{"a live camera has no file to keep bookmarks beside"};
    auto saved = saveReplacingUnreadable(path, m_bookmarks_unreadable,
                                         [&] { return m_bookmarks.save(path); });
    if (!saved)
        return Error{saved.error().message + " (the bookmarks are kept until the window closes)"};
    if (!saved.value().empty())
        emit notice(QString::fromStdString(saved.value()));
    return {};
}

Status StreamDocument::setBookmark(std::size_t frame, const QString& note)
{
    m_bookmarks.set({frame, local(frameName(frame)), note.toStdString()});
    return saveBookmarks();
}

Status StreamDocument::removeBookmark(std::size_t frame)
{
    if (!m_bookmarks.remove(frame))
        return {};
    return saveBookmarks();
}

} // namespace fieldsight::ui
