// View > Orientation in the real main window, offscreen: a stream stored upside down is shown
// upright once turned, a LUT tool's click classifies the colour at the upright position, the
// whole-stream scan reads the turned frames, the turn is one undo step that leaves every other
// document's history alone, and "Save to stream" writes stream.json only when asked and never
// into a read-only folder.
#include "support/test_suite.h"
#include "support/test_files.h"
#include "support/window_waits.h"
#include "support/synthetic_frames.h"
#include "support/turned_streams.h"
#include "ui/actions/session_files.h"
#include "ui/adapters/image_adapter.h"
#include "ui/scans/edit_effect_scan.h"
#include "ui/main_window.h"

#include <nlohmann/json.hpp>
#include <opencv2/core.hpp>

#include <QAction>
#include <QSettings>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QtTest>

#include <filesystem>
#include <fstream>
#include <sstream>

using namespace fieldsight;
using fieldsight::test::waitForScan;
using fieldsight::ui::MainWindow;
namespace fs = std::filesystem;

namespace {

constexpr int kTurnedFrames = 3;

std::vector<cv::Mat> scenes()
{
    std::vector<cv::Mat> frames;
    for (int i = 0; i < kTurnedFrames; ++i)
        frames.push_back(test::uprightScene(i));
    return frames;
}

cv::Mat storedHalf(int i)
{
    cv::Mat stored;
    orientImage(test::uprightScene(i), stored, Orientation::Half);
    return stored;
}

bool samePixels(const cv::Mat& a, const cv::Mat& b)
{
    return a.size() == b.size() && a.type() == b.type() && cv::norm(a, b, cv::NORM_INF) == 0;
}

std::string readText(const std::string& path)
{
    std::ifstream in(path, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

/// Waits until the newest request of the stream document is answered.
bool waitFrame(MainWindow& w)
{
    QElapsedTimer clock;
    clock.start();
    while (clock.elapsed() < 10000) {
        if (!w.session().stream().waiting() && w.session().stream().current())
            return true;
        QTest::qWait(2);
    }
    return false;
}

bool open(MainWindow& w, const std::string& stream, const QString& lut = {})
{
    QSignalSpy opened(&w.files(), &ui::SessionFiles::streamOpened);
    w.files().openStream(QString::fromStdString(stream), lut);
    return opened.wait(10000) && opened.front().front().toBool() && waitFrame(w);
}

/// Triggers View > Orientation > `name` ("180", "save", ...).
bool trigger(MainWindow& w, const QString& name)
{
    auto* action = w.findChild<QAction*>("view.orientation." + name);
    if (!action || !action->isEnabled())
        return false;
    action->trigger();
    return waitFrame(w);
}

/// Per frame, the detections the whole-stream scan says appeared after a click that makes the
/// drawn disc's colour orange (at its upright place in frame 0).
std::vector<int> appearedAfterClick(MainWindow& w)
{
    if (!waitForScan(w.session().effectScan()))
        return {};
    w.view().setZoom(1);
    w.view().setImageOrigin({0, 0});
    w.tools().settings().setColour(Colour::Orange);
    w.tools().settings().setTolerance({0, 0, 0});
    w.tools().activate(QStringLiteral("click"));
    QTest::mouseClick(&w.view(), Qt::LeftButton, {}, QPoint(100, 160));
    // The click's edit reaches the scan at once (its quiet time starts): wait for that scan, not
    // for the one that finished before the click.
    if (!w.session().effectScan().running())
        return {};
    if (!waitForScan(w.session().effectScan()))
        return {};
    std::vector<int> appeared;
    for (const FrameEffect& e : w.session().effectScan().effects())
        appeared.push_back(e.delta.appeared());
    return appeared;
}

} // namespace

class TestOrientationGui : public QObject
{
    Q_OBJECT

    QTemporaryDir m_dir;
    std::string m_upright; ///< the scenes as they are
    std::string m_half;    ///< stored upside down, nothing in stream.json says so
    QString m_no_orange;   ///< testLut() without its orange cells

    std::string path(const char* name) const
    {
        return m_dir.filePath(QString::fromLatin1(name)).toStdString();
    }

private slots:
    void initTestCase()
    {
        QCOMPARE(test::startWindowSuite("test_orientation_gui", m_dir), QString());
        m_upright = path("upright");
        m_half = path("half");
        QVERIFY(test::writeTurnedStream(m_upright, scenes(), {Orientation::Upright, {}, {}}));
        QVERIFY(test::writeTurnedStream(m_half, scenes(), {Orientation::Half, {}, {}}));
        ColourLut lut = test::testLut();
        for (std::size_t i = 0; i < ColourLut::kCells; ++i)
            if (lut.cell(i) == Colour::Orange)
                lut.setCell(i, Colour::Unclassified);
        m_no_orange = m_dir.filePath("no_orange.lut");
        QVERIFY(lut.save(m_no_orange.toStdString()));
    }

    void init()
    {
        QSettings().clear();
        ui::LutDocument probe;
        probe.discardRecovery();
    }

    void turningShowsTheUprightPictureAndUndoTurnsBack()
    {
        MainWindow w;
        w.show();
        QVERIFY(QTest::qWaitForWindowActive(&w)); // for the shortcuts
        QVERIFY(open(w, m_half));
        ui::StreamDocument& stream = w.session().stream();
        QCOMPARE(stream.orientation(), Orientation::Upright);
        QVERIFY(samePixels(stream.current()->frame.ycbcr, storedHalf(0)));
        auto* as_stored = w.findChild<QAction*>("view.orientation.0");
        QVERIFY(as_stored && as_stored->isChecked());
        const int lut_steps = w.session().lut().undoStack().count();
        const int settings_steps = w.session().settings().undoStack().count();

        QVERIFY(trigger(w, "180"));
        QCOMPARE(stream.orientation(), Orientation::Half);
        QVERIFY(w.findChild<QAction*>("view.orientation.180")->isChecked());
        // The shown image is the upright picture, pixel for pixel.
        QVERIFY(samePixels(stream.current()->frame.ycbcr, test::uprightScene(0)));
        QCOMPARE(stream.current()->raw, ui::ycbcrToZoomedQImage(test::uprightScene(0), 1));
        QCOMPARE(stream.info().width, 320);
        // The detections are in the upright frame: the disc where it is drawn.
        std::vector<QRectF> found;
        for (const ui::PerceptItem& item : stream.current()->items)
            if (item.bounds.contains(QPointF(100, 160)))
                found.push_back(item.bounds);
        QVERIFY(!found.empty());
        // Offered, not done: nothing is written until Save to stream.
        QVERIFY2(w.lastMessage().contains("Save to stream"), qPrintable(w.lastMessage()));
        QVERIFY(w.findChild<QAction*>("view.orientation.save")->isEnabled());
        QVERIFY(!nlohmann::json::parse(readText(m_half + "/stream.json")).contains("orientation"));

        // Another frame is read turned too.
        stream.setCurrentIndex(2);
        QVERIFY(waitFrame(w));
        QVERIFY(samePixels(stream.current()->frame.ycbcr, test::uprightScene(2)));

        // One undo step on its own stack: Edit > Undo turns it back, the other histories stay.
        QCOMPARE(stream.undoStack().count(), 1);
        QCOMPARE(w.session().undoGroup().activeStack(), &stream.undoStack());
        QTest::keySequence(&w, QKeySequence::Undo);
        QVERIFY(waitFrame(w));
        QCOMPARE(stream.orientation(), Orientation::Upright);
        QVERIFY(as_stored->isChecked());
        QVERIFY(samePixels(stream.current()->frame.ycbcr, storedHalf(2)));
        QCOMPARE(stream.currentIndex(), std::size_t(2));
        QTest::keySequence(&w, QKeySequence::Redo);
        QVERIFY(waitFrame(w));
        QCOMPARE(stream.orientation(), Orientation::Half);
        QVERIFY(samePixels(stream.current()->frame.ycbcr, test::uprightScene(2)));
        QCOMPARE(w.session().lut().undoStack().count(), lut_steps);
        QCOMPARE(w.session().settings().undoStack().count(), settings_steps);

        // A quarter turn: the frame comes on its side, 240 wide.
        QVERIFY(trigger(w, "90"));
        QCOMPARE(stream.current()->frame.ycbcr.cols, 240);
        QCOMPARE(stream.current()->raw.size(), QSize(240, 320));
        QCOMPARE(stream.undoStack().count(), 2);

        // A new stream starts with its own orientation and an empty orientation history.
        QVERIFY(open(w, m_upright));
        QCOMPARE(stream.orientation(), Orientation::Upright);
        QCOMPARE(stream.undoStack().count(), 0);
    }

    void aLutClickClassifiesTheColourAtTheUprightPosition()
    {
        MainWindow w;
        w.show();
        QVERIFY(open(w, m_half, m_no_orange));
        QVERIFY(trigger(w, "180"));
        w.view().setZoom(1);
        w.view().setImageOrigin({0, 0});
        w.tools().settings().setColour(Colour::Pink);
        w.tools().settings().setTolerance({0, 0, 0});
        w.tools().activate(QStringLiteral("click"));
        // At (100, 160) the upright frame shows the orange disc; the stored picture shows field.
        const test::ClassPixel orange = test::pixelFor(Colour::Orange);
        const test::ClassPixel green = test::pixelFor(Colour::Green);
        QCOMPARE(storedHalf(0).at<cv::Vec3b>(160, 100), cv::Vec3b(green.y, green.cb, green.cr));
        QTest::mouseClick(&w.view(), Qt::LeftButton, {}, QPoint(100, 160));
        const ColourLut& table = w.session().lut().table();
        QCOMPARE(table.classify(orange.y, orange.cb, orange.cr), Colour::Pink);
        QCOMPARE(table.classify(green.y, green.cb, green.cr), Colour::Green);

        // The right button picks the class under the cursor, also from the upright frame.
        QVERIFY(waitFrame(w));
        w.tools().settings().setColour(Colour::White);
        QTest::mouseClick(&w.view(), Qt::RightButton, {}, QPoint(100, 160));
        QCOMPARE(w.tools().settings().colour(), Colour::Pink);
    }

    void theWholeStreamScanReadsTheTurnedFrames()
    {
        std::vector<int> upright, turned, stored;
        {
            MainWindow w;
            w.show();
            QVERIFY(open(w, m_upright, m_no_orange));
            upright = appearedAfterClick(w);
        }
        {
            MainWindow w;
            w.show();
            QVERIFY(open(w, m_half, m_no_orange));
            QVERIFY(trigger(w, "180"));
            QCOMPARE(w.session().effectScan().streamOptions().orientation, Orientation::Half);
            turned = appearedAfterClick(w);
        }
        {
            MainWindow w;
            w.show();
            QVERIFY(open(w, m_half, m_no_orange));
            stored = appearedAfterClick(w);
        }
        QCOMPARE(int(upright.size()), kTurnedFrames);
        for (int appeared : upright)
            QVERIFY(appeared >= 1); // the disc is found in every frame once orange is known
        QCOMPARE(turned, upright);
        QVERIFY(stored != upright); // the comparison can fail
    }

    void saveToStreamWritesOnlyWhenAskedAndNeverIntoAReadOnlyFolder()
    {
        const std::string dir = path("to_save");
        QVERIFY(test::writeTurnedStream(dir, scenes(), {Orientation::Half, {}, {}}));
        const std::string manifest = dir + "/stream.json";
        const std::string before = readText(manifest);
        {
            MainWindow w;
            w.show();
            QVERIFY(open(w, dir));
            auto* save = w.findChild<QAction*>("view.orientation.save");
            QVERIFY(save && !save->isEnabled()); // nothing to save yet
            QVERIFY(trigger(w, "180"));
            QCOMPARE(readText(manifest), before);

            // Read-only: refused with a message, nothing written (even as root).
            fs::permissions(dir, fs::perms::owner_read | fs::perms::owner_exec);
            save->trigger();
            fs::permissions(dir, fs::perms::owner_all);
            QVERIFY2(w.lastMessage().contains("read-only"), qPrintable(w.lastMessage()));
            QCOMPARE(readText(manifest), before);
            QVERIFY(w.session().stream().orientationUnsaved());

            save->trigger();
            QVERIFY2(w.lastMessage().contains("Saved orientation 180"),
                     qPrintable(w.lastMessage()));
            QVERIFY(!w.session().stream().orientationUnsaved());
            QVERIFY(!save->isEnabled());
        }
        nlohmann::ordered_json saved = nlohmann::ordered_json::parse(readText(manifest));
        QCOMPARE(saved["orientation"].get<int>(), 180);
        saved.erase("orientation");
        QCOMPARE(saved.dump(), nlohmann::ordered_json::parse(before).dump());

        // Opened again, the stream is upright at once.
        MainWindow w;
        w.show();
        QVERIFY(open(w, dir));
        QCOMPARE(w.session().stream().orientation(), Orientation::Half);
        QVERIFY(w.findChild<QAction*>("view.orientation.180")->isChecked());
        QVERIFY(samePixels(w.session().stream().current()->frame.ycbcr, test::uprightScene(0)));
    }

    void aManifestAnotherWriterChangedIsNotWrittenOverButTheWindowsOwnWritesAre()
    {
        const std::string dir = path("manifest_writers");
        QVERIFY(test::writeTurnedStream(dir, scenes(), {Orientation::Half, {}, {}}));
        const std::string manifest = dir + "/stream.json";
        MainWindow w;
        w.show();
        QVERIFY(open(w, dir));
        // The window's own write of another key (the stream's parameters) is no other writer's.
        auto* params = w.findChild<QAction*>("pipeline.save_params_to_stream");
        QVERIFY(params && params->isEnabled());
        params->trigger();
        QVERIFY2(nlohmann::json::parse(readText(manifest)).contains("params"),
                 readText(manifest).c_str());
        QVERIFY(trigger(w, "180"));
        const Status saved = w.session().stream().saveOrientation();
        QVERIFY2(saved.ok(), saved.ok() ? "" : saved.error().message.c_str());
        QCOMPARE(nlohmann::json::parse(readText(manifest))["orientation"].get<int>(), 180);
        QVERIFY(!w.session().stream().orientationUnsaved());

        // Another program turns it in the file since: not written over, its file as it wrote it.
        QVERIFY(trigger(w, "90"));
        nlohmann::ordered_json other = nlohmann::ordered_json::parse(readText(manifest));
        other["orientation"] = 270;
        {
            std::ofstream out(manifest, std::ios::binary | std::ios::trunc);
            out << other.dump(1);
        }
        const std::string theirs = readText(manifest);
        const Status refused = w.session().stream().saveOrientation();
        QVERIFY(!refused.ok());
        QVERIFY2(refused.error().message.find("changed on disk") != std::string::npos,
                 refused.error().message.c_str());
        QVERIFY2(refused.error().message.find("stream.json") != std::string::npos,
                 refused.error().message.c_str());
        QCOMPARE(readText(manifest), theirs);
        QVERIFY(w.session().stream().orientationUnsaved());
    }
};

FIELDSIGHT_TEST_SUITE(TestOrientationGui, Widgets)

#include "test_orientation_gui.moc"
