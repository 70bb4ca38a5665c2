#include "ui/document/editing_session.h"

#include "ui/adapters/local_path.h"
#include "visioncore/io/lut_import.h"

#include <QDir>
#include <QFileInfo>
#include <QFutureWatcherBase>
#include <QLocale>

#include <chrono>
#include <condition_variable>
#include <exception>
#include <mutex>
#include <new>
#include <set>
#include <thread>

namespace fieldsight::ui {

struct EditingSession::OpenJob
{
    std::mutex mutex;
    std::condition_variable finished;
    bool done = false;
    EditingSession* session = nullptr;
};

EditingSession::EditingSession(const Pipeline& pipeline, QObject* parent)
    : QObject(parent), m_pipeline(pipeline)
{
    m_lut = new LutDocument(this);
    m_settings = new PipelineSettings(pipeline, this);
    m_annotations = new AnnotationsDocument(pipeline, this);
    m_stream = new StreamDocument(pipeline, *m_lut, *m_settings, this);
    m_bookmarks = new BookmarksDocument(this);
    m_samples = new SamplesDocument(*m_lut, this);
    m_effect = new EditEffectScan(pipeline, this);
    m_evaluation = new EvaluationScan(pipeline, this);
    m_light = new LightScan(this);
    // The scans give way while the user steps through the stream.
    m_effect->setGate(m_stream->scanGate());
    m_evaluation->setGate(m_stream->scanGate());
    m_light->setGate(m_stream->scanGate());

    addDocument(tr("Colour table"), *m_lut);
    addDocument(tr("LUT samples"), *m_samples);
    addDocument(tr("Pipeline settings"), *m_settings);
    addDocument(tr("Bookmarks"), *m_bookmarks);
    addDocument(tr("Annotations"), *m_annotations);
    addDocument(tr("Stream orientation"), *m_stream);
    m_undo_group.setActiveStack(&m_lut->undoStack());

    // The whole-stream scan observes the table and the settings.
    connect(m_lut, &LutDocument::changed, m_effect,
            [this] { m_effect->edited(m_lut->editBase(), m_lut->version()); });
    connect(m_settings, &PipelineSettings::changed, m_effect, [this] {
        m_effect->setSettings(m_settings->paramVersion(), m_settings->skippedStages());
    });
    // So does the evaluation: the annotated frames are scored again after every change.
    connect(m_lut, &LutDocument::changed, m_evaluation,
            [this] { m_evaluation->setLut(m_lut->version()); });
    connect(m_settings, &PipelineSettings::changed, m_evaluation, [this] {
        m_evaluation->setSettings(m_settings->paramVersion(), m_settings->skippedStages());
    });
    // And the annotations: a change of the truth alone is matched again without running the
    // frames scored before.
    connect(m_annotations, &AnnotationsDocument::changed, m_evaluation,
            [this] { m_evaluation->setTruth(truthVersion(), m_annotations->path()); });

    // The light is followed with the table in use; the frames are read in the light followed.
    connect(m_lut, &LutDocument::changed, m_light, [this] { m_light->setLut(m_lut->version()); });
    connect(m_light, &LightScan::trackChanged, m_stream,
            [this] { m_stream->setLight(m_light->track()); });
    // The whole-stream scans then read the frames in their light too, as the view does.
    connect(m_light, &LightScan::enabledChanged, m_effect, &EditEffectScan::setFollowLight);
    connect(m_light, &LightScan::enabledChanged, m_evaluation, &EvaluationScan::setFollowLight);

    // Whatever reads the stream's frames reads them turned as the window shows them.
    connect(m_stream, &StreamDocument::orientationChanged, this, [this] {
        const StreamOptions options{m_stream->orientation()};
        m_samples->setStreamOptions(options);
        if (!m_light->stream().isEmpty())
            m_light->setStream(m_stream->streamSpec(), m_lut->version(), options);
        if (!m_evaluation->stream().isEmpty() &&
            m_evaluation->streamOptions().orientation != options.orientation)
            m_evaluation->setStream(m_stream->streamSpec(), m_lut->version(), options);
        if (m_effect->stream().isEmpty() ||
            m_effect->streamOptions().orientation == options.orientation)
            return; // saved, not turned
        m_effect->setStream(m_stream->streamSpec(), m_lut->version(), options);
    });

    connect(m_bookmarks, &BookmarksDocument::notice, this, &EditingSession::notice);
}

EditingSession::~EditingSession()
{
    if (m_job) {
        std::unique_lock lock(m_job->mutex);
        m_job->session = nullptr;
        m_job->finished.wait_for(lock, std::chrono::milliseconds(kOpenWaitOnCloseMs),
                                 [this] { return m_job->done; });
    }
    for (QFutureWatcherBase* watcher : findChildren<QFutureWatcherBase*>())
        watcher->waitForFinished();
}

std::shared_ptr<const Annotations> EditingSession::truthVersion() const
{
    std::shared_ptr<const AnnotationsVersion> version = m_annotations->version();
    const Annotations* annotations = &version->annotations;
    return {std::move(version), annotations}; // shares the version's ownership
}

void EditingSession::addDocument(const QString& name, Document& document)
{
    connect(&document, &Document::problem, this, &EditingSession::problem);
    QUndoStack& stack = document.undoStack();
    m_undo_group.addStack(&stack);
    m_undo_documents.push_back({name, &stack});
    // The document edited last is the one Edit > Undo acts on.
    connect(&stack, &QUndoStack::indexChanged, this, [this, &stack] {
        if (stack.count() > 0) {
            m_touched[&stack] = ++m_touch_serial;
            m_undo_group.setActiveStack(&stack);
        }
        emit undoTargetChanged();
    });
    connect(&stack, &QUndoStack::canUndoChanged, this, &EditingSession::undoTargetChanged);
    connect(&stack, &QUndoStack::undoTextChanged, this, &EditingSession::undoTargetChanged);
}

QUndoStack* EditingSession::undoTarget() const
{
    QUndoStack* active = m_undo_group.activeStack();
    if (active && active->canUndo())
        return active;
    // The active document has no step left: the one edited most recently that has.
    QUndoStack* newest = nullptr;
    quint64 when = 0;
    for (const UndoDocument& d : m_undo_documents) {
        const auto it = m_touched.find(d.stack);
        if (d.stack->canUndo() && it != m_touched.end() && it->second >= when) {
            newest = d.stack;
            when = it->second;
        }
    }
    return newest;
}

QString EditingSession::undoDocumentName(const QUndoStack* stack) const
{
    for (const UndoDocument& d : m_undo_documents)
        if (d.stack == stack)
            return d.name;
    return {};
}

void EditingSession::undo()
{
    if (QUndoStack* target = undoTarget()) {
        m_undo_group.setActiveStack(target);
        target->undo();
    }
}

bool EditingSession::openStream(const QString& spec, const QString& lut)
{
    if (m_job)
        return false;
    m_opening = spec;
    auto job = std::make_shared<OpenJob>();
    job->session = this;
    m_job = job;
    SourceOpener opener = m_opener;
    if (!opener) {
        const Pipeline* pipeline = &m_pipeline;
        opener = [pipeline](const QString& s, const QString& l) {
            return StreamDocument::openSource(s, l, *pipeline);
        };
    }
    // A thread of its own, not the global pool: the application waits for the pool's threads
    // when it ends, and an open can be stuck in the system for good.
    std::thread([job, opener = std::move(opener), spec, lut] {
        Opening o;
        try {
            auto stream = opener(spec, lut);
            if (stream)
                o.stream = std::move(stream).value();
            else
                o.error = QString::fromStdString(stream.error().message);
        } catch (const std::bad_alloc&) {
            o.error = tr("%1: not enough memory to open it").arg(spec);
        } catch (const std::exception& e) {
            o.error = spec + QStringLiteral(": ") + QString::fromLocal8Bit(e.what());
        }
        const std::lock_guard lock(job->mutex);
        job->done = true;
        if (EditingSession* session = job->session) // alive while the lock is held
            QMetaObject::invokeMethod(
                session, [session, job, o] { session->finishOpening(job, o); },
                Qt::QueuedConnection);
        job->finished.notify_all();
    }).detach();
    return true;
}

void EditingSession::finishOpening(const std::shared_ptr<OpenJob>& job, const Opening& result)
{
    if (job != m_job) // cancelled after it ended
        return;
    m_job.reset();
    if (!result.stream) {
        emit opened(false, false, result.error);
        return;
    }
    adopt(result.stream);
    emit opened(true, false, {});
}

void EditingSession::cancelOpening()
{
    if (!m_job)
        return;
    // The open runs to its end in the background and is dropped there.
    {
        const std::lock_guard lock(m_job->mutex);
        m_job->session = nullptr;
    }
    m_job.reset();
    emit opened(false, true, tr("Opening %1 was cancelled").arg(m_opening));
}

Status EditingSession::open(const QString& spec, const QString& lut)
{
    auto stream = StreamDocument::openSource(spec, lut, m_pipeline);
    if (!stream)
        return stream.error();
    adopt(std::move(stream).value());
    return {};
}

QString EditingSession::missingAnnotatedFrames() const
{
    if (!m_stream->hasStream() || m_stream->live())
        return {};
    std::set<std::string, std::less<>> present; // the annotation keys the stream's frames have
    for (std::size_t i = 0; i < m_stream->frameCount(); ++i)
        present.insert(m_annotations->keyOf(m_stream->frameName(i).toStdString()));
    std::size_t missing = 0;
    std::string first;
    for (const auto& [name, frame] : m_annotations->annotations().frames) {
        if (present.count(name))
            continue;
        if (missing++ == 0)
            first = name;
    }
    if (missing == 0)
        return {};
    const QString file = m_annotations->path().isEmpty()
                             ? tr("The annotations")
                             : QFileInfo(m_annotations->path()).fileName();
    const QString count =
        missing == 1 ? tr("1 frame") : tr("%1 frames").arg(QLocale().toString(qulonglong(missing)));
    return tr("%1 names %2 this stream lacks (the first: %3); fieldsight eval refuses it while "
              "a done or reviewed one is missing")
        .arg(file, count, QString::fromStdString(first));
}

void EditingSession::adopt(std::shared_ptr<OpenedStream> opened)
{
    m_effect->setStream({}, nullptr); // scanned again once its table is in
    m_evaluation->setStream({}, nullptr);
    m_light->setStream({}, nullptr);
    m_warnings = opened->warnings;
    const QString spec = opened->spec;
    const QString lut_path = opened->lut_path;
    const std::optional<ParamSet> params = opened->params;
    const QString params_file =
        opened->info.params.empty() ? QString() : fromLocalPath(opened->info.params);
    const FileFingerprint params_read = opened->params_read;
    std::shared_ptr<const ColourLut> table = opened->lut;
    const FileFingerprint lut_read = opened->lut_read;
    // Its annotations just before it, so its first frame is drawn with its own truth. Unsaved
    // annotation edits of the stream before are the window's to save or drop before it opens
    // another; a recovery of them stays for their own stream.
    m_annotations->adopt(sessionStreamName(spec), opened->annotations_path,
                         std::move(opened->annotations), opened->annotations_problem,
                         opened->annotations_read);
    // The stream first: the table's change then runs the new stream's frame, never the old one.
    m_stream->adopt(std::move(opened));
    if (const QString missing = missingAnnotatedFrames(); !missing.isEmpty())
        m_warnings << missing;
    // Edits are never dropped silently: a table opened under unsaved edits (an open finishing
    // after a recovery) gives way to the edited one.
    if (!m_lut->modified())
        m_lut->reset(std::move(table), lut_path, lut_read);
    // The recovery file names the stream its edits belong to, wherever the next session runs.
    m_lut->setStream(sessionStreamName(spec));
    if (Status s = m_bookmarks->setStream(spec); !s)
        m_warnings << QString::fromStdString(s.error().message);
    if (Status s = m_samples->setStream(spec); !s)
        m_warnings << QString::fromStdString(s.error().message);
    // The stream's own parameters (and the command line's over them) replace those in use; a
    // stream without a parameter file runs with the pipeline's defaults, one whose file cannot
    // be read with those in use. The state it opens in is the bottom of the parameters' history:
    // no Undo goes back to the stream before's, or to the defaults.
    ParamSet wanted = params ? *params : m_settings->paramChanges();
    if (params)
        wanted.merge(m_param_overrides);
    m_settings->reset(wanted);
    m_settings->setFile(params_file, params_read);
    const StreamOptions options{m_stream->orientation()};
    m_samples->setStreamOptions(options);
    m_effect->setSettings(m_settings->paramVersion(), m_settings->skippedStages());
    m_effect->setStream(spec, m_lut->version(), options);
    m_evaluation->setSettings(m_settings->paramVersion(), m_settings->skippedStages());
    m_evaluation->setTruth(truthVersion(), m_annotations->path());
    m_evaluation->setStream(spec, m_lut->version(), options);
    if (!m_stream->live())
        m_light->setStream(spec, m_lut->version(), options);
    // Undo starts on the new stream's table.
    m_undo_group.setActiveStack(&m_lut->undoStack());
}

QString EditingSession::title() const
{
    if (!m_stream->hasStream())
        return QStringLiteral("Fieldsight");
    const bool annotations_edited = m_annotations->modified();
    // Qt shows a * at every [*]: one after each document with unsaved edits.
    const QString marker =
        m_lut->modified() || !annotations_edited ? QStringLiteral("[*]") : QString();
    const QString lut = m_lut->path();
    QString title = QStringLiteral("%1 — %2%3")
                        .arg(QFileInfo(m_stream->streamSpec()).fileName(),
                             lut.isEmpty() ? tr("new LUT")
                                           // Which default.lut: its folder too.
                                           : QFileInfo(lut).dir().dirName() + QLatin1Char('/') +
                                                 QFileInfo(lut).fileName(),
                             marker);
    if (annotations_edited) {
        const QString file = m_annotations->path();
        title += QStringLiteral(" — %1[*]")
                     .arg(file.isEmpty() ? tr("annotations") : QFileInfo(file).fileName());
    }
    return title + QStringLiteral(" — Fieldsight");
}

bool EditingSession::unsavedEdits() const
{
    return m_lut->modified() || (m_stream->hasStream() && m_annotations->modified());
}

Status EditingSession::openLut(const QString& path)
{
    if (!m_stream->hasStream())
        return Error{toLocalPath(path) + ": open a stream first"};
    auto table = importLut(toLocalPath(path));
    if (!table)
        return table.error();
    m_lut->reset(std::make_shared<const ColourLut>(std::move(table).value()), path);
    return {};
}

} // namespace fieldsight::ui
