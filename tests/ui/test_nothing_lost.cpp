// Issue 32, "Nothing lost, nothing overwritten", in the real window, offscreen: a save never drops
// what another window or a command wrote to the file since the window read it (annotations, the
// LUT, the bookmarks and samples written at every change); it asks (reload, Save As, overwrite,
// cancel) through the dialogs seam. Opening a stream is the bottom of its parameters' history.
// Ctrl+Z in a parameter box reaches Edit > Undo, and Ctrl+Z walks back into the document edited
// before when the active one has no step left. Each checks the bytes on disk or the document.
#include "support/test_suite.h"
#include "support/scripted_dialogs.h"
#include "support/test_files.h"
#include "support/window_waits.h"
#include "ui/actions/annotations_file.h"
#include "ui/document/bookmarks_document.h"
#include "ui/document/samples_document.h"
#include "ui/panels/pipeline_panel.h"
#include "ui/widgets/message_bar.h"
#include "visioncore/basics/file_fingerprint.h"
#include "visioncore/services/lut_building.h"

#include <QAbstractSpinBox>
#include <QLabel>
#include <QPushButton>
#include <QLineEdit>
#include <QSettings>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QtTest>

using namespace fieldsight;
using namespace fieldsight::test;
using fieldsight::ui::AnnotationsDocument;
using fieldsight::ui::MainWindow;

namespace {

bool writeAll(const QString& path, const QByteArray& bytes)
{
    QFile f(path);
    return f.open(QIODevice::WriteOnly | QIODevice::Truncate) && f.write(bytes) == bytes.size();
}

/// A frame marked done (an edit of its own, as a user's "D" makes).
FrameAnnotation doneFrame()
{
    FrameAnnotation f;
    f.done = true;
    return f;
}

QAction* action(MainWindow& w, const char* name)
{
    return w.findChild<QAction*>(QString::fromLatin1(name));
}

} // namespace

class TestNothingLost : public QObject
{
    Q_OBJECT

    QTemporaryDir m_dir;

    /// A copy of the first frames of the sample stream with its table, without annotations.
    QString copyStream(const QString& name, int frames = 4)
    {
        return copySampleFrames(m_dir.filePath(name), frames);
    }

    static bool showOn(MainWindow& w, const QString& stream)
    {
        w.show();
        return QTest::qWaitForWindowActive(&w) && openAndWait(w, stream);
    }

    static std::string frameName(MainWindow& w, std::size_t frame)
    {
        return w.session().stream().frameName(frame).toStdString();
    }

private slots:
    void initTestCase() { QCOMPARE(test::startWindowSuite("test_nothing_lost", m_dir), QString()); }

    void init() { test::forgetEarlierTests(); }

    void aFingerprintSeesOtherBytesNotATouch()
    {
        const QString path = m_dir.filePath("print.txt");
        const std::string local = path.toStdString();
        const FileFingerprint absent = fingerprintFile(local);
        QVERIFY(!absent.exists);
        QVERIFY(writeAll(path, "one"));
        QVERIFY(fileChangedSince(local, absent)); // absent then, there now
        const FileFingerprint one = fingerprintFile(local);
        QVERIFY(!fileChangedSince(local, one));
        QVERIFY(writeAll(path, "two")); // the same size, other bytes
        QVERIFY(fileChangedSince(local, one));
        const FileFingerprint two = fingerprintFile(local);
        QVERIFY(writeAll(path, "two")); // written again, the same bytes
        QVERIFY(!fileChangedSince(local, two));
        QVERIFY(QFile::remove(path));
        QVERIFY(fileChangedSince(local, two));
    }

    /// Two windows on one stream: A saves, then B (opened before A's save) saves. B asks; each
    /// answer keeps A's edit unless the user chose to overwrite it.
    void aSaveAsksBeforeDroppingAnotherWindowsAnnotations()
    {
        ScriptedDialogs dialogs;
        const QString stream = copyStream("two_windows");
        const QString file = stream + "/annotations.json";
        MainWindow a;
        MainWindow b;
        QVERIFY(showOn(a, stream));
        QVERIFY(showOn(b, stream));
        QVERIFY(a.session().annotations().editFrame(frameName(a, 0), doneFrame(), "A"));
        QVERIFY(a.annotationFiles().save());
        QVERIFY(dialogs.asked.isEmpty()); // nothing changed under A
        const QByteArray a_saved = fileBytes(file);
        QVERIFY(!a_saved.isEmpty());

        AnnotationsDocument& doc = b.session().annotations();
        QVERIFY(doc.editFrame(frameName(b, 1), doneFrame(), "B"));
        QVERIFY(doc.changedOnDisk());
        // Cancel: nothing written, B's edit kept and still unsaved.
        dialogs.choices.push_back(-1);
        QVERIFY(!b.annotationFiles().save());
        QCOMPARE(dialogs.asked.last(), QStringLiteral("Changed on disk"));
        QCOMPARE(fileBytes(file), a_saved);
        QVERIFY(doc.modified());
        // The document refuses it too, whoever asks.
        QVERIFY(!doc.save().ok());
        QCOMPARE(fileBytes(file), a_saved);

        // Save As: both kept.
        const QString other = stream + "/annotations_b.json";
        dialogs.choices.push_back(1);
        dialogs.paths.push_back(other);
        QVERIFY(b.annotationFiles().save());
        QCOMPARE(fileBytes(file), a_saved);
        QVERIFY(fileBytes(other).contains(QByteArray::fromStdString(frameName(b, 1))));
        QVERIFY(!doc.modified());
        QVERIFY(dialogs.unanswered.isEmpty());
    }

    /// A command writes the annotations while the window is open; Ctrl+Alt+S asks, and Reload
    /// takes the file's as one undo step that gives the window's edits back.
    void ctrlAltSAsksWhenACommandWroteTheAnnotations()
    {
        ScriptedDialogs dialogs;
        const QString stream = copyStream("command_wrote");
        const QString file = stream + "/annotations.json";
        MainWindow w;
        QVERIFY(showOn(w, stream));
        AnnotationsDocument& doc = w.session().annotations();
        QVERIFY(doc.editFrame(frameName(w, 0), doneFrame(), "Mine"));
        // Absent when the stream opened; a command writes three frames.
        Annotations theirs;
        for (std::size_t i = 1; i < 4; ++i)
            theirs.frames[frameName(w, i)] = doneFrame();
        QVERIFY(theirs.save(file.toStdString(), doc.kinds()).ok());
        const QByteArray written = fileBytes(file);

        dialogs.choices.push_back(0); // Reload
        QTest::keyClick(&w, Qt::Key_S, Qt::ControlModifier | Qt::AltModifier);
        QCOMPARE(dialogs.asked.value(0), QStringLiteral("Changed on disk"));
        QCOMPARE(fileBytes(file), written);
        QCOMPARE(doc.annotations().frames.size(), std::size_t(3));
        QVERIFY(!doc.frame(frameName(w, 0)));
        QVERIFY(!doc.modified());
        // Undo brings the window's edit back (unsaved), the file's frames gone again.
        QTest::keySequence(&w, QKeySequence::Undo);
        QVERIFY(doc.frame(frameName(w, 0)));
        QCOMPARE(doc.annotations().frames.size(), std::size_t(1));
        QVERIFY(doc.modified());

        // Overwrite: the window's replace the file's, and the next save asks nothing.
        dialogs.choices.push_back(2);
        QTest::keyClick(&w, Qt::Key_S, Qt::ControlModifier | Qt::AltModifier);
        auto saved = Annotations::load(file.toStdString(), doc.kinds());
        QVERIFY(saved.ok());
        QCOMPARE(saved.value().frames.size(), std::size_t(1));
        QVERIFY(!doc.modified());
        const int asked = int(dialogs.asked.size());
        QVERIFY(doc.editFrame(frameName(w, 2), doneFrame(), "Mine again"));
        QTest::keyClick(&w, Qt::Key_S, Qt::ControlModifier | Qt::AltModifier);
        QCOMPARE(int(dialogs.asked.size()), asked);
        QVERIFY(!doc.modified());
    }

    /// A command writes the annotations and the table while the stream is being opened (after
    /// the background open read them): the window still sees them as changed on disk.
    void aWriteDuringTheOpenIsAChangeOnDisk()
    {
        const QString stream = copyStream("written_while_opening");
        MainWindow w;
        w.show();
        QVERIFY(QTest::qWaitForWindowActive(&w));
        const Pipeline* pipeline = &w.session().pipeline();
        w.session().setSourceOpener([pipeline, stream](const QString& spec, const QString& lut) {
            auto opened = ui::StreamDocument::openSource(spec, lut, *pipeline);
            Annotations theirs;
            theirs.frames["frame_000001.png"] = doneFrame();
            (void)theirs.save((stream + "/annotations.json").toStdString(),
                              pipeline->perceptKinds());
            ColourLut table = ColourLut::load((stream + "/default.lut").toStdString()).value();
            table.setCell(11, Colour(4));
            (void)table.save((stream + "/default.lut").toStdString());
            return opened;
        });
        QVERIFY(openAndWait(w, stream));
        QVERIFY(w.session().annotations().annotations().frames.empty()); // read before the write
        QVERIFY(w.session().annotations().changedOnDisk());
        QVERIFY(w.session().lut().changedOnDisk());
    }

    /// The LUT written by someone else: Ctrl+S asks; closing the window asks too.
    void ctrlSAndClosingAskWhenTheLutChangedOnDisk()
    {
        ScriptedDialogs dialogs;
        const QString stream = copyStream("lut_changed");
        const QString file = stream + "/default.lut";
        auto w = std::make_unique<MainWindow>();
        QVERIFY(showOn(*w, stream));
        ui::LutDocument& lut = w->session().lut();
        QCOMPARE(QFileInfo(lut.path()).canonicalFilePath(), QFileInfo(file).canonicalFilePath());
        const QByteArray opened = test::tableBytes(w->session().lut().table());
        QVERIFY(lut.edit("Mine", {{0, lut.table().cell(0), Colour(3)}}));
        // Another window saves a table with one other cell changed.
        ColourLut theirs = ColourLut::load(file.toStdString()).value();
        theirs.setCell(7, Colour(5));
        QVERIFY(theirs.save(file.toStdString()).ok());
        const QByteArray written = fileBytes(file);

        dialogs.choices.push_back(0); // Reload
        QTest::keyClick(w.get(), Qt::Key_S, Qt::ControlModifier);
        QCOMPARE(dialogs.asked.value(0), QStringLiteral("Changed on disk"));
        QCOMPARE(fileBytes(file), written);
        QCOMPARE(test::tableBytes(w->session().lut().table()), written);
        QVERIFY(!lut.modified());
        lut.undoStack().undo();
        QVERIFY(test::tableBytes(w->session().lut().table()) != written);
        QCOMPARE(int(lut.table().data()[0]), 3);
        QCOMPARE(int(lut.table().data()[7]), int(std::uint8_t(opened[7])));

        // Written again by someone else; the window closes: Save, then Cancel at the question.
        theirs.setCell(9, Colour(6));
        QVERIFY(theirs.save(file.toStdString()).ok());
        const QByteArray again = fileBytes(file);
        dialogs.answers.push_back(QMessageBox::Save);
        dialogs.choices.push_back(-1);
        QVERIFY(!w->close());
        QCOMPARE(fileBytes(file), again);
        QVERIFY(lut.modified());
        QVERIFY(dialogs.unanswered.isEmpty());
    }

    /// The bookmarks and samples are written at every change: not over a file someone else
    /// changed since; overwrite() or reload() settle it.
    void bookmarksAndSamplesAreNotWrittenOverAnotherWritersFile()
    {
        const QString stream = copyStream("sidecars");
        MainWindow w;
        QVERIFY(showOn(w, stream));
        ui::BookmarksDocument& marks = w.session().bookmarks();
        marks.setBookmark(0, w.session().stream().frameName(0), "mine");
        const QString marks_file = marks.path();
        QVERIFY(QFileInfo::exists(marks_file));
        // Another window writes its own marks.
        ui::Bookmarks theirs;
        theirs.set({2, frameName(w, 2), "theirs"});
        QVERIFY(theirs.save(marks_file.toStdString()).ok());
        const QByteArray written = fileBytes(marks_file);
        QSignalSpy problem(&marks, &ui::BookmarksDocument::problem);
        marks.setBookmark(1, w.session().stream().frameName(1), "mine too");
        QCOMPARE(fileBytes(marks_file), written);
        QCOMPARE(problem.size(), 1);
        QVERIFY(marks.marks().find(1)); // kept in memory
        QVERIFY(marks.reload().ok());
        QVERIFY(marks.marks().find(2));
        QVERIFY(!marks.marks().find(1));

        ui::SamplesDocument& samples = w.session().samples();
        samples.addRect(w.session().stream().frameName(0), Colour(3), QRect(1, 1, 4, 4));
        const QString samples_file = samples.path();
        QVERIFY(QFileInfo::exists(samples_file));
        QVERIFY(writeAll(samples_file, R"({"format": "fieldsight-lut-samples/1", "samples": []})"));
        const QByteArray empty = fileBytes(samples_file);
        samples.addRect(w.session().stream().frameName(1), Colour(3), QRect(1, 1, 4, 4));
        QCOMPARE(fileBytes(samples_file), empty);
        QCOMPARE(samples.samples().samples.size(), std::size_t(2));
        samples.overwrite();
        QCOMPARE(loadLutSamples(samples_file.toStdString()).value().samples.size(), std::size_t(2));
    }

    /// Another window writes the bookmarks while this one is open: the bar offers to reload
    /// them (seen from the file system's notice, without a save); Reload takes theirs.
    void aBarOffersToReloadAFileChangedOnDisk()
    {
        const QString stream = copyStream("watched");
        MainWindow w;
        QVERIFY(showOn(w, stream));
        ui::BookmarksDocument& marks = w.session().bookmarks();
        marks.setBookmark(0, w.session().stream().frameName(0), "mine");
        QVERIFY(!w.diskBar().isVisible());
        ui::Bookmarks theirs;
        theirs.set({3, frameName(w, 3), "theirs"});
        QVERIFY(theirs.save(marks.path().toStdString()).ok());
        QTRY_VERIFY(w.diskBar().isVisible());
        QVERIFY2(w.diskBar().question().contains("bookmarks"), qPrintable(w.diskBar().question()));
        auto* reload = w.diskBar().findChild<QPushButton*>("accept");
        QVERIFY(reload);
        reload->click();
        QVERIFY(marks.marks().find(3));
        QVERIFY(!marks.marks().find(0));
        QVERIFY(!w.diskBar().isVisible());
    }

    /// A message, an offer or the scores' line appearing never moves the frame view.
    void barsNeverMoveTheFrameView()
    {
        MainWindow w;
        QVERIFY(showOn(w, copyStream("still")));
        const auto where = [&w] {
            return QRect(w.view().mapTo(&w, QPoint(0, 0)), w.view().size());
        };
        const QRect before = where();
        w.showMessage("Saved something somewhere", false);
        QVERIFY(w.messageBar().isVisible());
        QCoreApplication::sendPostedEvents();
        QCOMPARE(where(), before);
        w.diskBar().offer("A long question that wraps over more than one line of the bar, said "
                          "twice: a long question that wraps over more than one line of the bar");
        QCoreApplication::sendPostedEvents();
        QCOMPARE(where(), before);
        // The bars are over the view's top, not under it.
        QVERIFY(w.messageBar().isVisible());
        QCOMPARE(w.messageBar().mapTo(&w, QPoint(0, 0)), before.topLeft());
        auto* scores = w.findChild<QLabel*>("scores_change");
        QVERIFY(scores);
        scores->setText("Scores after the last change: ball recall 1.00 → 0.41");
        scores->show();
        QCoreApplication::sendPostedEvents();
        QCOMPARE(where(), before);
        w.messageBar().hide();
        w.diskBar().hide();
        QCoreApplication::sendPostedEvents();
        QCOMPARE(where(), before);
    }

    /// A stream's own parameters are the bottom of its history: two undos after a change come
    /// back to them, never to the defaults.
    void undoStopsAtTheParametersAStreamOpenedWith()
    {
        const QString stream = copyStream("own_params");
        const QString other = copyStream("defaults");
        MainWindow w;
        QVERIFY(showOn(w, stream));
        ui::PipelineSettings& settings = w.session().settings();
        const ParamInfo* spacing = nullptr;
        std::string stage;
        for (const StageDescriptor& s : settings.pipeline().descriptors())
            for (const ParamInfo& p : s.params)
                if (p.name == "scan_spacing") {
                    spacing = &p;
                    stage = s.info.id;
                }
        QVERIFY(spacing);
        const double own = spacing->default_value + 2;
        QVERIFY(settings.setParam(stage, "scan_spacing", own).ok());
        action(w, "pipeline.save_params_to_stream")->trigger();
        QVERIFY(openAndWait(w, other));
        QVERIFY(openAndWait(w, stream));
        QCOMPARE(settings.paramValue(stage, "scan_spacing"), own);
        QVERIFY(!settings.undoStack().canUndo()); // opening is no step

        QVERIFY(settings.setParam(stage, "scan_spacing", own + 1).ok());
        QTest::keySequence(&w, QKeySequence::Undo);
        QCOMPARE(settings.paramValue(stage, "scan_spacing"), own);
        QTest::keySequence(&w, QKeySequence::Undo);
        QCOMPARE(settings.paramValue(stage, "scan_spacing"), own);
    }

    /// The stream's params.json written by another writer since it opened: Save parameters to
    /// the stream asks; Cancel keeps their file, Reload takes it (one undo step), and what the
    /// file holds beyond the parameters survives a save.
    void savingParametersToTheStreamAsksWhenTheFileChanged()
    {
        const QString stream = copyStream("params_changed");
        MainWindow w;
        QVERIFY(showOn(w, stream));
        ui::PipelineSettings& settings = w.session().settings();
        QVERIFY(settings.setParam("ball", "min_radius", 4).ok());
        action(w, "pipeline.save_params_to_stream")->trigger(); // names params.json
        const QString file = stream + "/params.json";
        const QByteArray theirs = R"({"format": "fieldsight-params/1", "note": "venue B",
            "stages": {"ball": {"min_radius": 6}}})";
        QVERIFY(writeAll(file, theirs));
        QVERIFY(settings.setParam("ball", "min_radius", 5).ok());
        ScriptedDialogs dialogs;
        dialogs.choices = {-1, 0}; // Cancel, then Reload
        action(w, "pipeline.save_params_to_stream")->trigger();
        QCOMPARE(fileBytes(file), theirs);
        action(w, "pipeline.save_params_to_stream")->trigger();
        QCOMPARE(settings.paramValue("ball", "min_radius"), 6.0);
        QTest::keySequence(&w, QKeySequence::Undo);
        QCOMPARE(settings.paramValue("ball", "min_radius"), 5.0);
        action(w, "pipeline.save_params_to_stream")->trigger(); // unchanged since the reload
        QVERIFY(dialogs.unanswered.isEmpty());
        QVERIFY2(fileBytes(file).contains("\"note\": \"venue B\""), fileBytes(file).constData());
        QCOMPARE(ParamSet::load(file.toStdString()).value().values, settings.paramChanges().values);
    }

    /// Typing a value and Return in a parameter box, then Ctrl+Z: Edit > Undo takes it back,
    /// Ctrl+Shift+Z and Ctrl+Y bring it again.
    void undoKeysInAParameterBoxReachEditUndo()
    {
        MainWindow w;
        QVERIFY(showOn(w, copyStream("keys")));
        ui::PipelineSettings& settings = w.session().settings();
        QAbstractSpinBox* box = nullptr;
        for (auto* b : w.pipelinePanel().findChildren<QAbstractSpinBox*>())
            if (b->objectName().endsWith(".scan_spacing"))
                box = b;
        QVERIFY(box);
        const std::string stage = box->objectName().section('.', 0, 0).toStdString();
        const double before = settings.paramValue(stage, "scan_spacing");
        w.activateWindow();
        box->setFocus();
        QTRY_VERIFY(box->hasFocus());
        box->selectAll();
        QTest::keyClicks(box, QString::number(int(before) + 3));
        QTest::keyClick(box, Qt::Key_Return);
        QCOMPARE(settings.paramValue(stage, "scan_spacing"), before + 3);
        QVERIFY(box->hasFocus());

        QTest::keyClick(box, Qt::Key_Z, Qt::ControlModifier);
        QCOMPARE(settings.paramValue(stage, "scan_spacing"), before);
        QCOMPARE(box->text().section(' ', 0, 0), QString::number(int(before)));
        QTest::keyClick(box, Qt::Key_Z, Qt::ControlModifier | Qt::ShiftModifier);
        QCOMPARE(settings.paramValue(stage, "scan_spacing"), before + 3);
        QTest::keyClick(box, Qt::Key_Z, Qt::ControlModifier);
        QTest::keyClick(box, Qt::Key_Y, Qt::ControlModifier);
        QCOMPARE(settings.paramValue(stage, "scan_spacing"), before + 3);
    }

    /// After an annotation step is undone, Ctrl+Z goes on into the table edited before it, and
    /// Edit > Undo says so.
    void ctrlZWalksBackIntoTheDocumentEditedBefore()
    {
        MainWindow w;
        QVERIFY(showOn(w, copyStream("walk")));
        const QByteArray opened = test::tableBytes(w.session().lut().table());
        ui::LutDocument& lut = w.session().lut();
        QVERIFY(lut.edit("Classify a cell", {{0, lut.table().cell(0), Colour(3)}}));
        AnnotationsDocument& doc = w.session().annotations();
        QVERIFY(doc.editFrame(frameName(w, 0), doneFrame(), "Done"));
        QAction* undo = action(w, "edit.undo");
        QTest::keySequence(&w, QKeySequence::Undo);
        QVERIFY(!doc.frame(frameName(w, 0)));
        QVERIFY(undo->isEnabled());
        QVERIFY2(undo->text().contains("Classify a cell") && undo->text().contains("Colour table"),
                 qPrintable(undo->text()));
        QTest::keySequence(&w, QKeySequence::Undo);
        QCOMPARE(test::tableBytes(w.session().lut().table()), opened);
        QVERIFY(!undo->isEnabled());
    }
};

FIELDSIGHT_TEST_SUITE(TestNothingLost, Widgets)

#include "test_nothing_lost.moc"
