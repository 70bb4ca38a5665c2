// The editing session in the real window, offscreen: one edit of each document kind (the colour
// table, the LUT samples, a parameter, a stage switch, a bookmark) made as a user makes it, then
// undone and redone through Edit > Undo and Redo, checking the document's bytes each time; the
// history dock follows the document edited last; a tool added by this test alone (FakeTool, one
// registration line) gets its button, menu item and shortcut and receives the view's mouse events;
// every question goes through the dialogs seam; a stream's own parameters are saved to it and
// applied when it opens.
#include "support/test_suite.h"
#include "support/test_files.h"
#include "support/fake_stage.h"
#include "support/fake_tool.h"
#include "support/scripted_dialogs.h"
#include "support/synthetic_frames.h"
#include "support/window_waits.h"
#include "ui/panels/lut_panel.h"
#include "ui/panels/pipeline_panel.h"
#include "ui/stream_navigator/stream_navigator.h"
#include "ui/widgets/message_bar.h"
#include "visioncore/services/lut_building.h"

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QGroupBox>
#include <QMenuBar>
#include <QSettings>
#include <QStandardPaths>
#include <QStatusBar>
#include <QTemporaryDir>
#include <QToolButton>
#include <QtTest>

using namespace fieldsight;
using namespace fieldsight::test;
using fieldsight::ui::MainWindow;

namespace {

/// Every detection of a frame with its fields, one per line.
QString detections(const ui::FrameOutput& out)
{
    QStringList lines;
    for (const ui::PerceptItem& item : out.items)
        lines << item.details;
    return lines.join('\n');
}

QAction* menuAction(MainWindow& w, const char* name)
{
    return w.findChild<QAction*>(QString::fromLatin1(name));
}

/// The widget point of image pixel `p` (the view at zoom 1, image at its top-left corner).
QPoint pointAt(QPoint p)
{
    return p;
}

} // namespace

class TestSession : public QObject
{
    Q_OBJECT

    Pipeline m_pipeline = withFakeStage();
    QTemporaryDir m_dir;

    /// A copy of the sample stream's frames and table.
    QString copyStream(const QString& name)
    {
        return test::copyFolderFiles(sampleStream(), m_dir.filePath(name), test::isFrameOrTable);
    }

    /// Edit > Undo then Edit > Redo: `bytes` reads the document, `before` and `after` are what
    /// it must hold after the undo and after the redo.
    template <class Bytes>
    bool undoRedo(MainWindow& w, Bytes bytes, const QByteArray& before, const QByteArray& after)
    {
        QAction* undo = menuAction(w, "edit.undo");
        QAction* redo = menuAction(w, "edit.redo");
        if (!undo || !redo || !undo->isEnabled())
            return false;
        undo->trigger();
        if (bytes() != before)
            return false;
        if (!redo->isEnabled())
            return false;
        redo->trigger();
        return bytes() == after;
    }

    /// Edits the table of `stream` in a window that then ends without closing (a crash), so
    /// only the recovery file keeps them; returns the edited table.
    ColourLut editAndCrash(const QString& stream)
    {
        MainWindow w(m_pipeline);
        w.show();
        if (!openAndWait(w, stream))
            return {};
        w.session().lut().setAutosaveDelay(50);
        w.tools().activate(QStringLiteral("click"));
        w.view().setZoom(1);
        w.view().setImageOrigin({0, 0});
        QTest::mouseClick(&w.view(), Qt::LeftButton, {}, pointAt(QPoint(60, 200)));
        if (!QTest::qWaitFor([&] { return w.session().lut().findRecovery().has_value(); }, 5000))
            return {};
        return w.session().lut().table();
    }

private slots:
    void initTestCase()
    {
        QCOMPARE(test::startWindowSuite("test_session", m_dir), QString());
        QSettings().clear();
    }

    void init()
    {
        QSettings().clear();
        // No recovery file of an earlier case is offered to this one.
        const QDir app(QStandardPaths::writableLocation(QStandardPaths::AppDataLocation));
        for (const char* name : {"lut-recovery.lut", "lut-recovery.json"})
            QFile::remove(app.filePath(QString::fromLatin1(name)));
    }

    void everyDocumentsEditUndoesAndRedoesThroughTheEditMenu()
    {
        const QString stream = copyStream("undo_all");
        ScriptedDialogs dialogs;
        MainWindow w(m_pipeline);
        w.show();
        QVERIFY(QTest::qWaitForWindowActive(&w));
        QVERIFY(openAndWait(w, stream));
        w.view().setZoom(1);
        w.view().setImageOrigin({0, 0});

        // The colour table: a click with the Click tool.
        QTest::keyClick(&w, Qt::Key_C);
        QCOMPARE(w.tools().active().info().id, QStringLiteral("click"));
        const QByteArray lut_before = test::tableBytes(w.session().lut().table());
        const QImage classified_before = w.session().stream().current()->classified;
        QTest::mouseClick(&w.view(), Qt::LeftButton, {}, pointAt(QPoint(60, 200)));
        QVERIFY(waitForFrame(w, 0));
        const QImage classified_after = w.session().stream().current()->classified;
        QVERIFY(classified_after != classified_before);
        const QByteArray lut_after = test::tableBytes(w.session().lut().table());
        QVERIFY(lut_after != lut_before);
        QVERIFY(undoRedo(
            w, [&] { return test::tableBytes(w.session().lut().table()); }, lut_before, lut_after));
        // The frame follows the table both ways (the worker observes the document).
        menuAction(w, "edit.undo")->trigger();
        QVERIFY(waitForFrame(w, 0));
        QCOMPARE(w.session().stream().current()->classified, classified_before);
        menuAction(w, "edit.redo")->trigger();
        QVERIFY(waitForFrame(w, 0));
        QCOMPARE(w.session().stream().current()->classified, classified_after);

        // The samples: a rectangle dragged with the Sample tool (saved beside the stream).
        QTest::keyClick(&w, Qt::Key_S);
        const QString samples_file = stream + "/lut_samples.json";
        // The document's bytes, and the file beside the stream holds them after every step.
        const auto samples = [&] {
            const QByteArray bytes =
                QByteArray::fromStdString(lutSamplesToJson(w.session().samples().samples()));
            return fileBytes(samples_file) == bytes ? bytes : QByteArray("file differs");
        };
        const QByteArray samples_before =
            QByteArray::fromStdString(lutSamplesToJson(w.session().samples().samples()));
        QTest::mousePress(&w.view(), Qt::LeftButton, {}, pointAt(QPoint(100, 200)));
        QTest::mouseMove(&w.view(), pointAt(QPoint(130, 220)));
        QTest::mouseRelease(&w.view(), Qt::LeftButton, {}, pointAt(QPoint(130, 220)));
        const QByteArray samples_after = samples();
        QVERIFY(samples_after != samples_before);
        QVERIFY(undoRedo(w, samples, samples_before, samples_after));

        // A parameter: the fake stage's level in the pipeline panel.
        const auto params = [&] {
            return QByteArray::fromStdString(w.session().settings().paramChanges().toJson());
        };
        const QByteArray params_before = params();
        auto* level = qobject_cast<QDoubleSpinBox*>(w.pipelinePanel().editor("fake.level"));
        QVERIFY(level);
        level->setValue(level->value() + 1.5);
        const QByteArray params_after = params();
        QVERIFY(params_after != params_before);
        QVERIFY(undoRedo(w, params, params_before, params_after));
        QCOMPARE(level->value(), w.session().settings().paramValue("fake", "level"));

        // A stage switch: the fake stage's box.
        const auto switches = [&] {
            QByteArray b;
            for (const std::string& id : w.session().settings().skippedStages())
                b += QByteArray::fromStdString(id) + ';';
            return b;
        };
        const QByteArray skip_before = switches();
        w.pipelinePanel().stageBox("fake")->setChecked(false);
        const QByteArray skip_after = switches();
        QCOMPARE(skip_after, QByteArray("fake;"));
        QVERIFY(undoRedo(w, switches, skip_before, skip_after));
        QVERIFY(!w.pipelinePanel().stageBox("fake")->isChecked());

        // A bookmark: Navigate > Bookmark this frame, its note answered through the seam.
        const QString marks_file = stream + "/bookmarks.json";
        const auto marks = [&] {
            const QByteArray bytes =
                QByteArray::fromStdString(w.session().bookmarks().marks().toJson());
            return fileBytes(marks_file) == bytes ? bytes : QByteArray("file differs");
        };
        const QByteArray marks_before =
            QByteArray::fromStdString(w.session().bookmarks().marks().toJson());
        dialogs.texts.push_back(QStringLiteral("ball lost"));
        QTest::keyClick(&w, Qt::Key_B, Qt::ControlModifier);
        QVERIFY(dialogs.unanswered.isEmpty());
        const QByteArray marks_after = marks();
        QVERIFY(marks_after.contains("ball lost"));
        QVERIFY(undoRedo(w, marks, marks_before, marks_after));

        // The annotations: Annotate > Frame done.
        const auto truth = [&] {
            const ui::AnnotationsDocument& doc = w.session().annotations();
            return QByteArray::fromStdString(doc.annotations().toJson(doc.kinds()));
        };
        const QByteArray truth_before = truth();
        QAction* done = menuAction(w, "annotate.done");
        QVERIFY(done && done->isEnabled());
        done->trigger();
        const QByteArray truth_after = truth();
        QVERIFY(truth_after != truth_before);
        QVERIFY(undoRedo(w, truth, truth_before, truth_after));

        // The orientation: View > Orientation > Turn 180°; the frame follows both ways.
        const auto turned = [&] {
            return QByteArray::number(degrees(w.session().stream().info().orientation));
        };
        const QByteArray turned_before = turned();
        QAction* half = menuAction(w, "view.orientation.180");
        QVERIFY(half && half->isEnabled());
        half->trigger();
        QVERIFY(waitForFrame(w, 0));
        const QImage upside_down = w.session().stream().current()->raw;
        const QByteArray turned_after = turned();
        QCOMPARE(turned_after, QByteArray("180"));
        QVERIFY(undoRedo(w, turned, turned_before, turned_after));
        QVERIFY(waitForFrame(w, 0));
        QCOMPARE(w.session().stream().current()->raw, upside_down);
        menuAction(w, "edit.undo")->trigger();
        QVERIFY(waitForFrame(w, 0));
        QCOMPARE(w.session().stream().current()->raw, upside_down.mirrored(true, true));
    }

    void undoFollowsTheDocumentEditedLast()
    {
        ScriptedDialogs dialogs;
        MainWindow w(m_pipeline);
        w.show();
        QVERIFY(openAndWait(w, copyStream("follow")));
        auto* documents = w.findChild<QComboBox*>("history.document");
        QVERIFY(documents);
        w.tools().activate(QStringLiteral("click"));
        w.view().setZoom(1);
        w.view().setImageOrigin({0, 0});
        QTest::mouseClick(&w.view(), Qt::LeftButton, {}, pointAt(QPoint(60, 200)));
        QCOMPARE(w.session().undoGroup().activeStack(), &w.session().lut().undoStack());
        QCOMPARE(documents->currentText(), QStringLiteral("Colour table"));
        QVERIFY(w.session().settings().setParam("fake", "level", 4).ok());
        QCOMPARE(w.session().undoGroup().activeStack(), &w.session().settings().undoStack());
        QCOMPARE(documents->currentText(), QStringLiteral("Pipeline settings"));
        // Undo now takes back the parameter, not the click; choosing the table in the dock
        // makes Undo take back the click.
        const QByteArray edited = test::tableBytes(w.session().lut().table());
        menuAction(w, "edit.undo")->trigger();
        QCOMPARE(w.session().settings().paramValue("fake", "level"),
                 m_pipeline.find("fake")->params.front().default_value);
        QCOMPARE(test::tableBytes(w.session().lut().table()), edited);
        documents->setCurrentIndex(0);
        emit documents->activated(0);
        menuAction(w, "edit.undo")->trigger();
        QVERIFY(test::tableBytes(w.session().lut().table()) != edited);
        QVERIFY(!w.session().lut().modified());
    }

    void aToolAddedByOneLineGetsItsButtonMenuItemAndEvents()
    {
        ScriptedDialogs dialogs; // a question nobody expects fails the test instead of hanging
        std::vector<ui::ToolFactory> tools = ui::standardTools();
        tools.push_back(ui::toolFactory<FakeTool>()); // the line tool_list.cpp would get
        MainWindow w(m_pipeline, tools);
        w.show();
        QVERIFY(QTest::qWaitForWindowActive(&w));
        QVERIFY(openAndWait(w, copyStream("fake_tool")));
        // Its button in the LUT editor and its item in Edit > Tool, with its shortcut.
        QVERIFY(w.lutPanel().findChild<QToolButton*>("tool.fake"));
        bool in_menu = false;
        for (QMenu* menu : w.menuBar()->findChildren<QMenu*>())
            for (QAction* a : menu->actions())
                in_menu = in_menu || (a->objectName() == "tool.fake" && menu->title() == "Tool");
        QVERIFY(in_menu);
        QTest::keyClick(&w, Qt::Key_J);
        QCOMPARE(w.tools().active().info().id, QStringLiteral("fake"));

        // The view forwards the mouse; the tool's preview shows in the view and the status bar.
        w.view().setZoom(1);
        w.view().setImageOrigin({0, 0});
        FakeTool::presses = FakeTool::moves = FakeTool::releases = 0;
        // Sent to the view itself: QTest::mouseMove without a button moves the cursor and lets
        // the platform deliver the move later, mapped through whatever the layout is by then
        // (on a loaded machine once "Fake at 41,30").
        QMouseEvent hover(QEvent::MouseMove, QPointF(pointAt(QPoint(40, 30))),
                          QPointF(w.view().mapToGlobal(pointAt(QPoint(40, 30)))), Qt::NoButton,
                          Qt::NoButton, Qt::NoModifier);
        QCoreApplication::sendEvent(&w.view(), &hover);
        QCOMPARE(w.tools().preview().text, QStringLiteral("Fake at 40,30"));
        QCOMPARE(w.statusBar()->currentMessage(), QStringLiteral("Fake at 40,30"));
        const QImage& lit = w.view().highlight(QStringLiteral("preview"));
        QVERIFY(!lit.isNull());
        QVERIFY(qAlpha(lit.pixel(40, 30)) > 0);
        QCOMPARE(qAlpha(lit.pixel(44, 30)), 0);
        QTest::mousePress(&w.view(), Qt::LeftButton, {}, pointAt(QPoint(40, 30)));
        QTest::mouseMove(&w.view(), pointAt(QPoint(45, 32)));
        QTest::mouseRelease(&w.view(), Qt::LeftButton, {}, pointAt(QPoint(45, 32)));
        QCOMPARE(FakeTool::presses, 1);
        QVERIFY(FakeTool::moves >= 1);
        QCOMPARE(FakeTool::releases, 1);
        // Its edit is a command: in the bookmarks, undone by Edit > Undo.
        const ui::Bookmark* mark = w.session().bookmarks().marks().find(0);
        QVERIFY(mark);
        QCOMPARE(QString::fromStdString(mark->note), QStringLiteral("fake at 40,30"));
        menuAction(w, "edit.undo")->trigger();
        QVERIFY(!w.session().bookmarks().marks().find(0));

        // The pan tool does not reach it.
        w.tools().activate(QStringLiteral("pan"));
        QTest::mouseClick(&w.view(), Qt::LeftButton, {}, pointAt(QPoint(40, 30)));
        QCOMPARE(FakeTool::presses, 1);
    }

    void aStepToTheFramePreparedAheadIsAnsweredAtOnce()
    {
        ScriptedDialogs dialogs;
        MainWindow w(m_pipeline);
        w.show();
        QVERIFY(QTest::qWaitForWindowActive(&w));
        QVERIFY(openAndWait(w, copyStream("ahead")));
        // While frame 0 is shown the worker runs frame 1 with the same table and settings.
        QTRY_COMPARE(w.session().stream().preparedAhead(), std::optional<std::size_t>(1));
        w.navigator().step(1);
        // Answered on this thread, before any event is processed: nothing waits for the worker.
        QVERIFY(!w.session().stream().waiting());
        const auto ahead = w.session().stream().current();
        QCOMPARE(ahead->index, std::size_t(1));
        QCOMPARE(QString::fromStdString(ahead->frame.name), w.session().stream().frameName(1));
        // The same answer the worker gives when asked directly.
        const QString prepared = detections(*ahead);
        QVERIFY(!prepared.isEmpty());
        QTRY_COMPARE(w.session().stream().preparedAhead(), std::optional<std::size_t>(2));
        QVERIFY(w.session().settings().setParam("fake", "level", 2.5).ok()); // a miss
        QVERIFY(w.session().stream().waiting());
        QVERIFY(waitForFrame(w, 1));
        w.session().settings().undoStack().undo();
        QVERIFY(waitForFrame(w, 1));
        QCOMPARE(detections(*w.session().stream().current()), prepared);
        QCOMPARE(w.session().stream().current()->raw, ahead->raw);
        QVERIFY(dialogs.unanswered.isEmpty());

        // A run still going when the next step comes: the step waits for the worker and what
        // is shown at the end is the frame stepped to, not the older answer.
        QTRY_COMPARE(w.session().stream().preparedAhead(), std::optional<std::size_t>(2));
        w.session().stream().rerun();
        w.navigator().step(1);
        QVERIFY(waitForFrame(w, 2));
        // Once the worker has run ahead to frame 3 it owes no answer; deliver what it sent: an
        // older answer would show now.
        QTRY_COMPARE(w.session().stream().preparedAhead(), std::optional<std::size_t>(3));
        QCoreApplication::processEvents();
        QCOMPARE(w.session().stream().current()->index, std::size_t(2));
        QCOMPARE(QString::fromStdString(w.session().stream().current()->frame.name),
                 w.session().stream().frameName(2));

        // A table edit: the frame prepared with the old table is not used.
        QTRY_COMPARE(w.session().stream().preparedAhead(), std::optional<std::size_t>(3));
        w.tools().activate(QStringLiteral("click"));
        w.view().setZoom(1);
        w.view().setImageOrigin({0, 0});
        const ColourLut old_table = w.session().lut().table();
        QTest::mouseClick(&w.view(), Qt::LeftButton, {}, pointAt(QPoint(60, 200)));
        QVERIFY(waitForFrame(w, 2));
        w.navigator().step(1);
        QVERIFY(waitForFrame(w, 3));
        // Frame 3 as shown is classified with the edited table (whether the worker ran it on
        // the step or ahead of it once the edit was in), not with the table it was prepared with.
        const auto shown = w.session().stream().current();
        cv::Mat classes;
        const QImage with_new =
            ui::classifyFrame(shown->frame.ycbcr, w.session().lut().table(), classes);
        const QImage with_old = ui::classifyFrame(shown->frame.ycbcr, old_table, classes);
        QVERIFY(with_new != with_old); // the edit shows on frame 3
        QCOMPARE(shown->classified, with_new);
    }

    void recoveredEditsGoBackOnlyToTheStreamTheyCameFrom()
    {
        // The venue trial's case: edits of stream B, recovered while A is open.
        ScriptedDialogs dialogs;
        const QString a = copyStream("recover_a"), b = copyStream("recover_b");
        const ColourLut edited = editAndCrash(b);
        QVERIFY(!(edited == ColourLut()));
        const QByteArray a_table = fileBytes(a + "/default.lut");
        const QByteArray b_table = fileBytes(b + "/default.lut");
        MainWindow w(m_pipeline);
        w.show();
        QVERIFY(openAndWait(w, a));
        QVERIFY(w.recoveryBar().isVisible());
        QVERIFY2(w.recoveryBar().question().contains(b), qPrintable(w.recoveryBar().question()));
        QSignalSpy opened(&w.files(), &ui::SessionFiles::streamOpened);
        QVERIFY(w.files().recoverLut());
        QVERIFY(opened.wait(10000));
        QVERIFY(opened.front().front().toBool());
        // Recover opened B and put the edits on B's table, not on A's.
        QCOMPARE(QFileInfo(w.session().stream().streamSpec()).canonicalFilePath(),
                 QFileInfo(b).canonicalFilePath());
        QVERIFY(w.session().lut().table() == edited);
        QCOMPARE(QFileInfo(w.session().lut().path()).canonicalFilePath(),
                 QFileInfo(b + "/default.lut").canonicalFilePath());
        QCOMPARE(fileBytes(a + "/default.lut"), a_table);
        QCOMPARE(fileBytes(b + "/default.lut"), b_table);
        // Ctrl+S writes B's own table; A's is as it was.
        QVERIFY(w.files().saveLut());
        QVERIFY(fileBytes(b + "/default.lut") != b_table);
        QCOMPARE(fileBytes(a + "/default.lut"), a_table);
        QVERIFY(dialogs.unanswered.isEmpty());
    }

    void recoveredEditsOfAStreamThatIsGoneAreRefusedAndKept()
    {
        ScriptedDialogs dialogs;
        const QString a = copyStream("gone_a"), c = copyStream("gone_c");
        QVERIFY(!(editAndCrash(c) == ColourLut()));
        QVERIFY(QDir(c).removeRecursively());
        MainWindow w(m_pipeline);
        w.show();
        QVERIFY(openAndWait(w, a));
        const QByteArray a_before = test::tableBytes(w.session().lut().table());
        QVERIFY(!w.files().recoverLut());
        QVERIFY2(w.lastMessage().contains(c) && w.lastMessage().contains("kept"),
                 qPrintable(w.lastMessage()));
        QCOMPARE(test::tableBytes(w.session().lut().table()),
                 a_before); // nothing applied to A's table
        QVERIFY(!w.session().lut().modified());
        QVERIFY(w.session().lut().findRecovery().has_value()); // the edits are not lost
        QCOMPARE(QFileInfo(w.session().stream().streamSpec()).canonicalFilePath(),
                 QFileInfo(a).canonicalFilePath());
    }

    /// Pipeline > Save parameters to the stream writes them beside its frames and names them in
    /// its manifest; opening the stream applies them (the bottom of the history, no undo step); a
    /// params.json the stream does not name is not written over.
    void aStreamsOwnParametersAreSavedToItAndApplied()
    {
        const QString stream = copyStream("own_params");
        MainWindow w(m_pipeline);
        w.show();
        QVERIFY(openAndWait(w, stream));
        ui::PipelineSettings& settings = w.session().settings();
        QVERIFY(settings.paramChanges().empty());
        QVERIFY(settings.setParam("ball", "min_radius", 4).ok());
        menuAction(w, "pipeline.save_params_to_stream")->trigger();
        auto saved = ParamSet::load((stream + "/params.json").toStdString());
        QVERIFY2(saved.ok(), saved ? "" : saved.error().message.c_str());
        QCOMPARE(saved.value().values, settings.paramChanges().values);
        QFile manifest(stream + "/stream.json");
        QVERIFY(manifest.open(QIODevice::ReadOnly));
        QVERIFY(manifest.readAll().contains("\"params\": \"params.json\""));

        // Another stream (none of its own: the defaults), then this one: its parameters again.
        QVERIFY(openAndWait(w, sampleStream()));
        QVERIFY(settings.paramChanges().empty());
        QVERIFY(openAndWait(w, stream));
        QCOMPARE(settings.paramValue("ball", "min_radius"), 4.0);
        // Opening is no step: nothing undoes back to the stream before's (the defaults).
        QVERIFY(!settings.undoStack().canUndo());

        // Saved again: to the file the manifest names.
        QVERIFY(settings.setParam("ball", "min_radius", 5).ok());
        menuAction(w, "pipeline.save_params_to_stream")->trigger();
        QCOMPARE(ParamSet::load((stream + "/params.json").toStdString()).value().values,
                 settings.paramChanges().values);

        // A folder with a params.json of someone else's: left as it is, and the window says so.
        const QString other = copyStream("foreign_params");
        QFile foreign(other + "/params.json");
        QVERIFY(foreign.open(QIODevice::WriteOnly));
        foreign.write("not ours");
        foreign.close();
        QVERIFY(openAndWait(w, other));
        menuAction(w, "pipeline.save_params_to_stream")->trigger();
        QFile kept(other + "/params.json");
        QVERIFY(kept.open(QIODevice::ReadOnly));
        QCOMPARE(kept.readAll(), QByteArray("not ours"));
        QVERIFY(!QFileInfo::exists(other + "/stream.json"));
        QVERIFY2(w.lastMessage().contains("not written over"), qPrintable(w.lastMessage()));
    }

    void questionsGoThroughTheDialogsSeam()
    {
        ScriptedDialogs dialogs;
        MainWindow w(m_pipeline);
        w.show();
        QVERIFY(QTest::qWaitForWindowActive(&w));
        QVERIFY(openAndWait(w, copyStream("seam")));
        dialogs.numbers.push_back(1);
        QTest::keyClick(&w, Qt::Key_G, Qt::ControlModifier);
        QVERIFY(waitForFrame(w, 1));
        QCOMPARE(dialogs.asked.last(), QStringLiteral("Go to frame"));

        // Unsaved table edits: opening another stream asks first; Cancel keeps everything.
        w.tools().activate(QStringLiteral("click"));
        w.view().setZoom(1);
        w.view().setImageOrigin({0, 0});
        QTest::mouseClick(&w.view(), Qt::LeftButton, {}, pointAt(QPoint(60, 200)));
        QVERIFY(w.session().lut().modified());
        const QString before = w.session().stream().streamSpec();
        dialogs.answers.push_back(QMessageBox::Cancel);
        w.files().openStream(copyStream("seam_other"));
        QCOMPARE(dialogs.asked.last(), QStringLiteral("Unsaved LUT edits"));
        QVERIFY(!w.session().opening());
        QCOMPARE(w.session().stream().streamSpec(), before);
        QVERIFY(w.session().lut().modified());
        QVERIFY(dialogs.unanswered.isEmpty());
        // Discard: the other stream opens with its own table, clean.
        dialogs.answers.push_back(QMessageBox::Discard);
        QVERIFY(openAndWait(w, copyStream("seam_other")));
        QVERIFY(!w.session().lut().modified());
        QVERIFY(dialogs.unanswered.isEmpty());
    }
};

FIELDSIGHT_TEST_SUITE(TestSession, Widgets)

#include "test_session.moc"
