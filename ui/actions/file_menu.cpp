// File: streams, tables, the camera recording and snapshots of the view.
#include "ui/actions/coco_export_command.h"
#include "ui/actions/annotations_file.h"
#include "ui/actions/session_files.h"
#include "ui/actions/menus.h"
#include "ui/dialogs/dialogs.h"
#include "ui/recording/frame_recorder.h"
#include "ui/main_window.h"
#include "visioncore/io/lut_import.h"

#include <QFileInfo>
#include <QMenuBar>

namespace fieldsight::ui {

namespace {

QString lutFilter()
{
    QString filter = QObject::tr("Colour tables (");
    for (std::string_view suffix : importableLutSuffixes())
        filter += QStringLiteral("*%1 ").arg(
            QString::fromLatin1(suffix.data(), qsizetype(suffix.size())));
    return filter + QStringLiteral(");;") + QObject::tr("All files (*)");
}

void addRecordItem(MainWindow& w, QMenu* file)
{
    QAction* record = file->addAction(QObject::tr("Record camera to folder…"));
    record->setObjectName(QStringLiteral("record_camera"));
    record->setCheckable(true);
    record->setToolTip(QObject::tr("Write every camera frame shown (play to record "
                                   "continuously) into a stream folder, with the LUT in use"));
    FrameRecorder& recorder = w.recorder();
    QObject::connect(record, &QAction::triggered, &w, [&w, &recorder, record](bool on) {
        if (!on) {
            if (Status s = recorder.stop(); !s)
                w.showMessage(QString::fromStdString(s.error().message));
            else
                w.showMessage(QObject::tr("Recorded %1 frames to %2")
                                  .arg(qulonglong(recorder.frames()))
                                  .arg(recorder.path()),
                              false);
            return;
        }
        const QString folder =
            Dialogs::current().folder(&w, QObject::tr("Record camera frames into"), {});
        Status s = folder.isEmpty() ? Status(Error{"no folder chosen"})
                                    : recorder.start(folder, w.session().lut().table());
        if (!s && !folder.isEmpty())
            w.showMessage(QString::fromStdString(s.error().message));
        record->setChecked(recorder.recording());
    });
    QObject::connect(&recorder, &FrameRecorder::stateChanged, record, &QAction::setChecked);
    QObject::connect(&w.session().stream(), &StreamDocument::streamChanged, record,
                     [&w, record] { record->setEnabled(w.session().stream().live()); });
    record->setEnabled(false);
}

} // namespace

void addFileMenu(MainWindow& w)
{
    SessionFiles& files = w.files();
    EditingSession& session = w.session();
    QMenu* file = w.menuBar()->addMenu(QObject::tr("&File"));
    addMenuItem(file, QObject::tr("Open stream folder…"), QKeySequence::Open, &w, [&] {
        const QString dir =
            Dialogs::current().folder(&w, QObject::tr("Open stream folder"),
                                      QFileInfo(session.stream().streamSpec()).absolutePath());
        if (!dir.isEmpty())
            files.openStream(dir);
    });
    addMenuItem(file, QObject::tr("Open stream file (.strm, video)…"),
                QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_O), &w, [&] {
                    const QString path = Dialogs::current().openFile(
                        &w, QObject::tr("Open stream file"),
                        QFileInfo(session.stream().streamSpec()).absolutePath(),
                        QObject::tr("Streams (*.strm *.avi *.mp4 *.mkv *.mov *.webm);;All "
                                    "files (*)"));
                    if (!path.isEmpty())
                        files.openStream(path);
                });
    file->addAction(QObject::tr("Open camera…"), &w, [&] {
        if (const auto n = Dialogs::current().number(&w, QObject::tr("Open camera"),
                                                     QObject::tr("Camera number:"), 0, 0, 99))
            files.openStream(QStringLiteral("camera:%1").arg(*n));
    });
    addRecordItem(w, file);
    addMenuItem(file, QObject::tr("New LUT"), QKeySequence(Qt::CTRL | Qt::ALT | Qt::Key_N), &w,
                [&] { (void)files.newLut(); })
        ->setObjectName(QStringLiteral("file.new_lut"));
    addMenuItem(file, QObject::tr("Open LUT…"), QKeySequence(Qt::CTRL | Qt::Key_L), &w, [&] {
        const QString path = Dialogs::current().openFile(
            &w, QObject::tr("Open LUT"), QFileInfo(session.lut().path()).absolutePath(),
            lutFilter());
        if (!path.isEmpty())
            files.openLut(path);
    });
    file->addAction(QObject::tr("Compare with LUT…"), &w, [&] {
        const QString path = Dialogs::current().openFile(
            &w, QObject::tr("Compare with LUT"), QFileInfo(session.lut().path()).absolutePath(),
            lutFilter());
        if (!path.isEmpty())
            files.compareLut(path);
    });
    // Ctrl+S saves what has unsaved edits: the annotations, and the table as it always did.
    QAction* save = addMenuItem(file, QObject::tr("Save"), QKeySequence::Save, &w,
                                [&] { (void)w.annotationFiles().saveAll(); });
    save->setObjectName(QStringLiteral("file.save"));
    save->setToolTip(QObject::tr("Save the LUT, and the annotations when they have unsaved edits"));
    addMenuItem(file, QObject::tr("Save LUT as…"), QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_S),
                &w, [&] { (void)files.saveLutAs(); });
    addMenuItem(file, QObject::tr("Save annotations"), QKeySequence(Qt::CTRL | Qt::ALT | Qt::Key_S),
                &w, [&] { (void)w.annotationFiles().save(); })
        ->setObjectName(QStringLiteral("file.save_annotations"));
    file->addAction(QObject::tr("Save annotations as…"), &w,
                    [&] { (void)w.annotationFiles().saveAs(); })
        ->setObjectName(QStringLiteral("file.save_annotations_as"));
    files.setRecentMenu(file->addMenu(QObject::tr("Recent streams")));
    file->addSeparator();
    QAction* coco = file->addAction(QObject::tr("Export annotations as COCO…"), &w, [&] {
        const QFileInfo spec(session.stream().streamSpec());
        const QString folder = spec.isDir() ? spec.absoluteFilePath() : spec.absolutePath();
        const QString path = Dialogs::current().saveFile(
            &w, QObject::tr("Export annotations as COCO"),
            folder + QStringLiteral("/%1_coco.json").arg(spec.completeBaseName()),
            QObject::tr("COCO JSON (*.json)"));
        if (!path.isEmpty())
            exportAnnotationsAsCoco(w, path);
    });
    coco->setObjectName(QStringLiteral("file.export_coco"));
    file->addSeparator();
    addMenuItem(
        file, QObject::tr("Save view as PNG…"), QKeySequence(Qt::CTRL | Qt::Key_E), &w, [&] {
            const QString name =
                QStringLiteral("%1_%2.png")
                    .arg(QFileInfo(session.stream().streamSpec()).completeBaseName())
                    .arg(session.stream().currentIndex(), 6, 10, QLatin1Char('0'));
            const QString path = Dialogs::current().saveFile(
                &w, QObject::tr("Save view as PNG"), name, QObject::tr("PNG images (*.png)"));
            if (!path.isEmpty())
                files.saveSnapshot(path);
        });
    addMenuItem(file, QObject::tr("Copy view"), QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_C),
                &files, &SessionFiles::copySnapshot);
    file->addSeparator();
    addMenuItem(file, QObject::tr("Quit"), QKeySequence::Quit, &w, &QWidget::close);
}

} // namespace fieldsight::ui
