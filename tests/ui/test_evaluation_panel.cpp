// The evaluation dock in the real main window, offscreen: its numbers equal `fieldsight eval
// --json` on the same stream and annotations (run as a child process), a ball annotated where
// nothing is detected is listed on its frame and the next-disagreement key lands there with the
// ball drawn emphasised, a LUT edit that erases orange drops the ball recall the dock shows, and
// an edit of the annotations document is scored again with the detections already made.
#include "support/test_suite.h"
#include "support/child_process.h"
#include "support/test_files.h"
#include "support/window_waits.h"
#include "ui/actions/session_files.h"
#include "ui/document/annotations_document.h"
#include "ui/scans/evaluation_scan.h"
#include "ui/main_window.h"
#include "ui/panels/evaluation_panel.h"
#include "ui/panels/lut_panel.h"
#include "ui/stream_navigator/frame_marks_strip.h"
#include "visioncore/percepts/ball.h"

#include <QDir>
#include <QDockWidget>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QLabel>
#include <QListWidget>
#include <QSettings>
#include <QStandardPaths>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QtTest>

using namespace fieldsight;
using namespace fieldsight::test;
using fieldsight::ui::MainWindow;

namespace {

/// The eval JSON's class names, in the dock's row order (scoredKinds()).
const QStringList kClasses{"ball", "goalpost", "obstacle", "field_line"};

/// Copies the bundled stream into `dir` with its annotations changed by `edit`.
void copyStream(const QString& dir, const std::function<void(QJsonObject& frames)>& edit)
{
    const QDir from(sampleStream());
    QDir().mkpath(dir);
    for (const QString& name : from.entryList(QDir::Files))
        QFile::copy(from.filePath(name), dir + "/" + name);
    QFile file(dir + "/annotations.json");
    QVERIFY(file.open(QIODevice::ReadOnly));
    QJsonObject doc = QJsonDocument::fromJson(file.readAll()).object();
    file.close();
    QJsonObject frames = doc.value("frames").toObject();
    edit(frames);
    doc["frames"] = frames;
    QVERIFY(file.open(QIODevice::WriteOnly | QIODevice::Truncate));
    file.write(QJsonDocument(doc).toJson());
}

/// Adds `object` to the list `key` of frame `frame`.
void addObject(QJsonObject& frames, const QString& frame, const QString& key,
               const QJsonObject& object)
{
    QJsonObject f = frames.value(frame).toObject();
    QJsonArray list = f.value(key).toArray();
    list.append(object);
    f[key] = list;
    frames[frame] = f;
}

QString cell(ui::EvaluationPanel& panel, int row, int column)
{
    const QTableWidgetItem* item = panel.scores().item(row, column);
    return item ? item->text() : QString();
}

} // namespace

class TestEvaluationPanel : public QObject
{
    Q_OBJECT
private slots:
    void initTestCase()
    {
        QCOMPARE(test::startWindowSuite("test_evaluation_panel", m_dir), QString());
    }

    void init() { QSettings().clear(); }

    void panelNumbersEqualTheEvalCommand()
    {
        // Every extension in play: a concealed ball, a frame scored only for its reviewed
        // balls, and a ball nothing detects.
        const QString stream = m_dir.filePath("equal");
        copyStream(stream, [](QJsonObject& frames) {
            QJsonObject f5 = frames.value("frame_000005.png").toObject();
            QJsonArray balls = f5.value("balls").toArray();
            QJsonObject ball = balls.at(0).toObject();
            ball["concealed"] = true;
            balls[0] = ball;
            f5["balls"] = balls;
            frames["frame_000005.png"] = f5;
            QJsonObject f29 = frames.value("frame_000029.png").toObject();
            f29["done"] = false;
            f29["reviewed"] = QJsonArray{"balls"};
            frames["frame_000029.png"] = f29;
            addObject(frames, "frame_000017.png", "balls",
                      QJsonObject{{"x", 10}, {"y", 10}, {"radius", 5}});
        });
        MainWindow w;
        w.show();
        QVERIFY(openAndWait(w, stream));
        QVERIFY(waitForEvaluation(w));
        ui::EvaluationPanel& panel = w.evaluationPanel();
        QVERIFY2(w.session().evaluation().problem().isEmpty(),
                 qPrintable(w.session().evaluation().problem()));

        const QString json = m_dir.filePath("equal_eval.json");
        const Outcome o =
            runChild(FIELDSIGHT_EXE, {"eval", stream.toStdString(), "--json", json.toStdString()},
                     m_dir.path().toStdString(), RLIM_INFINITY, false, 120);
        QVERIFY2(o.status == 0, o.err.c_str());
        const QJsonObject doc = QJsonDocument::fromJson(fileBytes(json)).object();
        QCOMPARE(doc.value("frames").toInt(), 29);
        QCOMPARE(doc.value("frames_reviewed").toInt(), 1);
        QVERIFY(panel.statusText().contains("29 done frames"));
        QVERIFY(panel.statusText().contains("1 more for their reviewed kinds"));

        const QJsonObject classes = doc.value("classes").toObject();
        QCOMPARE(panel.scores().rowCount(), kClasses.size());
        int concealed = 0;
        for (int r = 0; r < kClasses.size(); ++r) {
            const QJsonObject c = classes.value(kClasses[r]).toObject();
            QVERIFY2(!c.isEmpty(), qPrintable(kClasses[r]));
            QCOMPARE(cell(panel, r, 1), QString::number(c.value("tp").toInt()));
            QCOMPARE(cell(panel, r, 2), QString::number(c.value("fp").toInt()));
            QCOMPARE(cell(panel, r, 3), QString::number(c.value("fn").toInt()));
            QCOMPARE(cell(panel, r, 4), QString::number(c.value("precision").toDouble(), 'f', 3));
            QCOMPARE(cell(panel, r, 5), QString::number(c.value("recall").toDouble(), 'f', 3));
            const int found = c.value("concealed_found").toInt();
            const int missed = c.value("concealed_missed").toInt();
            concealed += found + missed;
            if (found + missed > 0)
                QCOMPARE(cell(panel, r, 6), QString("%1 / %2").arg(found).arg(missed));
        }
        // The ball made concealed here and the stream's own concealed objects are counted
        // apart, found or not: those of the scored frames, and of frame 29 only its balls.
        int flagged = 0;
        const QJsonObject truth_frames =
            QJsonDocument::fromJson(fileBytes(stream + "/annotations.json"))
                .object()
                .value("frames")
                .toObject();
        for (auto f = truth_frames.begin(); f != truth_frames.end(); ++f) {
            const QJsonObject frame = f.value().toObject();
            for (auto kind = frame.begin(); kind != frame.end(); ++kind) {
                if (f.key() == "frame_000029.png" && kind.key() != "balls")
                    continue;
                for (const QJsonValue object : kind.value().toArray())
                    flagged += object.toObject().value("concealed").toBool();
            }
        }
        QVERIFY(flagged > 1);
        QCOMPARE(concealed, flagged);
        const QJsonObject boundary = doc.value("field_boundary").toObject();
        QVERIFY(boundary.value("frames").toInt() > 0);
        const auto* boundary_label = panel.findChild<QLabel*>("evaluation.boundary");
        QVERIFY(boundary_label->text().contains(
            QString::number(boundary.value("mean_error_px").toDouble(), 'f', 2) + " px over " +
            QString::number(boundary.value("frames").toInt()) + " frames"));

        // The same disagreements, frame by frame and kind by kind, with the same objects.
        const QJsonArray disagreements = doc.value("disagreements").toArray();
        const auto& failing = w.session().evaluation().failing();
        QCOMPARE(qsizetype(failing.size()), disagreements.size());
        QCOMPARE(panel.frames().count(), disagreements.size());
        for (const QJsonValue& v : disagreements) {
            const QJsonObject d = v.toObject();
            const auto same = [&](const ui::FailingFrame& f) {
                const auto indices = [](const QJsonArray& a) {
                    std::vector<std::size_t> out;
                    for (const QJsonValue& i : a)
                        out.push_back(std::size_t(i.toInt()));
                    return out;
                };
                const auto k =
                    std::find(scoredKinds().begin(), scoredKinds().end(), f.disagreement.kind) -
                    scoredKinds().begin();
                return f.index == std::size_t(d.value("index").toInt()) &&
                       kClasses.value(int(k)) == d.value("class").toString() &&
                       f.disagreement.missed == indices(d.value("missed").toArray()) &&
                       f.disagreement.false_detections ==
                           indices(d.value("false_detections").toArray());
            };
            QVERIFY2(std::any_of(failing.begin(), failing.end(), same),
                     QJsonDocument(d).toJson().constData());
        }
    }

    void missedBallIsListedAndTheKeyLandsOnIt()
    {
        const QString stream = m_dir.filePath("missed");
        copyStream(stream, [](QJsonObject& frames) {
            addObject(frames, "frame_000017.png", "balls",
                      QJsonObject{{"x", 10}, {"y", 10}, {"radius", 5}});
        });
        MainWindow w;
        w.show();
        QVERIFY(openAndWait(w, stream));
        QVERIFY(waitForEvaluation(w));
        ui::EvaluationPanel& panel = w.evaluationPanel();
        const auto& failing = w.session().evaluation().failing();
        // Listed on frame 17: the second true ball (index 1) missed.
        const auto listed = std::find_if(failing.begin(), failing.end(), [](const auto& f) {
            return f.index == 17 && f.disagreement.kind == &perceptKind<Ball>();
        });
        QVERIFY(listed != failing.end());
        QVERIFY(std::count(listed->disagreement.missed.begin(), listed->disagreement.missed.end(),
                           std::size_t(1)) == 1);
        const int row = int(listed - failing.begin());
        QVERIFY(panel.frames().item(row)->text().startsWith("Frame 17 · Ball"));
        QVERIFY(w.timeline().disagreementStrip().marks().count(17));
        QVERIFY(w.timeline().disagreementStrip().isVisible());

        // From frame 16 the key (Navigate > Next disagreement, F6) lands on frame 17's ball:
        // balls come first among a frame's kinds.
        w.session().stream().setCurrentIndex(16);
        QVERIFY(waitForFrame(w, 16));
        QVERIFY(!panel.frames().selectedItems().size());
        auto* next = w.findChild<QAction*>("navigate.next_disagreement");
        QVERIFY(next);
        QCOMPARE(next->shortcut(), QKeySequence(Qt::Key_F6));
        // Zoomed in on another corner: the view is brought to the culprit.
        w.view().setZoom(8);
        w.view().setImageOrigin({-1500, -1000});
        QTest::keyClick(&w.view(), Qt::Key_F6);
        QVERIFY(waitForFrame(w, 17));
        const QPointF ball = QPointF(w.view().imageOrigin()) + QPointF(10.5, 10.5) * 8;
        QVERIFY2(w.view().rect().contains(ball.toPoint()),
                 qPrintable(QString("%1,%2").arg(ball.x()).arg(ball.y())));
        QCOMPARE(panel.chosen(), row);
        QCOMPARE(panel.frames().currentRow(), row);
        // The missed ball is drawn emphasised over the frame: its ring (radius 5 around 10, 10)
        // in the missed colour, its centre left clear.
        const QImage& culprit = w.view().highlight("evaluation");
        QVERIFY(!culprit.isNull());
        QCOMPARE(culprit.size(), QSize(320, 240));
        QCOMPARE(culprit.pixelColor(15, 10), QColor(255, 40, 200));
        QCOMPARE(culprit.pixelColor(10, 10).alpha(), 0);
        QCOMPARE(culprit.pixelColor(100, 100).alpha(), 0);

        // Another frame: the culprit goes.
        w.session().stream().setCurrentIndex(2);
        QVERIFY(waitForFrame(w, 2));
        QVERIFY(w.view().highlight("evaluation").isNull());
        QCOMPARE(panel.chosen(), -1);

        // A click on the list goes there too.
        QListWidgetItem* item = panel.frames().item(row);
        w.findChild<QDockWidget*>("evaluation_dock")->raise();
        QApplication::processEvents();
        QTest::mouseClick(panel.frames().viewport(), Qt::LeftButton, {},
                          panel.frames().visualItemRect(item).center());
        QVERIFY(waitForFrame(w, 17));
        QVERIFY(!w.view().highlight("evaluation").isNull());
    }

    void erasingOrangeDropsBallRecall()
    {
        MainWindow w;
        w.show();
        QVERIFY(openAndWait(w, sampleStream()));
        QVERIFY(waitForEvaluation(w));
        ui::EvaluationPanel& panel = w.evaluationPanel();
        QVERIFY(panel.changeText().isEmpty()); // no change yet
        const double before = cell(panel, 0, 5).toDouble();
        QVERIFY2(before > 0.5, qPrintable(cell(panel, 0, 5)));
        QVERIFY(w.session().lut().clearClass(Colour::Orange) > 0);
        QVERIFY(w.session().evaluation().pending());
        QVERIFY(waitForEvaluation(w));
        const double after = cell(panel, 0, 5).toDouble();
        QVERIFY2(after < before, qPrintable(cell(panel, 0, 5)));
        const QString change = panel.changeText();
        QVERIFY2(change.contains(
                     QString("ball recall %1 → %2")
                         .arg(QString::number(before, 'f', 2), QString::number(after, 'f', 2))),
                 qPrintable(change));
        QVERIFY(panel.findChild<QLabel*>("evaluation.change")->text().contains(change));
        QVERIFY(w.findChild<QLabel*>("scores_change")->text().contains(change));

        // Undo: the recall comes back, and the change says so.
        w.session().undoGroup().undo();
        QVERIFY(waitForEvaluation(w));
        QCOMPARE(cell(panel, 0, 5).toDouble(), before);
        QVERIFY(panel.changeText().contains(
            QString("ball recall %1 → %2")
                .arg(QString::number(after, 'f', 2), QString::number(before, 'f', 2))));
        // The table edit again, and an annotation edit landing while it is being scored: the
        // change is still shown, measured on the annotations as they now are.
        QVERIFY(w.session().lut().clearClass(Colour::Orange) > 0);
        ui::AnnotationsDocument& truth = w.session().annotations();
        FrameAnnotation f3 = *truth.frame("frame_000003.png");
        f3.truth.output<Ball>().clear(); // its ball no longer there: one fewer to find
        QVERIFY(truth.editFrame("frame_000003.png", f3, "no ball"));
        QVERIFY(waitForEvaluation(w));
        const ClassScore balls = w.session().evaluation().report()->scores.of<Ball>();
        const EvaluationScores* scored_before = w.session().evaluation().before();
        QVERIFY(scored_before);
        const ClassScore was = scored_before->of<Ball>();
        QCOMPARE(was.tp + was.fn, balls.tp + balls.fn); // the same annotations on both sides
        QVERIFY2(was.recall() > balls.recall(), qPrintable(panel.changeText()));
        QVERIFY2(panel.changeText().contains("ball recall"), qPrintable(panel.changeText()));
    }

    void annotationEditsAreScoredWithTheDetectionsMade()
    {
        // Frame 29 not done: scored once it is marked done.
        const QString stream = m_dir.filePath("edits");
        copyStream(stream, [](QJsonObject& frames) {
            QJsonObject f29 = frames.value("frame_000029.png").toObject();
            f29["done"] = false;
            frames["frame_000029.png"] = f29;
        });
        MainWindow w;
        w.show();
        QVERIFY(openAndWait(w, stream));
        QVERIFY(waitForEvaluation(w));
        ui::EvaluationScan& scan = w.session().evaluation();
        QCOMPARE(scan.lastFramesRun(), std::size_t(29));
        QCOMPARE(scan.report()->scores.frames, std::size_t(29));
        const auto missedOn17 = [&scan] {
            return std::any_of(scan.failing().begin(), scan.failing().end(), [](const auto& f) {
                return f.index == 17 && f.disagreement.kind == &perceptKind<Ball>() &&
                       f.disagreement.missed == std::vector<std::size_t>{1};
            });
        };
        QVERIFY(!missedOn17());

        // A ball annotated where nothing is: matched again, no frame run again.
        ui::AnnotationsDocument& truth = w.session().annotations();
        FrameAnnotation f17 = *truth.frame("frame_000017.png");
        f17.truth.output<Ball>().push_back({10, 10, 5});
        QVERIFY(truth.editFrame("frame_000017.png", f17, "add ball"));
        QVERIFY(scan.pending());
        QVERIFY(waitForEvaluation(w));
        QVERIFY(missedOn17());
        QCOMPARE(scan.lastFramesRun(), std::size_t(0));
        QVERIFY(!scan.before()); // the detectors did not change
        QVERIFY(w.evaluationPanel().changeText().isEmpty());

        // Marking frame 29 done runs that frame alone.
        FrameAnnotation f29 = *truth.frame("frame_000029.png");
        f29.done = true;
        QVERIFY(truth.editFrame("frame_000029.png", f29, "done"));
        QVERIFY(waitForEvaluation(w));
        QCOMPARE(scan.lastFramesRun(), std::size_t(1));
        QCOMPARE(scan.report()->scores.frames, std::size_t(30));

        // Undo takes the ball back out of the scores.
        w.session().undoGroup().setActiveStack(&truth.undoStack());
        w.session().undoGroup().undo();
        w.session().undoGroup().undo();
        QVERIFY(waitForEvaluation(w));
        QVERIFY(!missedOn17());
        QCOMPARE(scan.report()->scores.frames, std::size_t(29));
    }

    void scoreChangeTextNamesKindsByTheirNouns()
    {
        EvaluationScores a;
        a.of<Ball>() = {91, 0, 9};
        a.of<Goalpost>() = {10, 0, 0};
        EvaluationScores b = a;
        b.of<Ball>() = {97, 0, 3};
        b.of<Goalpost>() = {24, 1, 0};
        QCOMPARE(ui::scoreChangeText(a, b),
                 QString("ball recall 0.91 → 0.97, goalpost precision 1.00 → 0.96"));
        // A change two decimals would hide shows three.
        b = a;
        b.of<Ball>() = {910, 0, 89};
        a.of<Ball>() = {910, 0, 90};
        QCOMPARE(ui::scoreChangeText(a, b), QString("ball recall 0.910 → 0.911"));
        QCOMPARE(ui::scoreChangeText(a, a), QString("no change in the scores"));
    }

private:
    QTemporaryDir m_dir;
};

FIELDSIGHT_TEST_SUITE(TestEvaluationPanel, Widgets)

#include "test_evaluation_panel.moc"
