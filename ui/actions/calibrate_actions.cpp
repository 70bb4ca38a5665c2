// Calibrate > Automatic table: the run started, its progress, and its table put in.
#include "ui/actions/calibrate_actions.h"

#include "ui/adapters/image_adapter.h"
#include "ui/document/editing_session.h"
#include "ui/widgets/progress_poll.h"

#include "visioncore/services/lut_compare.h"

#include <QLocale>

namespace fieldsight::ui {

namespace {

/// The parameter the found goal colour goes into: every colour choice named so, whichever stage
/// declares it (found through the registry, so no stage is named here).
constexpr std::string_view kGoalColourParam = "goal_colour";

bool isColourChoice(const ParamInfo& p)
{
    return p.kind == ParamKind::Choice && p.choices.size() == std::size_t(kColourCount);
}

QString frameCount(std::size_t n)
{
    return n == 1 ? CalibrateActions::tr("1 frame")
                  : CalibrateActions::tr("%1 frames").arg(QLocale().toString(qulonglong(n)));
}

QString percent(double share)
{
    return QLocale().toString(share * 100, 'f', 1) + QStringLiteral(" %");
}

} // namespace

CalibrateActions::CalibrateActions(const MenuTarget& target)
    : QObject(target.parent), m_target(target)
{
    m_run = new AutoLutRun(this);
    connect(m_run, &AutoLutRun::finished, this, &CalibrateActions::onFinished);
    // A table read from other frames is not this stream's: a run over a stream closed or turned
    // meanwhile is dropped.
    StreamDocument& stream = m_target.session.stream();
    const auto stale = [this] {
        if (m_run->running()) {
            m_stale = true;
            m_run->cancel();
        }
    };
    connect(&stream, &StreamDocument::streamChanged, this, stale);
    connect(&stream, &StreamDocument::orientationChanged, this, stale);
}

void CalibrateActions::automaticTable()
{
    if (m_run->running())
        return;
    StreamDocument& stream = m_target.session.stream();
    if (!stream.hasStream() || stream.live() || !stream.reopener()) {
        m_target.showMessage(stream.live()
                                 ? tr("The automatic table reads a stream's frames: record the "
                                      "camera to a folder first (File > Record camera to folder…)")
                                 : tr("Open a stream first: the automatic table is made from its "
                                      "frames"));
        return;
    }
    m_stale = false;
    m_run->start(stream.reopener());
    showProgress(m_target.parent, tr("Making the automatic table from the stream's frames…"),
                 QStringLiteral("calibrate.progress"),
                 {[this] { return m_run->progress(); }, [this] { return m_run->running(); },
                  [this] { m_run->cancel(); }});
}

void CalibrateActions::onFinished(const Result<AutoLut>& result)
{
    if (m_stale) {
        m_target.showMessage(tr("Automatic table dropped: the stream changed while it was made; "
                                "the LUT is unchanged"),
                             false);
        emit finished(false);
        return;
    }
    if (!result) {
        m_target.showMessage(tr("No automatic table: %1; the LUT is unchanged")
                                 .arg(QString::fromStdString(result.error().message)));
        emit finished(false);
        return;
    }
    const AutoLut& made = result.value();
    if (made.cancelled) {
        m_target.showMessage(tr("Automatic table cancelled; the LUT is unchanged"), false);
        emit finished(false);
        return;
    }
    // The goal colour first, so the first Ctrl+Z takes back the table and the next the colour.
    const bool goal_set = made.goal_colour && setGoalColour(*made.goal_colour);
    LutDocument& lut = m_target.session.lut();
    std::vector<CellChange> changes = diffLuts(lut.table(), made.lut).cells;
    const std::size_t cells = changes.size();
    lut.edit(tr("Automatic table from %1").arg(frameCount(made.frames)), std::move(changes));
    m_target.showMessage(summary(made, cells, goal_set), false);
    emit finished(true);
}

bool CalibrateActions::setGoalColour(Colour goal)
{
    PipelineSettings& settings = m_target.session.settings();
    const double value = double(int(goal));
    std::vector<std::pair<std::string, std::string>> targets;
    for (const StageDescriptor& stage : settings.pipeline().descriptors())
        for (const ParamInfo& p : stage.params)
            if (p.name == kGoalColourParam && isColourChoice(p) &&
                settings.paramValue(stage.info.id, p.name) != value)
                targets.emplace_back(stage.info.id, p.name);
    if (targets.empty())
        return false;
    QUndoStack& stack = settings.undoStack();
    if (targets.size() > 1)
        stack.beginMacro(tr("Goal colour %1").arg(colourLabel(goal)));
    for (const auto& [stage, name] : targets)
        if (Status s = settings.setParam(stage, name, value); !s)
            m_target.showMessage(QString::fromStdString(s.error().message));
    if (targets.size() > 1)
        stack.endMacro();
    return true;
}

QString CalibrateActions::summary(const AutoLut& made, std::size_t cells_changed,
                                  bool goal_set) const
{
    QStringList classes;
    for (const AutoLutClass& c : made.classes)
        classes << tr("%1 %2 cells (%3 of the pixels)")
                       .arg(colourLabel(c.colour), QLocale().toString(qulonglong(c.cells)),
                            percent(c.pixel_share));
    QString text =
        cells_changed == 0
            ? tr("The automatic table from %1 is the table in use").arg(frameCount(made.frames))
            : tr("Automatic table from %1 (%2 cells changed; Ctrl+Z undoes it)")
                  .arg(frameCount(made.frames), QLocale().toString(qulonglong(cells_changed)));
    text += QStringLiteral(": ") +
            (classes.isEmpty() ? tr("no class found") : classes.join(QStringLiteral(", ")));
    if (made.goal_colour)
        text += goal_set ? tr(". Goal colour %1 (the pipeline's goal colour is set to it)")
                               .arg(colourLabel(*made.goal_colour))
                         : tr(". Goal colour %1").arg(colourLabel(*made.goal_colour));
    else
        text += tr(". No goal found");
    QStringList notes;
    for (const std::string& n : made.notes)
        notes << QString::fromStdString(n);
    if (!notes.isEmpty())
        text += tr(". Notes: %1").arg(notes.join(QStringLiteral("; ")));
    return text;
}

} // namespace fieldsight::ui
