// File: streams, tables, the camera recording and snapshots of the view.
#include "ui/actions/coco_export_action.h"
#include "ui/actions/annotations_file.h"
#include "ui/actions/session_files.h"
#include "ui/actions/menus.h"
#include "ui/dialogs/dialogs.h"
#include "ui/recording/frame_recorder.h"
#include "ui/document/editing_session.h"
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

void addRecordItem(const MenuTarget& w, FrameRecorder& recorder, QMenu* file)
{
    QAction* record = file->addAction(QObject::tr("Record camera to folder…"));
    record->setObjectName(QStringLiteral("record_camera"));
    record->setCheckable(true);
    record->setToolTip(QObject::tr("Write every camera frame shown (play to record "
                                   "continuously) into a stream folder, with the LUT in use"));
    QObject::connect(record, &QAction::triggered, w.parent, [w, r = &recorder, record](bool on) {
        if (!on) {
            if (Status s = r->stop(); !s)
                w.showMessage(QString::fromStdString(s.error().message));
            else
                w.showMessage(QObject::tr("Recorded %1 frames to %2")
                                  .arg(qulonglong(r->frames()))
                                  .arg(r->path()),
                              false);
            return;
        }
        const QString folder =
            Dialogs::current().folder(w.parent, QObject::tr("Record camera frames into"), {});
        Status s = folder.isEmpty() ? Status(Error{"no folder chosen"})
                                    : r->start(folder, w.session.lut().table());
        if (!s && !folder.isEmpty())
            w.showMessage(QString::fromStdString(s.error().message));
        record->setChecked(r->recording());
    });
    QObject::connect(&recorder, &FrameRecorder::stateChanged, record, &QAction::setChecked);
    StreamDocument& stream = w.session.stream();
    QObject::connect(&stream, &StreamDocument::streamChanged, record,
                     [s = &stream, record] { record->setEnabled(s->live()); });
    record->setEnabled(false);
}

} // namespace

void addFileMenu(QMenuBar& bar, const MenuTarget& w, const MenuParts& parts)
{
    // Captured by pointer and copy: the lambdas outlive this call and `w`.
    SessionFiles* files = &parts.files;
    AnnotationsFile* annotations = &parts.annotation_files;
    EditingSession* session = &w.session;
    QWidget* parent = w.parent;
    QMenu* file = bar.addMenu(QObject::tr("&File"));
    addMenuItem(file, QObject::tr("Open stream folder…"), QKeySequence::Open, parent, [=] {
        const QString dir =
            Dialogs::current().folder(parent, QObject::tr("Open stream folder"),
                                      QFileInfo(session->stream().streamSpec()).absolutePath());
        if (!dir.isEmpty())
            files->openStream(dir);
    });
    addMenuItem(file, QObject::tr("Open stream file (.strm, video)…"),
                QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_O), parent, [=] {
                    const QString path = Dialogs::current().openFile(
                        parent, QObject::tr("Open stream file"),
                        QFileInfo(session->stream().streamSpec()).absolutePath(),
                        QObject::tr("Streams (*.strm *.avi *.mp4 *.mkv *.mov *.webm);;All "
                                    "files (*)"));
                    if (!path.isEmpty())
                        files->openStream(path);
                });
    file->addAction(QObject::tr("Open camera…"), parent, [=] {
        if (const auto n = Dialogs::current().number(parent, QObject::tr("Open camera"),
                                                     QObject::tr("Camera number:"), 0, 0, 99))
            files->openStream(QStringLiteral("camera:%1").arg(*n));
    });
    addRecordItem(w, parts.recorder, file);
    addMenuItem(file, QObject::tr("New LUT"), QKeySequence(Qt::CTRL | Qt::ALT | Qt::Key_N), parent,
                [=] { (void)files->newLut(); })
        ->setObjectName(QStringLiteral("file.new_lut"));
    addMenuItem(file, QObject::tr("Open LUT…"), QKeySequence(Qt::CTRL | Qt::Key_L), parent, [=] {
        const QString path = Dialogs::current().openFile(
            parent, QObject::tr("Open LUT"), QFileInfo(session->lut().path()).absolutePath(),
            lutFilter());
        if (!path.isEmpty())
            files->openLut(path);
    });
    file->addAction(QObject::tr("Compare with LUT…"), parent, [=] {
        const QString path = Dialogs::current().openFile(
            parent, QObject::tr("Compare with LUT"),
            QFileInfo(session->lut().path()).absolutePath(), lutFilter());
        if (!path.isEmpty())
            files->compareLut(path);
    });
    // Ctrl+S saves what has unsaved edits: the annotations, and the table as it always did.
    QAction* save = addMenuItem(file, QObject::tr("Save"), QKeySequence::Save, parent,
                                [=] { (void)files->saveAll(); });
    save->setObjectName(QStringLiteral("file.save"));
    save->setToolTip(QObject::tr("Save the LUT, and the annotations when they have unsaved edits"));
    addMenuItem(file, QObject::tr("Save LUT as…"), QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_S),
                parent, [=] { (void)files->saveLutAs(); });
    addMenuItem(file, QObject::tr("Save annotations"), QKeySequence(Qt::CTRL | Qt::ALT | Qt::Key_S),
                parent, [=] { (void)annotations->save(); })
        ->setObjectName(QStringLiteral("file.save_annotations"));
    file->addAction(QObject::tr("Save annotations as…"), parent,
                    [=] { (void)annotations->saveAs(); })
        ->setObjectName(QStringLiteral("file.save_annotations_as"));
    files->setRecentMenu(file->addMenu(QObject::tr("Recent streams")));
    file->addSeparator();
    QAction* coco = file->addAction(QObject::tr("Export annotations as COCO…"), parent, [=] {
        const QFileInfo spec(session->stream().streamSpec());
        const QString folder = spec.isDir() ? spec.absoluteFilePath() : spec.absolutePath();
        const QString path = Dialogs::current().saveFile(
            parent, QObject::tr("Export annotations as COCO"),
            folder + QStringLiteral("/%1_coco.json").arg(spec.completeBaseName()),
            QObject::tr("COCO JSON (*.json)"));
        if (!path.isEmpty())
            exportAnnotationsAsCoco(w, path);
    });
    coco->setObjectName(QStringLiteral("file.export_coco"));
    file->addSeparator();
    addMenuItem(
        file, QObject::tr("Save view as PNG…"), QKeySequence(Qt::CTRL | Qt::Key_E), parent, [=] {
            const QString name =
                QStringLiteral("%1_%2.png")
                    .arg(QFileInfo(session->stream().streamSpec()).completeBaseName())
                    .arg(session->stream().currentIndex(), 6, 10, QLatin1Char('0'));
            const QString path = Dialogs::current().saveFile(
                parent, QObject::tr("Save view as PNG"), name, QObject::tr("PNG images (*.png)"));
            if (!path.isEmpty())
                files->saveSnapshot(path);
        });
    addMenuItem(file, QObject::tr("Copy view"), QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_C),
                files, &SessionFiles::copySnapshot);
    file->addSeparator();
    addMenuItem(file, QObject::tr("Quit"), QKeySequence::Quit, parent, &QWidget::close);
}

} // namespace fieldsight::ui
