// Pipeline > Fit to annotations in the real window, offscreen (issue 34): on a copy of the bundled
// lab1 stream, with an unsaved annotation edit and an unsaved table edit, the search runs in the
// background on what the window holds (the result is tuneParams' own on the same inputs), its
// before/after table and changes are shown before anything is applied, Apply sets every tuned
// parameter as ONE undo step that one Ctrl+Z takes back whole, and Save parameters to the stream
// writes them to params.json. Cancel keeps the best so far while the window goes on answering; a
// stream without done annotations gets a message instead of a run; the budget is remembered.
#include "support/test_suite.h"
#include "support/scripted_dialogs.h"
#include "support/test_files.h"
#include "support/window_waits.h"
#include "ui/actions/fit_actions.h"
#include "ui/actions/menus.h"
#include "ui/adapters/local_path.h"
#include "ui/dialogs/fit_result_dialog.h"
#include "ui/settings/window_settings.h"
#include "ui/widgets/message_bar.h"

#include <QHeaderView>
#include <QMenuBar>
#include <QProgressDialog>
#include <QPushButton>
#include <QSettings>
#include <QStandardPaths>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QtTest>

using namespace fieldsight;
using namespace fieldsight::test;
using fieldsight::ui::FitActions;
using fieldsight::ui::FitResultDialog;
using fieldsight::ui::MainWindow;

namespace {

QAction* fitAction(MainWindow& w)
{
    return w.findChild<QAction*>(QStringLiteral("pipeline.fit_annotations"));
}

FitActions& fitActions(MainWindow& w)
{
    auto* fit = w.findChild<FitActions*>();
    Q_ASSERT(fit);
    return *fit;
}

/// Waits for the search to end; whether its result was shown.
std::optional<bool> waitForFit(QSignalSpy& spy, int ms = 120000)
{
    if (spy.isEmpty() && !spy.wait(ms))
        return std::nullopt;
    return spy.front().front().toBool();
}

/// The value in use of every parameter the pipeline declares, by "stage.name".
std::map<std::string, double> allValues(MainWindow& w)
{
    std::map<std::string, double> values;
    const ui::PipelineSettings& settings = w.session().settings();
    for (const StageDescriptor& stage : settings.pipeline().descriptors())
        for (const ParamInfo& p : stage.params)
            values[stage.info.id + "." + p.name] = settings.paramValue(stage.info.id, p.name);
    return values;
}

const ParamInfo* findParam(const Pipeline& pipeline, const std::string& stage,
                           const std::string& name)
{
    if (const StageDescriptor* d = pipeline.find(stage))
        for (const ParamInfo& p : d->params)
            if (p.name == name)
                return &p;
    return nullptr;
}

/// tuneParams on the stream in the folder `stream`, with the window's table, parameters and
/// skipped stages and `truth`: what the window's search must give.
Result<TuneResult> tuneDirectly(MainWindow& w, const QString& stream, const Annotations& truth,
                                int budget)
{
    auto reader =
        openStream(ui::toLocalPath(stream), StreamOptions{w.session().stream().orientation()});
    if (!reader)
        return reader.error();
    StreamInput input;
    input.stream = ui::toLocalPath(stream);
    input.reader = std::move(reader).value();
    input.lut = w.session().lut().version();
    input.pipeline = &w.session().pipeline();
    input.params = w.session().settings().paramChanges();
    for (const std::string& s : w.session().settings().skippedStages())
        input.skip.push_back(s);
    TuneOptions options;
    options.budget = budget;
    return tuneParams(input, truth, ui::toLocalPath(stream + "/annotations.json"), options);
}

} // namespace

class TestFitAnnotations : public QObject
{
    Q_OBJECT

    QTemporaryDir m_dir;

    /// A copy of the bundled stream (frames, table, annotations) named `name`.
    QString copyStream(const QString& name)
    {
        return test::copyFolderFiles(sampleStream(), m_dir.filePath(name));
    }

private slots:
    void initTestCase()
    {
        QCOMPARE(test::startWindowSuite("test_fit_annotations", m_dir), QString());
        // The bundled streams are part of the project: a wrong path must fail, not skip.
        QVERIFY2(QFileInfo(sampleStream() + "/annotations.json").isFile(),
                 qPrintable("the bundled sample stream is missing: " + sampleStream()));
    }

    void init() { test::forgetEarlierTests(); }

    void thePipelineMenuOffersItWithItsKey()
    {
        ScriptedDialogs dialogs;
        MainWindow w;
        QAction* action = fitAction(w);
        QVERIFY(action);
        QCOMPARE(action->shortcut(), QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_F));
        QMenu* pipeline = nullptr;
        for (QAction* top : w.menuBar()->actions())
            if (top->text().remove('&') == "Pipeline")
                pipeline = top->menu();
        QVERIFY(pipeline);
        QVERIFY(pipeline->actions().contains(action));
        QVERIFY(ui::shortcutsHtml(*w.menuBar()).contains("Fit to annotations"));
        // Without a stream it says what to do, asks nothing and runs nothing.
        action->trigger();
        QVERIFY(!fitActions(w).running());
        QVERIFY2(w.lastMessage().contains("Open a stream"), qPrintable(w.lastMessage()));
        QVERIFY(dialogs.asked.isEmpty());
        QVERIFY(dialogs.offered.isEmpty());
    }

    void aStreamWithoutDoneAnnotationsGetsAMessage()
    {
        ScriptedDialogs dialogs;
        const QString stream = copyStream("none");
        QVERIFY(QFile::remove(stream + "/annotations.json"));
        MainWindow w;
        QVERIFY(showAndOpen(w, stream));
        const int steps = w.session().settings().undoStack().count();
        QTest::keyClick(&w, Qt::Key_F, Qt::ControlModifier | Qt::ShiftModifier);
        QVERIFY(!fitActions(w).running());
        QVERIFY2(w.lastMessage().contains("no annotations"), qPrintable(w.lastMessage()));
        QVERIFY(dialogs.offered.isEmpty()); // no budget asked

        // Annotated, but no frame done (an unsaved edit of the document): still nothing to fit.
        const QString annotated = copyStream("not_done");
        QVERIFY(openAndWait(w, annotated));
        ui::AnnotationsDocument& doc = w.session().annotations();
        ui::AnnotationsDocument::FrameEdits edits;
        for (const auto& [name, frame] : doc.annotations().frames) {
            FrameAnnotation open = frame;
            open.done = false;
            open.reviewed.clear();
            edits[name] = open;
        }
        QVERIFY(doc.edit("undone", std::move(edits)));
        fitAction(w)->trigger();
        QVERIFY(!fitActions(w).running());
        QVERIFY2(w.lastMessage().contains("None of the annotated frames is done"),
                 qPrintable(w.lastMessage()));
        QVERIFY(dialogs.offered.isEmpty());
        QCOMPARE(w.session().settings().undoStack().count(), steps);
    }

    void theResultIsShownThenAppliedAsOneUndoStep()
    {
        ScriptedDialogs dialogs;
        const QString stream = copyStream("apply");
        MainWindow w;
        QVERIFY(showAndOpen(w, stream));
        // Unsaved edits the search must see: frame 7 no longer done, and the table's orange
        // (the ball's colour) taken out.
        ui::AnnotationsDocument& doc = w.session().annotations();
        const std::string undone = "frame_000007.png";
        QVERIFY(doc.frame(undone) && doc.frame(undone)->done);
        FrameAnnotation open = *doc.frame(undone);
        open.done = false;
        open.reviewed.clear();
        QVERIFY(doc.editFrame(undone, open, "undone"));
        std::vector<CellChange> cells;
        const ColourLut& table = w.session().lut().table();
        for (std::uint32_t c = 0; c < ColourLut::kCells; ++c)
            if (table.cell(c) == Colour::Orange)
                cells.push_back({c, Colour::Orange, Colour::Unclassified});
        QVERIFY(!cells.empty());
        QVERIFY(w.session().lut().edit("no orange", std::move(cells)));
        const Annotations truth = doc.annotations();
        const std::map<std::string, double> before = allValues(w);
        const ParamSet changes_before = w.session().settings().paramChanges();
        const int steps = w.session().settings().undoStack().count();

        constexpr int kBudget = 120;
        dialogs.numbers.push_back(kBudget);
        QSignalSpy done(&fitActions(w), &FitActions::finished);
        QTest::keyClick(&w, Qt::Key_F, Qt::ControlModifier | Qt::ShiftModifier);
        QCOMPARE(dialogs.offered, QList<int>{FitActions::kDefaultBudget});
        QVERIFY(fitActions(w).running() || !done.isEmpty());
        QVERIFY(!fitAction(w)->isEnabled());
        QCOMPARE(waitForFit(done), std::optional<bool>(true));
        QVERIFY(fitAction(w)->isEnabled());
        FitResultDialog* dialog = fitActions(w).resultDialog();
        QVERIFY(dialog);
        QTRY_VERIFY(dialog->isVisible());
        const TuneResult r = dialog->result(); // a copy: the dialog goes once closed

        // Nothing applied yet.
        QCOMPARE(allValues(w), before);
        QCOMPARE(w.session().settings().undoStack().count(), steps);

        // What the window searched: the annotations and table as edited, unsaved.
        QCOMPARE(r.fit_frames.size() + r.holdout_frames.size(), truth.frames.size() - 1);
        for (const auto& list : {r.fit_frames, r.holdout_frames})
            QVERIFY(std::find(list.begin(), list.end(), undone) == list.end());
        QVERIFY(!r.holdout_frames.empty());
        QVERIFY(r.evaluations > 0 && r.evaluations <= kBudget);
        QVERIFY(!r.cancelled);
        const auto expected = tuneDirectly(w, stream, truth, kBudget);
        QVERIFY2(expected.ok(), expected.ok() ? "" : expected.error().message.c_str());
        const TuneResult& e = expected.value();
        QCOMPARE(r.fit_frames, e.fit_frames);
        QCOMPARE(r.start_fit.total, e.start_fit.total);
        QCOMPARE(r.start_holdout.total, e.start_holdout.total);
        QCOMPARE(r.tuned_fit.total, e.tuned_fit.total);
        QCOMPARE(r.params.values, e.params.values);
        // The table without orange finds no ball: the start is the edited table's.
        QVERIFY(r.start_fit.classes.count("ball"));
        QCOMPARE(r.start_fit.classes.at("ball").tp, 0);
        QVERIFY(r.tuned_fit.total >= r.start_fit.total);
        QVERIFY2(!r.changes.empty(), "the search should find a better set on lab1");

        // The before/after table: a row per class scored, then the boundary and the total.
        QTableWidget& scores = dialog->scores();
        QCOMPARE(scores.columnCount(), 5);
        QVERIFY(scores.horizontalHeaderItem(1)->text().contains("Fit frames"));
        QVERIFY(scores.horizontalHeaderItem(3)->text().contains("Held out"));
        const int last = scores.rowCount() - 1;
        QCOMPARE(scores.item(last, 0)->text(), QString("Score"));
        QCOMPARE(scores.item(last, 1)->text(), QString::number(r.start_fit.total, 'f', 3));
        QCOMPARE(scores.item(last, 2)->text(), QString::number(r.tuned_fit.total, 'f', 3));
        QCOMPARE(scores.item(last, 3)->text(), QString::number(r.start_holdout.total, 'f', 3));
        QCOMPARE(scores.item(last, 4)->text(), QString::number(r.tuned_holdout.total, 'f', 3));
        QCOMPARE(scores.rowCount(), int(r.start_fit.classes.size() + 2));
        const std::string_view ball_title = perceptKind<Ball>().title;
        bool ball_row = false;
        for (int row = 0; row < last; ++row)
            if (scores.item(row, 0)->text() ==
                QString::fromUtf8(ball_title.data(), qsizetype(ball_title.size()))) {
                ball_row = true;
                QVERIFY2(scores.item(row, 1)->text().startsWith("0.00"),
                         qPrintable(scores.item(row, 1)->text()));
            }
        QVERIFY(ball_row);
        // The changes: parameter, old value, new value, what it bought.
        QTableWidget& changes = dialog->changes();
        QCOMPARE(changes.rowCount(), int(r.changes.size()));
        for (int row = 0; row < changes.rowCount(); ++row) {
            const TuneChange& c = r.changes[std::size_t(row)];
            const ParamInfo* info = findParam(w.session().pipeline(), c.stage, c.name);
            QVERIFY(info);
            QVERIFY(changes.item(row, 0)->text().contains(QString::fromStdString(c.name)));
            QCOMPARE(changes.item(row, 1)->text(), ui::paramValueText(*info, c.before));
            QCOMPARE(changes.item(row, 2)->text(), ui::paramValueText(*info, c.after));
            QVERIFY(!changes.item(row, 3)->text().isEmpty());
        }
        QVERIFY2(dialog->summary().contains(QString::number(r.evaluations)),
                 qPrintable(dialog->summary()));
        // FIELDSIGHT_FIT_SCREENSHOT=FILE.png: the dialog as shown, to look at.
        if (const QByteArray shot = qgetenv("FIELDSIGHT_FIT_SCREENSHOT"); !shot.isEmpty())
            QVERIFY(dialog->grab().save(QString::fromLocal8Bit(shot)));

        // Apply: every change in use, as one step of the pipeline settings.
        QVERIFY(dialog->applyButton().isEnabled());
        QTest::mouseClick(&dialog->applyButton(), Qt::LeftButton);
        QTRY_VERIFY(!fitActions(w).resultDialog());
        QCOMPARE(w.session().settings().undoStack().count(), steps + 1);
        // The settings keep what differs from the defaults (a value put back to its default is
        // no change).
        const ParamSet tuned = differingFromDefaults(r.params, w.session().pipeline());
        QCOMPARE(w.session().settings().paramChanges().values, tuned.values);
        for (const TuneChange& c : r.changes)
            QCOMPARE(w.session().settings().paramValue(c.stage, c.name), c.after);
        QVERIFY(allValues(w) != before);
        QVERIFY2(w.lastMessage().contains("Fitted parameters in use"), qPrintable(w.lastMessage()));

        // One Ctrl+Z takes every parameter back; Ctrl+Y puts them all in again.
        w.activateWindow();
        QVERIFY(QTest::qWaitForWindowActive(&w));
        QTest::keyClick(&w, Qt::Key_Z, Qt::ControlModifier);
        QCOMPARE(allValues(w), before);
        QCOMPARE(w.session().settings().paramChanges().values, changes_before.values);
        QCOMPARE(w.session().lut().undoStack().index(), 1); // the table's edit is still in
        QTest::keyClick(&w, Qt::Key_Y, Qt::ControlModifier);
        QCOMPARE(w.session().settings().paramChanges().values, tuned.values);

        // The existing save path writes them as the stream's params.json.
        QVERIFY(!QFileInfo::exists(stream + "/params.json"));
        auto* save = w.findChild<QAction*>(QStringLiteral("pipeline.save_params_to_stream"));
        QVERIFY(save);
        save->trigger();
        auto saved = ParamSet::load(ui::toLocalPath(stream + "/params.json"));
        QVERIFY2(saved.ok(), saved.ok() ? "" : saved.error().message.c_str());
        QCOMPARE(saved.value().values, tuned.values);
        QVERIFY(dialogs.unanswered.isEmpty());

        // The budget is offered again next time, and kept between sessions.
        dialogs.numbers.clear();
        fitAction(w)->trigger(); // asked, then cancelled (nothing queued)
        QCOMPARE(dialogs.offered.last(), kBudget);
        QVERIFY(!fitActions(w).running());
        w.saveSettings();
        QCOMPARE(ui::WindowSettings::load().fit_budget, kBudget);
    }

    void cancelKeepsTheBestSoFarAndTheWindowAnswers()
    {
        ScriptedDialogs dialogs;
        const QString stream = copyStream("cancel");
        MainWindow w;
        QVERIFY(showAndOpen(w, stream));
        const std::map<std::string, double> before = allValues(w);
        const int steps = w.session().settings().undoStack().count();
        dialogs.numbers.push_back(100000); // far more than it is let run
        QSignalSpy done(&fitActions(w), &FitActions::finished);
        fitAction(w)->trigger();
        QVERIFY(fitActions(w).running());
        QTRY_VERIFY_WITH_TIMEOUT(fitActions(w).run().progress().first >= 3, 60000);

        // The window answers while it searches: other frames are shown, each within a second.
        for (std::size_t frame : {3u, 12u, 20u}) {
            QElapsedTimer clock;
            clock.start();
            w.session().stream().setCurrentIndex(frame);
            QVERIFY(waitForFrame(w, frame));
            QVERIFY2(clock.elapsed() < 3000, qPrintable(QString::number(clock.elapsed())));
        }
        QVERIFY(fitActions(w).running());

        auto* progress = w.findChild<QProgressDialog*>(QStringLiteral("fit.progress"));
        QVERIFY(progress);
        QTRY_VERIFY(progress->isVisible());
        QTRY_VERIFY(progress->labelText().contains("Best score"));
        if (const QByteArray shot = qgetenv("FIELDSIGHT_FIT_SCREENSHOT"); !shot.isEmpty())
            QVERIFY(progress->grab().save(
                QString::fromLocal8Bit(shot).replace(".png", "-progress.png")));
        auto* cancel = progress->findChild<QPushButton*>();
        QVERIFY(cancel);
        QTest::mouseClick(cancel, Qt::LeftButton);
        QCOMPARE(waitForFit(done, 60000), std::optional<bool>(true));
        QTRY_VERIFY(!w.findChild<QProgressDialog*>(QStringLiteral("fit.progress")));
        FitResultDialog* dialog = fitActions(w).resultDialog();
        QVERIFY(dialog);
        const TuneResult r = dialog->result(); // a copy: the dialog goes once closed
        QVERIFY(r.cancelled);
        QVERIFY(r.evaluations >= 3 && r.evaluations < 100000);
        QVERIFY(r.tuned_fit.total >= r.start_fit.total);
        QVERIFY2(dialog->summary().contains("Cancelled"), qPrintable(dialog->summary()));
        QCOMPARE(dialog->applyButton().isEnabled(), !r.changes.empty());
        // Closed without Apply: nothing changed.
        dialog->reject();
        QTRY_VERIFY(!fitActions(w).resultDialog());
        QCOMPARE(allValues(w), before);
        QCOMPARE(w.session().settings().undoStack().count(), steps);

        // The window still works: a frame, and a second search that runs to its end.
        w.session().stream().setCurrentIndex(5);
        QVERIFY(waitForFrame(w, 5));
        done.clear();
        QVERIFY(fitAction(w)->isEnabled());
        QVERIFY(fitActions(w).start(12));
        QCOMPARE(waitForFit(done), std::optional<bool>(true));
        QVERIFY(fitActions(w).resultDialog());
        QVERIFY(!fitActions(w).resultDialog()->result().cancelled);
        QCOMPARE(fitActions(w).resultDialog()->result().evaluations, 12);
    }

    void aSearchOverAStreamClosedMeanwhileIsDropped()
    {
        ScriptedDialogs dialogs;
        const QString first = copyStream("first");
        const QString second = copyStream("second");
        MainWindow w;
        QVERIFY(showAndOpen(w, first));
        dialogs.numbers.push_back(100000);
        QSignalSpy done(&fitActions(w), &FitActions::finished);
        fitAction(w)->trigger();
        QVERIFY(fitActions(w).running());
        QVERIFY(openAndWait(w, second));
        QCOMPARE(waitForFit(done, 60000), std::optional<bool>(false));
        QVERIFY(!fitActions(w).resultDialog());
        QVERIFY2(w.lastMessage().contains("dropped"), qPrintable(w.lastMessage()));
        QCOMPARE(w.session().settings().undoStack().count(), 0);
    }
};

FIELDSIGHT_TEST_SUITE(TestFitAnnotations, Widgets)

#include "test_fit_annotations.moc"
