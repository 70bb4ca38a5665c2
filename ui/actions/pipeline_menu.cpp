// Pipeline: run the frame again, reset, and parameter files (loading one is an undoable edit).
#include "ui/actions/menus.h"
#include "ui/adapters/local_path.h"
#include "ui/dialogs/dialogs.h"
#include "ui/main_window.h"

#include <QMenuBar>

namespace fieldsight::ui {

void addPipelineMenu(MainWindow& w)
{
    EditingSession& session = w.session();
    QMenu* pipe = w.menuBar()->addMenu(QObject::tr("&Pipeline"));
    addMenuItem(pipe, QObject::tr("Run this frame again"), QKeySequence(Qt::Key_F5),
                &session.stream(), &StreamDocument::rerun);
    pipe->addAction(QObject::tr("Reset every parameter"), &w, [&session] {
        (void)session.settings().setParamChanges({}, QObject::tr("Reset every parameter"));
    });
    pipe->addAction(QObject::tr("Reset the running means"), &session.stream(),
                    &StreamDocument::resetMeans);
    pipe->addAction(QObject::tr("Save parameters…"), &w, [&w, &session] {
        const QString path = Dialogs::current().saveFile(&w, QObject::tr("Save parameters"),
                                                         QStringLiteral("params.json"),
                                                         QObject::tr("Parameter sets (*.json)"));
        if (path.isEmpty())
            return;
        if (Status s = session.settings().paramChanges().save(toLocalPath(path)); !s)
            w.showMessage(QString::fromStdString(s.error().message));
        else
            w.showMessage(QObject::tr("Saved the parameters to %1").arg(path), false);
    });
    pipe->addAction(QObject::tr("Load parameters…"), &w, [&w, &session] {
        const QString path = Dialogs::current().openFile(&w, QObject::tr("Load parameters"), {},
                                                         QObject::tr("Parameter sets (*.json)"));
        if (path.isEmpty())
            return;
        auto params = ParamSet::load(toLocalPath(path));
        Status s = params ? session.settings().setParamChanges(params.value(),
                                                               QObject::tr("Load %1").arg(path))
                          : Status(params.error());
        if (!s)
            w.showMessage(QString::fromStdString(s.error().message));
    });
}

} // namespace fieldsight::ui
