// A percept kind in one place, in the window: the fake kind of support/fake_percept.h, added to the
// window's pipeline by this test alone, has a row of its own in the evaluation panel with the
// numbers `eval` gives, and a tool that draws it; what is drawn is scored again.
#include "support/test_suite.h"
#include "support/fake_percept.h"
#include "support/test_files.h"
#include "support/window_waits.h"
#include "ui/adapters/local_path.h"
#include "ui/document/annotations_document.h"
#include "ui/panels/evaluation_panel.h"
#include "ui/tools/annotate_tool.h"
#include "ui/tools/tool_manager.h"

#include <QDir>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QSettings>
#include <QStandardPaths>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QtTest>

using namespace fieldsight;
using namespace fieldsight::test;

namespace {

/// Screen px per image px: image pixel (x, y) is at widget ((x + 0.5) * 2, ...).
constexpr double kSpotZoom = 2;

QPoint spotAt(PointF p)
{
    return QPoint(int((p.x + 0.5) * kSpotZoom), int((p.y + 0.5) * kSpotZoom));
}

QString cell(ui::EvaluationPanel& panel, int row, int column)
{
    const QTableWidgetItem* item = panel.scores().item(row, column);
    return item ? item->text() : QString();
}

/// The TP, FP and FN cells of `row`.
QString counts(ui::EvaluationPanel& panel, int row)
{
    return cell(panel, row, 1) + " " + cell(panel, row, 2) + " " + cell(panel, row, 3);
}

} // namespace

class TestFakePerceptWindow : public QObject
{
    Q_OBJECT

    Pipeline m_pipeline = withFakePercept();
    QTemporaryDir m_dir;

    /// The bundled stream (30 done frames) with a true fake spot near the one the stage sees on
    /// frame 0 and one far from it on frame 1.
    QString copyStream()
    {
        const QString to = m_dir.filePath("stream");
        QDir().mkpath(to);
        for (const QString& file : QDir(sampleStream()).entryList(QDir::Files))
            QFile::copy(sampleStream() + "/" + file, to + "/" + file);
        QFile file(to + "/annotations.json");
        if (!file.open(QIODevice::ReadOnly))
            return {};
        QJsonObject doc = QJsonDocument::fromJson(file.readAll()).object();
        file.close();
        QJsonObject frames = doc.value("frames").toObject();
        const auto add = [&frames](const QString& frame, double x, double y) {
            QJsonObject f = frames.value(frame).toObject();
            f["fake_spots"] = QJsonArray{QJsonObject{{"x", x}, {"y", y}, {"radius", 4}}};
            frames[frame] = f;
        };
        add("frame_000000.png", 42, 31);
        add("frame_000001.png", 200, 200);
        doc["frames"] = frames;
        if (!file.open(QIODevice::WriteOnly | QIODevice::Truncate))
            return {};
        file.write(QJsonDocument(doc).toJson());
        return to;
    }

private slots:
    void initTestCase()
    {
        QStandardPaths::setTestModeEnabled(true);
        QCoreApplication::setOrganizationName("FieldsightTest");
        QCoreApplication::setApplicationName("test_fake_percept_window");
        QSettings().clear();
        QVERIFY(m_dir.isValid());
        QVERIFY2(QFileInfo(sampleStream()).isDir(),
                 qPrintable("the bundled sample stream is missing: " + sampleStream()));
    }

    void theKindIsScoredShownAndDrawn()
    {
        const QString stream = copyStream();
        QVERIFY(!stream.isEmpty());
        MainWindow w(m_pipeline);
        w.resize(1400, 900);
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        QVERIFY(openAndWait(w, stream));
        QVERIFY(waitForEvaluation(w));
        QVERIFY2(w.session().evaluation().problem().isEmpty(),
                 qPrintable(w.session().evaluation().problem()));

        // Its row follows the standard classes': the stage's spot on each of the 30 frames, one
        // of the two true spots near it (as test_fake_percept's eval).
        ui::EvaluationPanel& panel = w.evaluationPanel();
        QCOMPARE(panel.scores().rowCount(), 5);
        QCOMPARE(cell(panel, 4, 0), QString("Fake spots"));
        QCOMPARE(counts(panel, 4), QString("1 29 1"));
        QCOMPARE(cell(panel, 4, 5), QString("0.500"));
        const QString standard = counts(panel, 0) + counts(panel, 1) + counts(panel, 2);

        // A tool for it, named by it; a drag on frame 1 draws a true spot where the stage sees
        // one, one undo step, and the frame is scored again: one more found, one false fewer.
        ui::AnnotateTool* tool = nullptr;
        for (const auto& t : w.tools().tools())
            if (auto* a = qobject_cast<ui::AnnotateTool*>(t.get());
                a && &a->kind() == &perceptKind<FakeSpot>())
                tool = a;
        QVERIFY(tool);
        QCOMPARE(tool->info().name, QString("Fake spots"));
        w.session().stream().setCurrentIndex(1);
        QVERIFY(waitForFrame(w, 1));
        w.view().setZoom(kSpotZoom);
        w.view().setImageOrigin({0, 0});
        w.tools().activate(tool->info().id);
        QUndoStack& undo = w.session().annotations().undoStack();
        const int steps = undo.index();
        const PointF from{kFakeSpotSeen.x, kFakeSpotSeen.y};
        const PointF to{from.x + 3, from.y + 4}; // radius 5
        QTest::mousePress(&w.view(), Qt::LeftButton, {}, spotAt(from));
        QTest::mouseMove(&w.view(), spotAt({from.x + 1, from.y + 2}));
        QTest::mouseMove(&w.view(), spotAt(to));
        QTest::mouseRelease(&w.view(), Qt::LeftButton, {}, spotAt(to));
        QCOMPARE(undo.index(), steps + 1);
        const FrameAnnotation* frame =
            w.session().annotations().frame(ui::toLocalPath(w.session().stream().frameName(1)));
        QVERIFY(frame);
        const std::vector<FakeSpot>& spots = frame->truth.list<FakeSpot>();
        QCOMPARE(spots.size(), std::size_t(2));
        QCOMPARE(spots[1].x, kFakeSpotSeen.x);
        QCOMPARE(spots[1].y, kFakeSpotSeen.y);
        QCOMPARE(spots[1].radius, 5.0);

        QTRY_COMPARE_WITH_TIMEOUT(counts(panel, 4), QString("2 28 1"), 60000);
        QVERIFY(waitForEvaluation(w));
        QCOMPARE(counts(panel, 0) + counts(panel, 1) + counts(panel, 2), standard);
    }
};

FIELDSIGHT_TEST_SUITE(TestFakePerceptWindow, Widgets)

#include "test_fake_percept_window.moc"
