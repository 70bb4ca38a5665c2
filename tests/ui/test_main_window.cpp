// The real main window, offscreen, driven as a user would: open a stream, step with the keys,
// toggle layers, skip a stage, edit a parameter, restart with remembered settings, meet a corrupt
// frame. The pipeline has an eighth, fake stage added by this test alone: the window shows its
// layer, its parameter and its timing without any UI change.
#include "support/test_suite.h"
#include "commands/commands.h"
#include "support/test_files.h"
#include "support/fake_stage.h"
#include "support/window_waits.h"
#include "support/synthetic_frames.h"
#include "ui/adapters/image_adapter.h"
#include "ui/adapters/local_path.h"
#include "ui/adapters/overlay_painter.h"
#include "ui/document/bookmarks.h"
#include "ui/recording/frame_recorder.h"
#include "ui/document/samples_document.h"
#include "ui/actions/session_files.h"
#include "ui/main_window.h"
#include "ui/panels/bookmarks_panel.h"
#include "ui/panels/inspector_panel.h"
#include "ui/settings/window_settings.h"
#include "ui/panels/detections_panel.h"
#include "ui/panels/layers_panel.h"
#include "ui/panels/lut_panel.h"
#include "ui/panels/pipeline_panel.h"
#include "ui/stream_navigator/stream_navigator.h"
#include "visioncore/io/lut_import.h"
#include "visioncore/services/lut_building.h"
#include "visioncore/percepts/ball.h"

#include <opencv2/core.hpp>

#include <QDoubleSpinBox>
#include <QFile>
#include <QGroupBox>
#include <QLabel>
#include <QListWidget>
#include <QSettings>
#include <QSignalSpy>
#include <QSlider>
#include <QSpinBox>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QToolButton>
#include <QtTest>

#include <atomic>
#include <chrono>
#include <filesystem>
#include <sstream>
#include <thread>

using namespace fieldsight;
using namespace fieldsight::test;
using fieldsight::ui::MainWindow;

namespace {

/// The view's image region at zoom 1 with the image at the view's top-left corner.
QImage viewImage(MainWindow& w)
{
    w.view().setZoom(1);
    w.view().setImageOrigin({0, 0});
    const auto& out = w.session().stream().current();
    return w.view()
        .grab()
        .toImage()
        .copy(0, 0, out->raw.width(), out->raw.height())
        .convertToFormat(QImage::Format_RGB32);
}

int countDifferent(const QImage& a, const QImage& b, QRect* where = nullptr)
{
    int n = 0;
    QRect box;
    for (int y = 0; y < a.height(); ++y)
        for (int x = 0; x < a.width(); ++x)
            if (a.pixel(x, y) != b.pixel(x, y)) {
                ++n;
                box |= QRect(x, y, 1, 1);
            }
    if (where)
        *where = box;
    return n;
}

/// A live camera stand-in: the sample stream's frames one after another, every 5 ms, for ever,
/// reported as a camera (no frame count, no seeking).
class StandInCamera : public StreamReader
{
public:
    StandInCamera(std::unique_ptr<StreamReader> frames, std::atomic<int>& alive)
        : m_frames(std::move(frames)), m_alive(alive)
    {
        m_info = m_frames->info();
        m_info.path = "camera:stand-in";
        m_info.kind = StreamKind::Camera;
        m_info.frame_count = 0;
        ++m_alive;
    }
    ~StandInCamera() override { --m_alive; }
    const StreamInfo& info() const override { return m_info; }
    std::string frameName(std::size_t index) const override
    {
        return "live_" + std::to_string(index);
    }
    Result<Frame> read(std::size_t) override
    {
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
        auto frame = m_frames->read(m_next % m_frames->info().frame_count);
        if (frame)
            frame.value().name = frameName(m_next);
        ++m_next;
        return frame;
    }

private:
    std::unique_ptr<StreamReader> m_frames;
    std::atomic<int>& m_alive;
    StreamInfo m_info;
    std::size_t m_next = 0;
};

std::size_t liveNumber(const ui::FrameOutput& out)
{
    return std::stoul(out.frame.name.substr(std::string("live_").size()));
}

} // namespace

class TestMainWindow : public QObject
{
    Q_OBJECT

    Pipeline m_pipeline = withFakeStage();
    QTemporaryDir m_dir;

    void copyStream(const QString& to, int frames)
    {
        QDir().mkpath(to);
        QFile::copy(sampleStream() + "/default.lut", to + "/default.lut");
        for (int i = 0; i < frames; ++i) {
            const QString name = QStringLiteral("frame_%1.png").arg(i, 6, 10, QLatin1Char('0'));
            QVERIFY(QFile::copy(sampleStream() + "/" + name, to + "/" + name));
        }
    }

private slots:
    /// A rejected candidate's note (why a stage threw it away) shows in the inspector for the
    /// shape under the pointer, and only for that shape.
    void inspectorShowsWhyACandidateWasRejected()
    {
        ui::FrameOutput out;
        out.frame.ycbcr = cv::Mat(20, 20, CV_8UC3, cv::Scalar(80, 100, 100));
        out.classes = cv::Mat(20, 20, CV_8U, cv::Scalar(0));
        out.raw = QImage(20, 20, QImage::Format_RGB32);
        out.raw.fill(Qt::black);
        DebugDrawing rejected{"ball.rejected", {}, {}};
        rejected.add(DebugShape{ShapeKind::Circle, {{10, 10}}, {220, 20, 60}, 4, false, 1},
                     "radius 4.0 px, not 8.5-20.3 px as its distance wants");
        rejected.add(DebugShape{ShapeKind::Circle, {{3, 3}}, {220, 20, 60}, 2, false, 1});
        out.drawings.push_back(rejected);
        ui::InspectorPanel panel(Pipeline::standard());
        panel.inspect(&out, {14, 10}); // on the first circle's outline
        QVERIFY2(panel.text().contains("as its distance wants"), qPrintable(panel.text()));
        QVERIFY2(panel.text().contains("Rejected balls"), qPrintable(panel.text()));
        panel.inspect(&out, {5, 3}); // on the second, which has no note
        QVERIFY2(panel.text().contains("centre (3, 3)") && !panel.text().contains("distance wants"),
                 qPrintable(panel.text()));
    }

    void initTestCase()
    {
        QCOMPARE(test::startWindowSuite("test_main_window", m_dir), QString());
        QSettings().clear();
    }

    void init() { QSettings().clear(); }

    void theFakeStageAppearsWithoutUiChanges()
    {
        MainWindow w(m_pipeline);
        // Its layer, under its own name and colour, off until chosen; its detections on.
        QTreeWidgetItem* box = w.layersPanel().layerItem("fake.box");
        QVERIFY(box);
        QCOMPARE(box->text(0), QStringLiteral("Fake box"));
        QVERIFY(box->parent());
        QCOMPARE(box->parent()->text(0), QStringLiteral("Fake"));
        QCOMPARE(box->checkState(0), Qt::Unchecked);
        QCOMPARE(box->icon(0).pixmap(16, 16).toImage().pixelColor(8, 8),
                 QColor(kFakeLayerColour.r, kFakeLayerColour.g, kFakeLayerColour.b));
        QTreeWidgetItem* marks = w.layersPanel().layerItem("percepts.fake_marks");
        QVERIFY(marks);
        QCOMPARE(marks->text(0), QStringLiteral("Fake marks"));
        QCOMPARE(marks->checkState(0), Qt::Checked);

        // Its switch, parameters (range, step, unit, description) and time in the pipeline panel.
        QGroupBox* stage = w.pipelinePanel().stageBox("fake");
        QVERIFY(stage);
        QCOMPARE(stage->title(), QStringLiteral("Fake"));
        QVERIFY(stage->isCheckable());
        QVERIFY(stage->isChecked());
        QCOMPARE(stage->toolTip(),
                 QStringLiteral("A test stage: marks one point and fills one box."));
        auto* level = qobject_cast<QDoubleSpinBox*>(w.pipelinePanel().editor("fake.level"));
        QVERIFY(level);
        QCOMPARE(level->value(), 1.5);
        QCOMPARE(level->minimum(), 0.0);
        QCOMPARE(level->maximum(), 10.0);
        QCOMPARE(level->singleStep(), 0.5);
        QVERIFY2(level->toolTip().startsWith("Written into every mark.") &&
                     level->toolTip().contains("Range 0 to 10, default 1.5"),
                 qPrintable(level->toolTip()));
        auto* every = qobject_cast<QSpinBox*>(w.pipelinePanel().editor("fake.every"));
        QVERIFY(every);
        QCOMPARE(every->value(), 1);
        QCOMPARE(every->suffix(), QStringLiteral(" frames"));
        QCOMPARE(every->maximum(), 100);
        auto* time = w.pipelinePanel().findChild<QLabel*>("fake.time");
        QVERIFY(time);

        // Once a frame is shown: the stage's time as the core measured it, its mark's value in
        // the detections.
        w.show();
        QVERIFY(openAndWait(w, sampleStream()));
        const auto& out = w.session().stream().current();
        double ms = -1;
        for (const StageTiming& t : out->result.report.stages)
            if (t.stage == "fake" && t.ran)
                ms = t.ms;
        QVERIFY(ms >= 0);
        QVERIFY2(time->text().startsWith(QString::number(ms, 'f', 3) + " ms (mean "),
                 qPrintable(time->text()));
        QTreeWidgetItem* row = nullptr;
        for (int i = 0; i < w.detectionsPanel().topLevelItemCount(); ++i)
            if (w.detectionsPanel().topLevelItem(i)->text(0) == "Fake marks (1)")
                row = w.detectionsPanel().topLevelItem(i);
        QVERIFY2(row, qPrintable(w.detectionsPanel().topLevelTexts().join(" | ")));
        QCOMPARE(row->childCount(), 1);
        QCOMPARE(row->child(0)->text(0), QStringLiteral("x: 40.0, y: 30.0, value: 1.5"));
    }

    void opensStepsAndJumpsFrameAccurately()
    {
        MainWindow w(m_pipeline);
        w.show();
        QVERIFY(QTest::qWaitForWindowActive(&w));
        QVERIFY(openAndWait(w, sampleStream()));
        QCOMPARE(w.session().stream().frameCount(), std::size_t(30));

        auto reader = openStream(sampleStream().toStdString());
        QVERIFY(reader.ok());
        auto expectFrame = [&](std::size_t index) {
            QVERIFY2(waitForFrame(w, index), qPrintable(QString::number(index)));
            QCOMPARE(w.session().stream().currentIndex(), index);
            QCOMPARE(w.navigator().slider()->value(), int(index));
            auto frame = reader.value()->read(index);
            QVERIFY(frame.ok());
            const cv::Mat& shown = w.view().output()->frame.ycbcr;
            QCOMPARE(shown.size(), frame.value().ycbcr.size());
            QVERIFY(std::equal(shown.datastart, shown.dataend, frame.value().ycbcr.datastart));
            QCOMPARE(w.view().output()->frame.name, frame.value().name);
        };
        expectFrame(0);
        QTest::keyClick(&w, Qt::Key_Right);
        expectFrame(1);
        QTest::keyClick(&w, Qt::Key_Right, Qt::ShiftModifier);
        expectFrame(11);
        QTest::keyClick(&w, Qt::Key_Left);
        expectFrame(10);
        QTest::keyClick(&w, Qt::Key_Right, Qt::ControlModifier);
        expectFrame(29); // +100, clamped to the last frame
        QTest::keyClick(&w, Qt::Key_Home);
        expectFrame(0);
        QTest::keyClick(&w, Qt::Key_End);
        expectFrame(29);
        QTest::keyClick(&w, Qt::Key_Left, Qt::ShiftModifier);
        expectFrame(19);
        w.navigator().slider()->setValue(7);
        expectFrame(7);
    }

    void aSupersededFrameIsDroppedNotQueued()
    {
        MainWindow w(m_pipeline);
        QVERIFY(openAndWait(w, sampleStream()));
        QSignalSpy ready(&w.session().stream(), &ui::StreamDocument::frameReady);
        for (std::size_t i = 1; i < 30; ++i)
            w.session().stream().setCurrentIndex(i); // 29 steps without waiting
        QVERIFY(waitForFrame(w, 29));
        QVERIFY2(ready.count() < 29, qPrintable(QString::number(ready.count())));
        QCOMPARE(w.view().output()->index, std::size_t(29));
    }

    void zoomOneSnapshotEqualsTheHeadlessRender()
    {
        MainWindow w(m_pipeline);
        w.show();
        QVERIFY(openAndWait(w, sampleStream()));
        w.session().stream().setCurrentIndex(4);
        QVERIFY(waitForFrame(w, 4));
        w.layersPanel().setVisibleLayers(selectLayers("all", m_pipeline).value());
        QVERIFY(waitForFrame(w, 4));    // the stage layers shown are drawn
        w.view().setLabelsShown(false); // text labels are the window's own, not the render's
        const QImage shown = viewImage(w);

        const QString dir = m_dir.filePath("render");
        std::ostringstream out, err;
        const cli::Context ctx{m_pipeline, out, err};
        const int status =
            cli::runHeadless("run",
                             {"fieldsight", sampleStream(), "--out", m_dir.filePath("r.json"),
                              "--render", dir, "--layers", "all", "--scale", "1", "--limit", "5"},
                             ctx);
        QVERIFY2(status == 0, err.str().c_str());
        const QImage rendered =
            QImage(dir + "/frame_000004.png").convertToFormat(QImage::Format_RGB32);
        QCOMPARE(rendered.size(), shown.size());
        QCOMPARE(countDifferent(shown, rendered), 0);
    }

    /// A hidden stage layer is not drawn, yet the pixel inspector lists every stage's shapes under
    /// the pointer: while the pointer is on the frame, the frame is run with every layer.
    void theInspectorSeesHiddenLayersUnderThePointer()
    {
        MainWindow w(m_pipeline);
        w.show();
        QVERIFY(openAndWait(w, sampleStream()));
        w.layersPanel().setVisibleLayers({});
        QVERIFY(!w.session().stream().layers().count("fake.box"));
        w.view().setZoom(1);
        w.view().setImageOrigin({0, 0});
        QTest::mouseMove(&w.view(), QPoint(15, 15)); // image pixel (15, 15), in the fake box
        QVERIFY(w.session().stream().layers().count("fake.box"));
        QVERIFY(waitForFrame(w, 0));
        QVERIFY2(w.inspector().text().contains("Fake box #0"), qPrintable(w.inspector().text()));
        QEvent leave(QEvent::Leave);
        QCoreApplication::sendEvent(&w.view(), &leave);
        QVERIFY(!w.session().stream().layers().count("fake.box"));
    }

    void aLayerTogglesExactlyItsPixels()
    {
        MainWindow w(m_pipeline);
        w.show();
        QVERIFY(openAndWait(w, sampleStream()));
        w.view().setLabelsShown(false);
        const auto drawn = [&w](const char* layer) {
            for (const DebugDrawing& d : w.session().stream().current()->drawings)
                if (d.layer == layer)
                    return !d.shapes.empty();
            return false;
        };

        LayerSet layers = ui::LayersPanel::defaultLayers(w.session().stream().pipeline());
        layers.erase("fake.box");
        w.layersPanel().setVisibleLayers(layers);
        QVERIFY(!w.session().stream().waiting());
        QVERIFY(!drawn("fake.box")); // hidden: the core does not draw it
        const QImage without = viewImage(w);
        const std::uint64_t serial = w.session().stream().lastSerial();
        w.layersPanel().layerItem("fake.box")->setCheckState(0, Qt::Checked); // as a click does
        QVERIFY(w.view().visibleLayers().count("fake.box"));
        QCOMPARE(w.session().stream().lastSerial(), serial + 1); // shown: the frame runs again
        QVERIFY(waitForFrame(w, 0));
        QVERIFY(drawn("fake.box"));
        const QImage with = viewImage(w);
        QRect changed;
        // The fake box fills pixels (10, 10) to (19, 19): exactly those change.
        QCOMPARE(countDifferent(without, with, &changed), 100);
        QCOMPARE(changed, QRect(QPoint(10, 10), QPoint(19, 19)));
        const QRgb fill = with.pixel(15, 15);
        QCOMPARE(QColor(fill), ui::toQColor(kFakeLayerColour));
    }

    void skippingAStageRemovesItsDetections()
    {
        MainWindow w(m_pipeline);
        w.show();
        QVERIFY(openAndWait(w, sampleStream()));
        w.view().setLabelsShown(false);
        w.layersPanel().setVisibleLayers({"percepts.fake_marks"});
        QVERIFY(w.detectionsPanel().topLevelTexts().contains("Fake marks (1)"));
        const QImage before = viewImage(w);
        QCOMPARE(QColor(before.pixel(40, 30)), QColor(12, 200, 34));

        w.pipelinePanel().stageBox("fake")->setChecked(false); // the stage's switch
        QVERIFY(!w.session().settings().stageEnabled("fake"));
        QVERIFY(waitForFrame(w, 0));
        for (const QString& row : w.detectionsPanel().topLevelTexts())
            QVERIFY2(!row.startsWith("Fake marks"), qPrintable(row));
        const QImage after = viewImage(w);
        QRect changed;
        QVERIFY(countDifferent(before, after, &changed) > 0);
        QVERIFY(QRect(37, 27, 7, 7).contains(changed)); // only the mark's square went
        QVERIFY(w.session().stream().current()->result.percepts.list<FakeMark>().empty());

        w.pipelinePanel().stageBox("fake")->setChecked(true);
        QVERIFY(waitForFrame(w, 0));
        QCOMPARE(w.session().stream().current()->result.percepts.list<FakeMark>().size(),
                 std::size_t(1));
    }

    void editingAParameterRerunsTheFrame()
    {
        MainWindow w(m_pipeline);
        QVERIFY(openAndWait(w, sampleStream()));
        auto* level = qobject_cast<QDoubleSpinBox*>(w.pipelinePanel().editor("fake.level"));
        QVERIFY(level);
        level->setValue(3.5);
        QVERIFY(waitForFrame(w, 0));
        QCOMPARE(w.session().stream().current()->result.percepts.list<FakeMark>().at(0).value, 3.5);
        QVERIFY(w.session().settings().paramChanged("fake", "level"));

        auto* reset = w.pipelinePanel().findChild<QToolButton*>("fake.level.reset");
        QVERIFY(reset && reset->isEnabled());
        reset->click();
        QVERIFY(waitForFrame(w, 0));
        QCOMPARE(w.session().stream().current()->result.percepts.list<FakeMark>().at(0).value, 1.5);
        QCOMPARE(level->value(), 1.5);
        QVERIFY(!reset->isEnabled());
    }

    void aFaultyStageIsADiagnosticAndTheRestRuns_data()
    {
        QTest::addColumn<int>("fault");
        QTest::addColumn<QString>("message");
        QTest::newRow("throws") << int(FakeStage::kThrows) << "failed on purpose";
        QTest::newRow("NaN") << int(FakeStage::kNotANumber) << "(nan, 30)";
        QTest::newRow("far outside") << int(FakeStage::kFarOutside) << "(10000000, 30)";
    }

    void aFaultyStageIsADiagnosticAndTheRestRuns()
    {
        QFETCH(int, fault);
        QFETCH(QString, message);
        MainWindow w(m_pipeline);
        w.show();
        QVERIFY(QTest::qWaitForWindowActive(&w));
        QVERIFY(openAndWait(w, sampleStream()));
        QVERIFY(w.session().settings().setParam("fake", "fault", fault).ok());
        QVERIFY(waitForFrame(w, 0));
        const auto out = w.session().stream().current();
        QCOMPARE(out->result.diagnostics.size(), std::size_t(1));
        QCOMPARE(out->result.diagnostics[0].stage, std::string("fake"));
        QVERIFY2(QString::fromStdString(out->result.diagnostics[0].message).contains(message),
                 out->result.diagnostics[0].message.c_str());
        QVERIFY(w.detectionsPanel().topLevelTexts().contains("Diagnostics (1)"));
        // Its nonsense never reaches the overlay: the list is there and empty.
        const auto* marks = out->result.percepts.find<FakeMark>();
        QVERIFY(marks && marks->empty());
        // The stages before it still ran: their lists are there.
        QVERIFY(
            w.detectionsPanel().topLevelTexts().filter(QRegularExpression("^Balls \\(")).size() ==
            1);
        QVERIFY(out->result.percepts.find<Ball>());
        w.grab();                           // the overlay paints
        QTest::keyClick(&w, Qt::Key_Right); // and the tool goes on
        QVERIFY(waitForFrame(w, 1));
    }

    void aCorruptFrameIsAnErrorAndSteppingGoesOn()
    {
        const QString stream = m_dir.filePath("corrupt");
        copyStream(stream, 3);
        QFile bad(stream + "/frame_000001.png");
        QVERIFY(bad.open(QIODevice::WriteOnly | QIODevice::Truncate));
        bad.write("\x89PNG\r\n\x1a\n this is not a picture");
        bad.close();

        MainWindow w(m_pipeline);
        w.show();
        QVERIFY(openAndWait(w, stream));
        QVERIFY(w.session().stream().current()->error.isEmpty());
        QTest::keyClick(&w, Qt::Key_Right);
        QVERIFY(waitForFrame(w, 1));
        QVERIFY2(w.session().stream().current()->error.contains("frame_000001.png"),
                 qPrintable(w.session().stream().current()->error));
        QVERIFY(w.detectionsPanel().topLevelTexts().value(0).startsWith("Frame not processed"));
        (void)w.view().grab(); // paints the error, does not crash
        QTest::keyClick(&w, Qt::Key_Right);
        QVERIFY(waitForFrame(w, 2));
        QVERIFY(w.session().stream().current()->error.isEmpty());
        QVERIFY(!w.session().stream().current()->result.percepts.entries().empty());
    }

    void aLiveCameraShowsItsNewestFramesThroughItsOwnDataWrapper()
    {
        std::atomic<int> alive = 0;
        auto frames = openStream(sampleStream().toStdString());
        QVERIFY(frames);
        auto opened = std::make_shared<ui::OpenedStream>();
        opened->spec = QStringLiteral("camera:stand-in");
        opened->lut = std::make_shared<const ColourLut>(
            importLut((sampleStream() + "/default.lut").toStdString()).value());
        opened->source = std::make_shared<ui::FrameSource>();
        auto camera = std::make_unique<StandInCamera>(std::move(frames).value(), alive);
        opened->info = camera->info();
        opened->source->camera =
            std::make_unique<CameraDataWrapper>(std::move(camera), opened->lut);
        const CameraDataWrapper* capture = opened->source->camera.get(); // the session owns it

        MainWindow w(m_pipeline);
        w.show();
        w.session().stream().adopt(std::move(opened));
        QVERIFY(waitForFrame(w, 0));
        QVERIFY2(w.session().stream().current()->error.isEmpty(),
                 qPrintable(w.session().stream().current()->error));
        QVERIFY(w.session().stream().live());
        auto* label = w.navigator().findChild<QLabel*>("frame_label");
        QVERIFY(label);
        QVERIFY2(label->text().contains("live"), qPrintable(label->text()));
        QVERIFY(w.detectionsPanel().topLevelTexts().contains("Fake marks (1)"));

        // Each step shows a newer camera frame: frames that came meanwhile are skipped.
        std::size_t last = liveNumber(*w.session().stream().current());
        for (std::size_t i = 1; i <= 3; ++i) {
            // Wait until the camera has two frames newer than the one shown (frames last + 1 and
            // last + 2 captured): the step must skip the older.
            QTRY_VERIFY(capture->captured() > last + 2);
            QTest::keyClick(&w, Qt::Key_Right);
            QVERIFY(waitForFrame(w, i));
            const std::size_t now = liveNumber(*w.session().stream().current());
            QVERIFY2(now > last + 1, qPrintable(QStringLiteral("%1 after %2").arg(now).arg(last)));
            last = now;
        }
        // Play runs on the live frames.
        w.navigator().setSpeed(0);
        w.navigator().setPlaying(true);
        QTRY_VERIFY(w.session().stream().current() && w.session().stream().current()->index >= 8);
        w.navigator().setPlaying(false);
        QVERIFY(w.session().stream().current()->error.isEmpty());

        // Recording: every frame shown goes into a stream folder, with the LUT in use.
        const QString folder = m_dir.filePath("recorded");
        QTRY_VERIFY(!w.session().stream().waiting()); // play's last frame is in
        QVERIFY(w.recorder().start(folder, *w.session().lut().version()));
        QVERIFY(!w.recorder().start(folder, *w.session().lut().version())); // already recording
        std::vector<cv::Mat> shown;
        for (std::size_t i = 0; i < 3; ++i) {
            const std::uint64_t serial = w.session().stream().lastSerial();
            const std::size_t shown_now = liveNumber(*w.session().stream().current());
            QTRY_VERIFY(capture->captured() > shown_now + 1); // a newer frame is there to take
            QTest::keyClick(&w, Qt::Key_Right);
            QTRY_VERIFY(w.session().stream().current()->serial > serial &&
                        !w.session().stream().waiting());
            shown.push_back(w.session().stream().current()->frame.ycbcr.clone());
        }
        QVERIFY(w.recorder().stop());
        QCOMPARE(w.recorder().frames(), std::size_t(3));
        auto recorded = openStream((folder + "/recording.strm").toStdString());
        QVERIFY2(recorded, recorded ? "" : recorded.error().message.c_str());
        QCOMPARE(recorded.value()->info().frame_count, std::size_t(3));
        for (std::size_t i = 0; i < 3; ++i) {
            auto frame = recorded.value()->read(i);
            QVERIFY(frame);
            QCOMPARE(cv::norm(frame.value().ycbcr, shown[i], cv::NORM_INF), 0.0);
        }
        QVERIFY(importLut((folder + "/default.lut").toStdString()).value() ==
                *w.session().lut().version());
        // A folder that already holds a recording is not written over.
        const auto again = w.recorder().start(folder, *w.session().lut().version());
        QVERIFY(!again && QString::fromStdString(again.error().message).contains("not empty"));

        // Another stream: the camera is closed (on the worker thread).
        QVERIFY(openAndWait(w, sampleStream()));
        QTRY_COMPARE(alive.load(), 0);
    }

    void aBadStreamIsAMessageAndTheOldStreamStays()
    {
        MainWindow w(m_pipeline);
        QVERIFY(openAndWait(w, sampleStream()));
        QSignalSpy opened(&w.files(), &ui::SessionFiles::streamOpened);
        const QString missing = m_dir.filePath("no_such_stream");
        w.files().openStream(missing);
        QVERIFY(opened.wait(5000));
        QCOMPARE(opened.front().front().toBool(), false);
        QVERIFY2(w.lastMessage().contains(missing), qPrintable(w.lastMessage()));
        QCOMPARE(w.session().stream().streamSpec(), sampleStream());
        w.session().stream().setCurrentIndex(3);
        QVERIFY(waitForFrame(w, 3));
    }

    void bookmarksLiveInASidecarBesideTheStream()
    {
        const QString stream = m_dir.filePath("marked");
        copyStream(stream, 5);
        {
            MainWindow w(m_pipeline);
            QVERIFY(openAndWait(w, stream));
            w.session().bookmarks().setBookmark(3, w.session().stream().frameName(3), "ball lost");
            QVERIFY(QFileInfo::exists(stream + "/bookmarks.json"));
        }
        MainWindow w(m_pipeline);
        w.show();
        QVERIFY(QTest::qWaitForWindowActive(&w));
        QVERIFY(openAndWait(w, stream));
        QCOMPARE(w.bookmarksPanel().list().count(), 1);
        QVERIFY(w.bookmarksPanel().list().item(0)->text().contains("ball lost"));
        emit w.bookmarksPanel().list().itemActivated(w.bookmarksPanel().list().item(0));
        QVERIFY(waitForFrame(w, 3));
        QTest::keyClick(&w, Qt::Key_Home);
        QVERIFY(waitForFrame(w, 0));
    }

    void aDamagedSidecarIsSetAsideNotOverwritten()
    {
        // Bookmarks and LUT samples beside the stream that the window cannot read: its first
        // save of each moves the file aside and says where, instead of writing over the work.
        const QString stream = m_dir.filePath("damaged_sidecars");
        copyStream(stream, 3);
        const QByteArray marks = "{\"format\": \"fieldsight-bookmarks/1\", \"bookmarks\": [";
        const QByteArray samples = "{\"format\": \"fieldsight-lut-samples/2\", \"samples\": []}";
        for (const auto& [name, bytes] :
             {std::pair{"bookmarks.json", marks}, std::pair{"lut_samples.json", samples}}) {
            QFile f(stream + "/" + name);
            QVERIFY(f.open(QIODevice::WriteOnly));
            f.write(bytes);
        }
        const auto contents = [&](const QString& name) {
            QFile f(stream + "/" + name);
            return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
        };
        MainWindow w(m_pipeline);
        w.show();
        QVERIFY(QTest::qWaitForWindowActive(&w));
        QVERIFY(openAndWait(w, stream));
        // Both refusals are in the message of opening.
        QVERIFY2(w.lastMessage().contains("bookmarks.json") &&
                     w.lastMessage().contains("lut_samples.json") &&
                     w.lastMessage().count("set aside, not overwritten") == 2,
                 qPrintable(w.lastMessage()));

        w.session().bookmarks().setBookmark(1, w.session().stream().frameName(1), "ball lost");
        QVERIFY2(w.lastMessage().contains("kept as") &&
                     w.lastMessage().contains("bookmarks.json.unreadable"),
                 qPrintable(w.lastMessage()));
        QCOMPARE(contents("bookmarks.json.unreadable"), marks);
        auto back = ui::Bookmarks::load((stream + "/bookmarks.json").toStdString());
        QVERIFY(back.ok());
        QCOMPARE(back.value().list().size(), std::size_t(1));

        ui::SamplesDocument& sampler = w.session().samples();
        QCOMPARE(sampler.samples().samples.size(), std::size_t(0));
        sampler.addRect("frame_000000.png", Colour::Green, QRect(10, 200, 20, 10));
        QCOMPARE(contents("lut_samples.json.unreadable"), samples);
        auto kept = loadLutSamples((stream + "/lut_samples.json").toStdString());
        QVERIFY(kept.ok());
        QCOMPARE(kept.value().samples.size(), std::size_t(1));
        QVERIFY2(w.lastMessage().contains("lut_samples.json.unreadable"),
                 qPrintable(w.lastMessage()));
    }

    void settingsSurviveARestart()
    {
        const LayerSet chosen{"fake.box", "percepts.balls"};
        {
            MainWindow w(m_pipeline);
            w.show();
            QVERIFY(openAndWait(w, sampleStream()));
            w.layersPanel().setVisibleLayers(chosen);
            w.view().setMode(ui::ViewMode::Classified);
            w.navigator().setSpeed(10);
            w.navigator().loopAction()->setChecked(true);
            w.resize(1200, 760);
            w.close(); // saves the settings
        }
        MainWindow w(m_pipeline);
        QCOMPARE(w.view().visibleLayers(), chosen);
        QCOMPARE(w.layersPanel().visibleLayers(), chosen);
        QCOMPARE(w.view().mode(), ui::ViewMode::Classified);
        QCOMPARE(w.navigator().speed(), 10);
        QVERIFY(w.navigator().loopAction()->isChecked());
        QCOMPARE(w.size(), QSize(1200, 760));
        QSignalSpy opened(&w.files(), &ui::SessionFiles::streamOpened);
        w.files().openLastSession(ui::WindowSettings::load().stream,
                                  ui::WindowSettings::load().lut);
        QVERIFY(opened.wait(5000));
        QCOMPARE(QFileInfo(w.session().stream().streamSpec()).canonicalFilePath(),
                 QFileInfo(sampleStream()).canonicalFilePath());
    }

    void aFirstRunOpensTheUsersCopyOfTheSampleNotTheBundledOne()
    {
        const QString bundled = ui::SessionFiles::bundledSampleStream();
        QVERIFY2(!bundled.isEmpty(), "the bundled sample stream is part of the project");
        const QString copy = ui::SessionFiles::sampleStreamCopy();
        QDir(copy).removeRecursively(); // as on a first run
        MainWindow w(m_pipeline);
        w.show();
        QSignalSpy opened(&w.files(), &ui::SessionFiles::streamOpened);
        w.files().openLastSession({}, {});
        QVERIFY(opened.wait(5000));
        const QString shown = QFileInfo(w.session().stream().streamSpec()).canonicalFilePath();
        QCOMPARE(shown, QFileInfo(copy).canonicalFilePath());
        QVERIFY(shown != QFileInfo(bundled).canonicalFilePath());
        QCOMPARE(QDir(copy).entryList(QDir::Files), QDir(bundled).entryList(QDir::Files));
        // A save goes into the copy; the next run keeps that copy as it is.
        QVERIFY(w.session().lut().saveAs(copy + "/mine.lut").ok());
        QCOMPARE(ui::SessionFiles::sampleStreamCopy(), copy);
        QVERIFY(QFileInfo::exists(copy + "/mine.lut"));
        QVERIFY(!QFileInfo::exists(bundled + "/mine.lut"));
    }

    void theLastStreamIsRememberedWhenItOpensNotOnlyOnAQuit()
    {
        const QString other = m_dir.filePath("remembered");
        copyStream(other, 2);
        {
            MainWindow w(m_pipeline);
            w.show();
            QVERIFY(openAndWait(w, other));
        } // gone without closing, as after a crash
        QCOMPARE(QFileInfo(ui::WindowSettings::load().stream).canonicalFilePath(),
                 QFileInfo(other).canonicalFilePath());
    }

    void aFolderNamedInAnotherEncodingKeepsItsBytes()
    {
        // "café ÿ" in Latin-1: bytes that are not UTF-8. The window opens the stream, saves a LUT
        // beside it and, after a restart, reopens it: each at exactly these bytes (issue 10).
        namespace fs = std::filesystem;
        const std::string folder = m_dir.path().toStdString() + "/caf\xe9 \xff";
        fs::create_directories(folder);
        const std::string sample = sampleStream().toStdString();
        for (const char* name : {"frame_000000.png", "frame_000001.png", "default.lut"})
            fs::copy_file(sample + "/" + name, folder + "/" + name);
        const std::string lut = folder + "/venue\xe9.lut";
        {
            MainWindow w(m_pipeline);
            w.show();
            QVERIFY(openAndWait(w, ui::fromLocalPath(folder)));
            QCOMPARE(ui::toLocalPath(w.session().stream().streamSpec()), folder);
            QVERIFY(w.session().lut().saveAs(ui::fromLocalPath(lut)).ok());
            QVERIFY(fs::is_regular_file(lut));
            w.close(); // saves the settings
        }
        MainWindow w(m_pipeline);
        QSignalSpy opened(&w.files(), &ui::SessionFiles::streamOpened);
        w.files().openLastSession(ui::WindowSettings::load().stream,
                                  ui::WindowSettings::load().lut);
        QVERIFY(opened.wait(5000));
        QVERIFY(opened.front().front().toBool());
        QCOMPARE(ui::toLocalPath(w.session().stream().streamSpec()), folder);
    }
};

FIELDSIGHT_TEST_SUITE(TestMainWindow, Widgets)

#include "test_main_window.moc"
