// Pipeline: run the frame again, reset, parameter files (loading one is an undoable edit),
// comparing the table and parameters in use with others over the annotated frames, and fitting
// the parameters to those frames (FitActions).
#include "ui/actions/disk_conflict.h"
#include "ui/actions/fit_actions.h"
#include "ui/actions/menus.h"
#include "ui/adapters/local_path.h"
#include "ui/dialogs/dialogs.h"
#include "ui/dialogs/ab_compare_dialog.h"
#include "ui/document/editing_session.h"

#include "visioncore/basics/output_guard.h"
#include "visioncore/io/orientation.h"

#include <QMenuBar>

#include <filesystem>

namespace fieldsight::ui {

namespace {

/// Saves the parameters in use as the stream's own: to the file its manifest names, or to a new
/// params.json in its folder, which the manifest then names (so the stream opens with them, in
/// the window and on the command line). Never over a file the stream does not name.
void saveParams(const MenuTarget& w);

/// The stream names `file` as its own parameters, which hold what the settings hold.
void markSaved(const MenuTarget& w, const std::string& file)
{
    w.session.stream().setParamsFile(file);
    w.session.settings().setFile(fromLocalPath(file));
}

void saveParamsToStream(const MenuTarget& w)
{
    StreamDocument& stream = w.session.stream();
    const StreamInfo& info = stream.info();
    if (!stream.hasStream() || info.kind != StreamKind::ImageFolder) {
        w.showMessage(QObject::tr("Only a folder of images keeps its own parameters (in its "
                                  "stream.json); use Save parameters… for this stream"));
        return;
    }
    const std::filesystem::path folder(info.path);
    const bool named = !info.params.empty();
    const std::string file = named ? info.params : (folder / "params.json").string();
    std::error_code ec;
    if (!named && std::filesystem::exists(std::filesystem::symlink_status(file, ec))) {
        w.showMessage(QObject::tr("%1 exists and the stream does not name it as its parameters: "
                                  "it is not written over (use Save parameters…)")
                          .arg(fromLocalPath(file)));
        return;
    }
    // Another window or a command wrote the stream's parameters since it opened: never dropped
    // silently.
    const auto reload = [&] {
        auto read = ParamSet::load(file);
        Status s = read ? w.session.settings().setParamChanges(
                              read.value(), QObject::tr("Reload parameters from disk"))
                        : Status(read.error());
        if (!s)
            w.showMessage(QString::fromStdString(s.error().message));
        else
            markSaved(w, file);
        return s.ok();
    };
    bool overwrite = false; // the stream's own file is written either way
    if (settleDiskChange(w, named && w.session.settings().changedOnDisk(),
                         QObject::tr("the parameters"), fromLocalPath(file), overwrite, reload,
                         [&w] {
                             saveParams(w);
                             return true;
                         })
            .has_value())
        return; // reloaded, saved elsewhere or cancelled
    Status s = w.session.settings().paramChanges().save(file);
    if (s && !named) {
        s = writeStreamParams(info.path, file);
        if (s)
            stream.manifestWritten(); // the window's own write: no other writer's change
    }
    if (!s) {
        w.showMessage(QString::fromStdString(s.error().message));
        return;
    }
    markSaved(w, file);
    w.showMessage(QObject::tr("Saved the parameters as the stream's own (%1): it opens with them")
                      .arg(fromLocalPath(file)),
                  false);
}

/// Pipeline > Save parameters…: the parameters in use to a file the user names, through the
/// output guard (never over a frame, a table or another command's file).
void saveParams(const MenuTarget& w)
{
    const QString path = Dialogs::current().saveFile(w.parent, QObject::tr("Save parameters"),
                                                     QStringLiteral("params.json"),
                                                     QObject::tr("Parameter sets (*.json)"));
    if (path.isEmpty())
        return;
    const OutputFileKind params{"fieldsight-params/1", {}, false, true};
    Status s = checkOutputFile("Save parameters", toLocalPath(path), {}, params);
    if (s)
        s = w.session.settings().paramChanges().save(toLocalPath(path));
    if (!s)
        w.showMessage(QString::fromStdString(s.error().message));
    else
        w.showMessage(QObject::tr("Saved the parameters to %1").arg(path), false);
}

} // namespace

void addPipelineMenu(QMenuBar& bar, const MenuTarget& w, const MenuParts& parts)
{
    EditingSession& session = w.session;
    QMenu* pipe = bar.addMenu(QObject::tr("&Pipeline"));
    addMenuItem(pipe, QObject::tr("Run this frame again"), QKeySequence(Qt::Key_F5),
                &session.stream(), &StreamDocument::rerun);
    pipe->addAction(QObject::tr("Reset every parameter"), w.parent, [&session] {
        (void)session.settings().setParamChanges({}, QObject::tr("Reset every parameter"));
    });
    pipe->addAction(QObject::tr("Reset the running means"), &session.stream(),
                    &StreamDocument::resetMeans);
    pipe->addAction(QObject::tr("Save parameters…"), w.parent, [w] { saveParams(w); });
    pipe->addAction(QObject::tr("Save parameters to the stream"), w.parent,
                    [w] { saveParamsToStream(w); })
        ->setObjectName(QStringLiteral("pipeline.save_params_to_stream"));
    pipe->addAction(QObject::tr("Load parameters…"), w.parent, [w, &session] {
        const QString path = Dialogs::current().openFile(
            w.parent, QObject::tr("Load parameters"), {}, QObject::tr("Parameter sets (*.json)"));
        if (path.isEmpty())
            return;
        auto params = ParamSet::load(toLocalPath(path));
        Status s = params ? session.settings().setParamChanges(params.value(),
                                                               QObject::tr("Load %1").arg(path))
                          : Status(params.error());
        if (!s)
            w.showMessage(QString::fromStdString(s.error().message));
    });
    pipe->addSeparator();
    QAction* compare = pipe->addAction(QObject::tr("Compare A/B…"), w.parent, [w, &session] {
        auto* dialog = new AbCompareDialog(session, w.parent);
        dialog->setAttribute(Qt::WA_DeleteOnClose);
        dialog->show();
    });
    compare->setObjectName(QStringLiteral("pipeline.compare_ab"));
    compare->setToolTip(QObject::tr("Run the annotated frames with another table or parameter set "
                                    "and list the frames it fixes and breaks"));
    FitActions* fit = &parts.fit;
    QAction* fit_action = addMenuItem(pipe, QObject::tr("Fit to annotations…"),
                                      QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_F), fit,
                                      &FitActions::fitToAnnotations);
    fit_action->setObjectName(QStringLiteral("pipeline.fit_annotations"));
    fit_action->setToolTip(QObject::tr(
        "Search the stages' parameters for the best score on the annotated frames, show the "
        "scores before and after on the fitted and held-out frames, then apply (one undo step)"));
    // Greyed while the search runs: a second click would only wait for the first.
    QObject::connect(fit, &FitActions::finished, fit_action,
                     [fit_action] { fit_action->setEnabled(true); });
    QObject::connect(fit_action, &QAction::triggered, fit_action,
                     [fit_action, fit] { fit_action->setEnabled(!fit->running()); });
}

} // namespace fieldsight::ui
