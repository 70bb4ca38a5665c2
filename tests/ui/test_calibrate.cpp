// Calibrate > Automatic table in the real window, offscreen (issue 33): the action and its button
// in the LUT editor, the table the window puts in is byte for byte what buildAutoLut makes of the
// same frames, as one undo step that Undo takes back to the bytes before; then the edit-effect
// strip and the evaluation's change line follow as after any edit; the goal colour found goes
// into the pipeline's goal-colour parameter (a step of its own); Cancel and a frame that cannot
// be read leave the table as it was. Builders given by the test stand in for the method where a
// test needs a result it controls (a table, a goal colour, a run that waits for Cancel).
#include "support/test_suite.h"
#include "support/scripted_dialogs.h"
#include "support/test_files.h"
#include "support/window_waits.h"
#include "ui/actions/calibrate_actions.h"
#include "ui/actions/menus.h"
#include "ui/adapters/local_path.h"
#include "ui/panels/evaluation_panel.h"
#include "ui/panels/lut_panel.h"
#include "ui/widgets/message_bar.h"
#include "visioncore/services/lut_compare.h"

#include <QDockWidget>
#include <QLabel>
#include <QMenuBar>
#include <QProgressDialog>
#include <QPushButton>
#include <QSettings>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QToolButton>
#include <QtTest>

#include <chrono>
#include <thread>

using namespace fieldsight;
using namespace fieldsight::test;
using fieldsight::ui::AutoLutRun;
using fieldsight::ui::CalibrateActions;
using fieldsight::ui::MainWindow;

namespace {

/// What Calibrate > Automatic table runs, a child of the window.
CalibrateActions& calibrateActions(MainWindow& w)
{
    auto* calibrate = w.findChild<CalibrateActions*>();
    Q_ASSERT(calibrate);
    return *calibrate;
}

QAction* autoAction(MainWindow& w)
{
    return w.findChild<QAction*>(QStringLiteral("calibrate.auto_lut"));
}

/// Waits for the automatic table's run to end; whether its table went in.
std::optional<bool> waitForRun(QSignalSpy& spy, int ms = 60000)
{
    if (spy.isEmpty() && !spy.wait(ms))
        return std::nullopt;
    return spy.front().front().toBool();
}

/// Waits until the whole-stream scan has covered every frame.
/// The value of every colour parameter named goal_colour, found as the window finds it.
std::vector<double> goalColours(MainWindow& w)
{
    std::vector<double> values;
    const ui::PipelineSettings& settings = w.session().settings();
    for (const StageDescriptor& stage : settings.pipeline().descriptors())
        for (const ParamInfo& p : stage.params)
            if (p.name == "goal_colour" && p.kind == ParamKind::Choice)
                values.push_back(settings.paramValue(stage.info.id, p.name));
    return values;
}

/// A builder that reads every frame it is given (reporting each) and returns `made`.
AutoLutRun::Builder returning(AutoLut made)
{
    return [made](StreamReader& reader, const AutoLutOptions&, const AutoLutProgress& progress) {
        const std::size_t n = reader.info().frame_count;
        for (std::size_t i = 0; i < n; ++i) {
            if (auto f = reader.read(i); !f)
                return Result<AutoLut>(f.error());
            if (progress && !progress(i + 1, n)) {
                AutoLut cut = made;
                cut.cancelled = true;
                return Result<AutoLut>(cut);
            }
        }
        return Result<AutoLut>(made);
    };
}

} // namespace

class TestCalibrate : public QObject
{
    Q_OBJECT

    QTemporaryDir m_dir;

    /// A copy of the bundled stream (frames, table, annotations) named `name`.
    QString copyStream(const QString& name)
    {
        return test::copyFolderFiles(sampleStream(), m_dir.filePath(name));
    }

private slots:
    void initTestCase() { QCOMPARE(test::startWindowSuite("test_calibrate", m_dir), QString()); }

    void init() { test::forgetEarlierTests(); }

    void theCalibrateMenuAndTheEditorOfferTheAutomaticTable()
    {
        MainWindow w;
        QAction* action = autoAction(w);
        QVERIFY(action);
        QCOMPARE(action->shortcut(), QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_A));
        QMenu* calibrate = nullptr;
        for (QAction* top : w.menuBar()->actions())
            if (top->text().remove('&') == "Calibrate")
                calibrate = top->menu();
        QVERIFY(calibrate);
        QVERIFY(calibrate->actions().contains(action));
        // The LUT editor's button is the same action (one shortcut, one enabled state).
        auto* button = w.lutPanel().findChild<QToolButton*>(QStringLiteral("calibrate.auto_lut"));
        QVERIFY(button);
        QCOMPARE(button->defaultAction(), action);
        // Help > Keyboard shortcuts lists it.
        QVERIFY(ui::shortcutsHtml(*w.menuBar()).contains("Automatic table"));
        // Without a stream it says what to do, and changes nothing.
        const int steps = w.session().lut().undoStack().count();
        action->trigger();
        QVERIFY(!calibrateActions(w).running());
        QVERIFY2(w.lastMessage().contains("Open a stream"), qPrintable(w.lastMessage()));
        QCOMPARE(w.session().lut().undoStack().count(), steps);
        QVERIFY(action->isEnabled());
    }

    void theTableIsWhatTheMethodMakesAsOneUndoStep()
    {
        ScriptedDialogs dialogs;
        const QString stream = copyStream("method");
        const QByteArray on_disk = fileBytes(stream + "/default.lut");
        MainWindow w;
        QVERIFY(showAndOpen(w, stream));
        const QByteArray before = test::tableBytes(w.session().lut().table());
        const ColourLut before_table = w.session().lut().table();
        const int steps = w.session().lut().undoStack().count();
        QVERIFY(!w.isWindowModified());

        QSignalSpy done(&calibrateActions(w), &CalibrateActions::finished);
        QTest::keyClick(&w, Qt::Key_A, Qt::ControlModifier | Qt::ShiftModifier);
        QVERIFY(calibrateActions(w).running() || !done.isEmpty());
        const auto applied = waitForRun(done);
        QVERIFY(applied.has_value());
        QVERIFY(*applied);

        // The same frames, turned as shown, through the method itself.
        auto reader =
            openStream(ui::toLocalPath(stream), StreamOptions{w.session().stream().orientation()});
        QVERIFY(reader.ok());
        auto expected = buildAutoLut(*reader.value());
        QVERIFY2(expected.ok(), expected.ok() ? "" : expected.error().message.c_str());
        const QByteArray made = test::tableBytes(expected.value().lut);
        QCOMPARE(test::tableBytes(w.session().lut().table()), made);
        QVERIFY2(made != before, "the sample's table and the automatic one should differ");
        QCOMPARE(w.session().lut().undoStack().count(), steps + 1);
        QVERIFY(w.session().undoGroup().activeStack() == &w.session().lut().undoStack());
        // Not saved: the title says so, the file is as it was.
        QVERIFY(w.session().lut().modified());
        QVERIFY(w.isWindowModified());
        QCOMPARE(fileBytes(stream + "/default.lut"), on_disk);
        QVERIFY2(w.lastMessage().contains("Automatic table from"), qPrintable(w.lastMessage()));
        for (const std::string& note : expected.value().notes)
            QVERIFY2(w.lastMessage().contains(QString::fromStdString(note)),
                     qPrintable(w.lastMessage()));

        // The whole-stream strip shows this edit's cells.
        QVERIFY(waitForScan(w.session().effectScan(), 30000));
        QVERIFY(w.session().effectScan().showsEdit());
        QCOMPARE(w.session().effectScan().changedCells(),
                 diffLuts(before_table, w.session().lut().table()).cells.size());

        // Ctrl+Z: the bytes before; Ctrl+Y: the automatic table again. The progress window
        // gives the keys back when it closes; wait for that (a slow run shows it longer).
        QTRY_VERIFY(!w.findChild<QWidget*>(QStringLiteral("calibrate.progress")));
        w.activateWindow();
        QVERIFY(QTest::qWaitForWindowActive(&w));
        QTest::keyClick(&w, Qt::Key_Z, Qt::ControlModifier);
        QVERIFY2(test::tableBytes(w.session().lut().table()) == before,
                 qPrintable(QString("lut steps %1 index %2, focus %3, active %4")
                                .arg(w.session().lut().undoStack().count())
                                .arg(w.session().lut().undoStack().index())
                                .arg(QApplication::focusWidget()
                                         ? QApplication::focusWidget()->metaObject()->className()
                                         : "none")
                                .arg(w.session().undoGroup().activeStack() ==
                                     &w.session().lut().undoStack())));
        QVERIFY(!w.session().lut().modified());
        QTest::keyClick(&w, Qt::Key_Y, Qt::ControlModifier);
        QCOMPARE(test::tableBytes(w.session().lut().table()), made);
        QVERIFY(dialogs.unanswered.isEmpty());
    }

    void theGoalColourAndTheScoresFollowTheResult()
    {
        const QString stream = copyStream("goal");
        MainWindow w;
        QVERIFY(showAndOpen(w, stream));
        QVERIFY(waitForEvaluation(w));
        const std::vector<double> goals_before = goalColours(w);
        QVERIFY(!goals_before.empty());
        for (double g : goals_before)
            QVERIFY(g != double(int(Colour::Blue)));
        const QByteArray before = test::tableBytes(w.session().lut().table());

        // A table without orange (the ball is lost) and a blue goal.
        AutoLut made;
        made.lut = w.session().lut().table();
        for (std::size_t i = 0; i < ColourLut::kCells; ++i)
            if (made.lut.cell(i) == Colour::Orange)
                made.lut.setCell(i, Colour::Unclassified);
        made.classes = {{Colour::Green, 1234, 0.625}, {Colour::White, 56, 0.031}};
        made.goal_colour = Colour::Blue;
        made.frames = 32;
        made.notes = {"no ball-coloured blob found"};
        calibrateActions(w).run().setBuilder(returning(made));
        const int lut_steps = w.session().lut().undoStack().count();
        const int settings_steps = w.session().settings().undoStack().count();

        QSignalSpy done(&calibrateActions(w), &CalibrateActions::finished);
        autoAction(w)->trigger();
        QCOMPARE(waitForRun(done), std::optional<bool>(true));
        QCOMPARE(test::tableBytes(w.session().lut().table()), test::tableBytes(made.lut));
        QCOMPARE(w.session().lut().undoStack().count(), lut_steps + 1);
        QCOMPARE(w.session().settings().undoStack().count(), settings_steps + 1);
        for (double g : goalColours(w))
            QCOMPARE(g, double(int(Colour::Blue)));
        const QString message = w.messageBar().text();
        for (const char* part :
             {"Automatic table from 32 frames", "green 1,234 cells", "62.5 %", "white 56 cells",
              "Goal colour blue", "no ball-coloured blob found"})
            QVERIFY2(message.contains(QLatin1String(part)), qPrintable(message));

        // The evaluation's change line, as after any edit: the ball is lost.
        QVERIFY(waitForEvaluation(w));
        const QString change = w.evaluationPanel().changeText();
        QVERIFY2(change.contains("ball recall"), qPrintable(change));
        QVERIFY(w.findChild<QLabel*>("scores_change")->text().contains(change));

        // Undo takes back the table first, then the goal colour.
        w.session().undo();
        QCOMPARE(test::tableBytes(w.session().lut().table()), before);
        for (double g : goalColours(w))
            QCOMPARE(g, double(int(Colour::Blue)));
        w.session().undo();
        QCOMPARE(goalColours(w), goals_before);

        // The same result again, with the goal already blue: no settings step.
        w.session().undoGroup().setActiveStack(&w.session().settings().undoStack());
        w.session().settings().undoStack().redo();
        const int settings_now = w.session().settings().undoStack().count();
        done.clear();
        autoAction(w)->trigger();
        QCOMPARE(waitForRun(done), std::optional<bool>(true));
        QCOMPARE(w.session().settings().undoStack().count(), settings_now);
    }

    void cancelLeavesTheTableAsItWas()
    {
        const QString stream = copyStream("cancel");
        MainWindow w;
        QVERIFY(showAndOpen(w, stream));
        const QByteArray before = test::tableBytes(w.session().lut().table());
        const int steps = w.session().lut().undoStack().count();
        // A run that goes on until it is cancelled (at most a minute).
        calibrateActions(w).run().setBuilder(
            [](StreamReader&, const AutoLutOptions&, const AutoLutProgress& progress) {
                AutoLut partial;
                partial.lut.setCell(5, Colour::Green);
                for (int i = 0; i < 6000; ++i) {
                    if (!progress(std::size_t(i % 40), 40)) {
                        partial.cancelled = true;
                        break;
                    }
                    std::this_thread::sleep_for(std::chrono::milliseconds(10));
                }
                return Result<AutoLut>(partial);
            });
        QSignalSpy done(&calibrateActions(w), &CalibrateActions::finished);
        // The editor's button, clicked.
        auto* button = w.lutPanel().findChild<QToolButton*>(QStringLiteral("calibrate.auto_lut"));
        QVERIFY(button);
        w.findChild<QDockWidget*>("lut_dock")->raise();
        QTRY_VERIFY(button->isVisible());
        QTest::mouseClick(button, Qt::LeftButton);
        QVERIFY(calibrateActions(w).running());
        QVERIFY(!autoAction(w)->isEnabled());

        // The window answers meanwhile: another frame is shown.
        w.session().stream().setCurrentIndex(3);
        QVERIFY(waitForFrame(w, 3));
        auto* progress = w.findChild<QProgressDialog*>(QStringLiteral("calibrate.progress"));
        QVERIFY(progress);
        QTRY_VERIFY(progress->isVisible());
        auto* cancel = progress->findChild<QPushButton*>();
        QVERIFY(cancel);
        QTest::mouseClick(cancel, Qt::LeftButton);
        QCOMPARE(waitForRun(done, 10000), std::optional<bool>(false));
        QCOMPARE(test::tableBytes(w.session().lut().table()), before);
        QCOMPARE(w.session().lut().undoStack().count(), steps);
        QVERIFY2(w.lastMessage().contains("cancelled"), qPrintable(w.lastMessage()));
        QVERIFY(autoAction(w)->isEnabled());
        QTRY_VERIFY(!w.findChild<QProgressDialog*>(QStringLiteral("calibrate.progress")));
    }

    void aFrameThatCannotBeReadIsAMessage()
    {
        const QString stream = copyStream("damaged");
        MainWindow w;
        QVERIFY(showAndOpen(w, stream));
        const QByteArray before = test::tableBytes(w.session().lut().table());
        const int steps = w.session().lut().undoStack().count();
        // Damaged after the stream opened (the window shows frame 0, read before).
        const QString frame = stream + "/frame_000010.png";
        QFile f(frame);
        QVERIFY(f.open(QIODevice::WriteOnly | QIODevice::Truncate));
        QVERIFY(f.write("not a picture") > 0);
        f.close();
        QSignalSpy done(&calibrateActions(w), &CalibrateActions::finished);
        autoAction(w)->trigger();
        QCOMPARE(waitForRun(done), std::optional<bool>(false));
        QCOMPARE(test::tableBytes(w.session().lut().table()), before);
        QCOMPARE(w.session().lut().undoStack().count(), steps);
        QVERIFY(w.messageBar().isVisible());
        QVERIFY2(w.messageBar().text().contains("frame_000010.png"),
                 qPrintable(w.messageBar().text()));
        QVERIFY2(w.messageBar().text().contains("LUT is unchanged"),
                 qPrintable(w.messageBar().text()));
    }

    void aRunOverAStreamClosedMeanwhileIsDropped()
    {
        const QString first = copyStream("first");
        const QString second = copySampleFrames(m_dir.filePath("second"), 4);
        MainWindow w;
        QVERIFY(showAndOpen(w, first));
        AutoLut made;
        made.lut.setCell(7, Colour::White);
        calibrateActions(w).run().setBuilder(
            [made](StreamReader&, const AutoLutOptions&, const AutoLutProgress& progress) {
                for (int i = 0; i < 6000 && progress(0, 1); ++i)
                    std::this_thread::sleep_for(std::chrono::milliseconds(10));
                return Result<AutoLut>(made);
            });
        QSignalSpy done(&calibrateActions(w), &CalibrateActions::finished);
        autoAction(w)->trigger();
        QVERIFY(calibrateActions(w).running());
        QVERIFY(openAndWait(w, second));
        QCOMPARE(waitForRun(done, 10000), std::optional<bool>(false));
        QCOMPARE(w.session().lut().undoStack().count(), 0);
        QVERIFY(w.session().lut().table().cell(7) != Colour::White);
        QVERIFY2(w.lastMessage().contains("dropped"), qPrintable(w.lastMessage()));
    }
};

FIELDSIGHT_TEST_SUITE(TestCalibrate, Widgets)

#include "test_calibrate.moc"
