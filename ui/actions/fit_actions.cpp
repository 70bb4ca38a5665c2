// Pipeline > Fit to annotations: the search started, its progress, its result shown and applied.
#include "ui/actions/fit_actions.h"

#include "ui/adapters/local_path.h"
#include "ui/dialogs/dialogs.h"
#include "ui/document/editing_session.h"
#include "ui/dialogs/fit_result_dialog.h"
#include "ui/widgets/progress_poll.h"

#include <QLocale>
#include <QProgressDialog>
#include <QTimer>

#include <algorithm>

namespace fieldsight::ui {

namespace {

constexpr int kMinBudget = 10;
constexpr int kMaxBudget = 100000;

/// The frames of `truth` with something to score by `pipeline`'s kinds.
std::size_t scoredFrames(const Annotations& truth, const Pipeline& pipeline)
{
    const std::vector<const PerceptKind*> kinds = scoredKinds(pipeline.perceptKinds());
    return std::size_t(
        std::count_if(truth.frames.begin(), truth.frames.end(),
                      [&kinds](const auto& f) { return isScored(f.second, kinds); }));
}

} // namespace

FitActions::FitActions(const MenuTarget& target) : QObject(target.parent), m_target(target)
{
    m_run = new TuneRun(this);
    connect(m_run, &TuneRun::finished, this, &FitActions::onFinished);
    // Parameters fitted to other frames are not this stream's: a search over a stream closed or
    // turned meanwhile is dropped, and a result shown for another stream closes.
    StreamDocument& stream = m_target.session.stream();
    const auto stale = [this] {
        if (m_run->running()) {
            m_stale = true;
            m_run->cancel();
        }
        if (m_dialog)
            m_dialog->close();
    };
    connect(&stream, &StreamDocument::streamChanged, this, stale);
    connect(&stream, &StreamDocument::orientationChanged, this, stale);
}

FitResultDialog* FitActions::resultDialog() const
{
    return m_dialog;
}

void FitActions::setBudget(int budget)
{
    m_budget = std::clamp(budget, kMinBudget, kMaxBudget);
}

void FitActions::fitToAnnotations()
{
    if (m_run->running() || !ready())
        return;
    const std::optional<int> budget = Dialogs::current().number(
        m_target.parent, tr("Fit to annotations"),
        tr("Search the pipeline's parameters for the best score on the annotated frames.\nHow many "
           "evaluations (each runs the fit frames once)? Cancel keeps the best found so far."),
        m_budget, kMinBudget, kMaxBudget);
    if (!budget)
        return;
    setBudget(*budget);
    start(m_budget);
}

bool FitActions::ready()
{
    EditingSession& session = m_target.session;
    StreamDocument& stream = session.stream();
    if (!stream.hasStream() || stream.live()) {
        m_target.showMessage(stream.live()
                                 ? tr("Fit to annotations reads a stream's annotated frames: "
                                      "record the camera to a folder and annotate it first")
                                 : tr("Open a stream with annotations first: the parameters are "
                                      "fitted to its annotated frames"));
        return false;
    }
    const AnnotationsDocument& annotations = session.annotations();
    if (!annotations.loadProblem().isEmpty()) {
        m_target.showMessage(tr("Fit to annotations: %1").arg(annotations.loadProblem()));
        return false;
    }
    if (scoredFrames(annotations.annotations(), session.pipeline()) == 0) {
        m_target.showMessage(
            annotations.annotations().frames.empty()
                ? tr("This stream has no annotations yet: annotate some frames and mark them done "
                     "(D), then fit the parameters to them")
                : tr("None of the annotated frames is done or has a reviewed kind: mark the frames "
                     "whose truth is complete done (D), then fit the parameters to them"));
        return false;
    }
    return true;
}

bool FitActions::start(int budget)
{
    if (m_run->running() || !ready())
        return false;
    EditingSession& session = m_target.session;
    StreamDocument& stream = session.stream();
    // The annotations as the document holds them, unsaved edits too.
    const AnnotationsDocument& annotations = session.annotations();
    Annotations truth = annotations.annotations();
    const std::size_t scored = scoredFrames(truth, session.pipeline());
    const std::string spec = toLocalPath(stream.streamSpec());
    StreamOptions options;
    options.orientation = stream.orientation();
    auto reader = openStream(spec, options);
    if (!reader) {
        m_target.showMessage(QString::fromStdString(reader.error().message));
        return false;
    }
    auto input = std::make_shared<StreamInput>();
    input->stream = spec;
    input->reader = std::move(reader).value();
    input->lut_path = toLocalPath(session.lut().path());
    input->lut = session.lut().version();
    input->pipeline = &session.pipeline();
    input->params = session.settings().paramChanges();
    const StageSet& skipped = session.settings().skippedStages();
    input->skip.assign(skipped.begin(), skipped.end());

    TuneOptions tune;
    tune.budget = budget;
    m_stale = false;
    m_start_params = session.settings().paramVersion();
    m_start_lut = input->lut;
    m_run->start(std::move(input), std::move(truth), toLocalPath(annotations.path()),
                 std::move(tune));
    const QString label = scored == 1 ? tr("Fitting the parameters to 1 annotated frame…")
                                      : tr("Fitting the parameters to %1 annotated frames…")
                                            .arg(QLocale().toString(qulonglong(scored)));
    QProgressDialog* progress =
        showProgress(m_target.parent, label, QStringLiteral("fit.progress"),
                     {[this] { return m_run->progress(); }, [this] { return m_run->running(); },
                      [this] { m_run->cancel(); }});
    // The best score so far under the count, so a user sees when more is not buying anything.
    auto* best = new QTimer(progress);
    connect(best, &QTimer::timeout, progress, [this, progress, label] {
        if (m_run->bestFit() >= 0 && !progress->wasCanceled())
            progress->setLabelText(label + '\n' +
                                   tr("Best score on the fit frames so far: %1")
                                       .arg(QString::number(m_run->bestFit(), 'f', 3)));
    });
    best->start(250);
    return true;
}

void FitActions::onFinished(const Result<TuneResult>& result)
{
    if (m_stale) {
        m_target.showMessage(tr("Fit to annotations dropped: the stream changed while it ran; "
                                "the parameters are unchanged"),
                             false);
        emit finished(false);
        return;
    }
    if (!result) {
        m_target.showMessage(tr("Fit to annotations: %1; the parameters are unchanged")
                                 .arg(QString::fromStdString(result.error().message)));
        emit finished(false);
        return;
    }
    EditingSession& session = m_target.session;
    auto* dialog = new FitResultDialog(result.value(), session.pipeline(), m_target.parent);
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    QStringList notes;
    if (session.settings().paramVersion() != m_start_params)
        notes << tr("The parameters changed while the search ran: Apply replaces them with "
                    "these (Ctrl+Z brings them back).");
    if (session.lut().version() != m_start_lut)
        notes << tr("The table changed while the search ran: these scores are the table's "
                    "before the change.");
    dialog->setNote(notes.join(' '));
    connect(dialog, &FitResultDialog::applyRequested, this,
            [this, dialog] { apply(dialog->result()); });
    m_dialog = dialog;
    dialog->show();
    dialog->raise();
    dialog->activateWindow();
    emit finished(true);
}

bool FitActions::apply(const TuneResult& result)
{
    PipelineSettings& settings = m_target.session.settings();
    const int changed = int(result.changes.size());
    // The settings hold the values that differ from the defaults (the stream's own are in
    // them already): a value the search put back to its default is dropped, as the pipeline
    // panel drops one, rather than kept as a change.
    if (Status s = settings.setParamChanges(
            differingFromDefaults(result.params, settings.pipeline()),
            changed == 1 ? tr("Fit to annotations (1 parameter)")
                         : tr("Fit to annotations (%1 parameters)").arg(changed));
        !s) {
        m_target.showMessage(tr("The fitted parameters were not applied: %1")
                                 .arg(QString::fromStdString(s.error().message)));
        return false;
    }
    m_target.showMessage(tr("Fitted parameters in use: %n changed (Ctrl+Z takes them back); "
                            "Pipeline > Save parameters to the stream writes them to its "
                            "params.json",
                            nullptr, changed),
                         false);
    return true;
}

} // namespace fieldsight::ui
