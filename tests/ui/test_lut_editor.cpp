// The LUT editor in the real main window, offscreen, with simulated mouse and keys: a click and a
// brush stroke change exactly the expected cells, undo restores the bytes and redo re-applies,
// the frame is reclassified, save then load gives the same bytes, and unsaved edits left by a
// crashed session are offered and restored.
#include "support/test_suite.h"
#include "support/window_waits.h"
#include "support/test_files.h"
#include "support/synthetic_frames.h"
#include "ui/actions/session_files.h"
#include "ui/main_window.h"
#include "support/scripted_dialogs.h"
#include "ui/widgets/message_bar.h"
#include "ui/settings/window_settings.h"
#include "ui/panels/lut_panel.h"
#include "ui/dialogs/lut_compare_dialog.h"
#include "ui/panels/uv_plane_panel.h"
#include "ui/stream_navigator/effect_strip.h"
#include "visioncore/services/stream_runner.h"

#include <QCheckBox>
#include <QDir>
#include <QDockWidget>
#include <QPushButton>
#include <QTableWidget>
#include <QSettings>
#include <QSignalSpy>
#include <QSlider>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QtTest>

#include <set>

using namespace fieldsight;
using fieldsight::ui::MainWindow;
using test::sampleStream;
using test::waitForScan;

namespace {

bool waitForLut(MainWindow& w, const std::shared_ptr<const ColourLut>& lut)
{
    QElapsedTimer clock;
    clock.start();
    while (clock.elapsed() < 10000) {
        const auto& out = w.session().stream().current();
        if (!w.session().stream().waiting() && out && w.session().lut().version() == lut)
            return true;
        QTest::qWait(2);
    }
    return false;
}

bool openAndWait(MainWindow& w)
{
    QSignalSpy opened(&w.files(), &ui::SessionFiles::streamOpened);
    w.files().openStream(sampleStream());
    if (!opened.wait(10000) || !opened.front().front().toBool())
        return false;
    return waitForLut(w, w.session().lut().version());
}

/// The frame shown (YCbCr), what a retarget is estimated from.
const cv::Mat* shownFrame(MainWindow& w)
{
    const auto& out = w.session().stream().current();
    return out && !out->frame.ycbcr.empty() ? &out->frame.ycbcr : nullptr;
}

/// Widget position of image pixel `p` at zoom 1 with the image at the view's corner.
QPoint at(QPoint p)
{
    return p;
}

void showPixelsOneToOne(MainWindow& w)
{
    w.view().setZoom(1);
    w.view().setImageOrigin({0, 0});
}

/// The cells where two tables differ.
std::set<std::uint32_t> differences(const ColourLut& a, const ColourLut& b)
{
    std::set<std::uint32_t> cells;
    for (std::uint32_t i = 0; i < ColourLut::kCells; ++i)
        if (a.data()[i] != b.data()[i])
            cells.insert(i);
    return cells;
}

/// The window shown and active (for key shortcuts) on the sample stream.
bool showAndOpen(MainWindow& w)
{
    w.show();
    return QTest::qWaitForWindowActive(&w) && openAndWait(w);
}

/// A large window on the sample stream with the UV plane's dock in front.
bool openWithUvPlane(MainWindow& w)
{
    w.resize(1400, 900);
    if (!showAndOpen(w))
        return false;
    auto* dock = w.findChild<QDockWidget*>("uv_dock");
    if (!dock)
        return false;
    dock->show();
    dock->raise();
    return true;
}

/// Waits until the whole-stream scan has covered every frame.
cv::Vec3b colourAt(MainWindow& w, QPoint p)
{
    return w.session().stream().current()->frame.ycbcr.at<cv::Vec3b>(p.y(), p.x());
}

} // namespace

class TestLutEditor : public QObject
{
    Q_OBJECT

    QTemporaryDir m_dir;

private slots:
    void initTestCase() { QCOMPARE(test::startWindowSuite("test_lut_editor", m_dir), QString()); }

    void init()
    {
        QSettings().clear();
        ui::LutDocument probe;
        probe.discardRecovery();
    }

    void aClickClassifiesExactlyTheToleranceBox()
    {
        MainWindow w;
        QVERIFY(showAndOpen(w));
        showPixelsOneToOne(w);
        const ColourLut before = w.session().lut().table();

        QTest::keyClick(&w, Qt::Key_9); // blue
        QCOMPARE(w.tools().settings().colour(), Colour::Blue);
        w.tools().activate(QStringLiteral("click"));
        w.tools().settings().setTolerance({4, 2, 2});
        const QPoint pixel(40, 200);
        const cv::Vec3b c = colourAt(w, pixel);
        QTest::mouseClick(&w.view(), Qt::LeftButton, {}, at(pixel));

        std::set<std::uint32_t> want;
        for (const std::uint32_t cell : cellsInBox(c[0], c[1], c[2], {4, 2, 2}))
            if (before.cell(cell) != Colour::Blue)
                want.insert(cell);
        QVERIFY(!want.empty());
        QCOMPARE(differences(before, w.session().lut().table()), want);
        for (const std::uint32_t cell : want)
            QCOMPARE(w.session().lut().table().cell(cell), Colour::Blue);
        QVERIFY(w.session().lut().modified());
        QVERIFY(w.isWindowModified());

        // The frame is reclassified with the edited table.
        QVERIFY(waitForLut(w, w.session().lut().version()));
        QCOMPARE(
            Colour(w.session().stream().current()->classes.at<std::uint8_t>(pixel.y(), pixel.x())),
            Colour::Blue);

        // Right-click picks the class under the cursor.
        QTest::keyClick(&w, Qt::Key_1);
        QTest::mouseClick(&w.view(), Qt::RightButton, {}, at(pixel));
        QCOMPARE(w.tools().settings().colour(), Colour::Blue);
    }

    void aBrushStrokeIsOneUndoStepAndUndoRestoresTheBytes()
    {
        MainWindow w;
        QVERIFY(showAndOpen(w));
        showPixelsOneToOne(w);
        const ColourLut before = w.session().lut().table();
        const int steps = w.session().lut().undoStack().count();

        QTest::keyClick(&w, Qt::Key_6); // orange
        w.tools().activate(QStringLiteral("brush"));
        w.tools().settings().setBrushRadius(1);
        w.tools().settings().setTolerance({0, 0, 0});
        const cv::Mat frame = w.session().stream().current()->frame.ycbcr.clone();
        QTest::mousePress(&w.view(), Qt::LeftButton, {}, at({100, 150}));
        QTest::mouseMove(&w.view(), at({104, 150}));
        QTest::mouseMove(&w.view(), at({104, 156}));
        QTest::mouseRelease(&w.view(), Qt::LeftButton, {}, at({104, 156}));
        QCOMPARE(w.session().lut().undoStack().count(), steps + 1);

        // The cells of every pixel the radius-1 brush went over, 100..104 along y 150, then
        // y 150..156 along x 104.
        std::vector<cv::Point> path;
        for (int x = 100; x <= 104; ++x)
            for (const cv::Point& p : brushPixels({x, 150}, 1, frame.size()))
                path.push_back(p);
        for (int y = 150; y <= 156; ++y)
            for (const cv::Point& p : brushPixels({104, y}, 1, frame.size()))
                path.push_back(p);
        std::set<std::uint32_t> want;
        for (const std::uint32_t cell : cellsOfPixels(frame, path))
            if (before.cell(cell) != Colour::Orange)
                want.insert(cell);
        QVERIFY(!want.empty());
        const ColourLut after = w.session().lut().table();
        QCOMPARE(differences(before, after), want);

        QTest::keySequence(&w, QKeySequence::Undo);
        QVERIFY(w.session().lut().table() == before);
        QVERIFY(!w.session().lut().modified());
        QTest::keySequence(&w, QKeySequence::Redo);
        QCOMPARE(w.session().lut().undoStack().index(), steps + 1);
        QVERIFY(w.session().lut().table() == after);

        // Erase takes a painted colour back to unclassified.
        w.tools().activate(QStringLiteral("erase"));
        w.tools().settings().setBrushRadius(0);
        const cv::Vec3b c = frame.at<cv::Vec3b>(150, 102);
        QTest::mouseClick(&w.view(), Qt::LeftButton, {}, at({102, 150}));
        QCOMPARE(w.session().lut().table().classify(c[0], c[1], c[2]), Colour::Unclassified);
    }

    void saveThenLoadGivesTheSameBytes()
    {
        MainWindow w;
        w.show();
        QVERIFY(openAndWait(w));
        showPixelsOneToOne(w);
        w.tools().settings().setColour(Colour::Yellow);
        w.tools().activate(QStringLiteral("wand"));
        w.tools().settings().setTolerance({6, 6, 6});
        QTest::mouseClick(&w.view(), Qt::LeftButton, {}, at({160, 40}));
        QVERIFY(w.session().lut().modified());

        const QString path = m_dir.filePath("venue.lut");
        QVERIFY(w.files().saveLutAs(path));
        QVERIFY(!w.session().lut().modified());
        QVERIFY(!w.isWindowModified());
        auto loaded = ColourLut::load(path.toStdString());
        QVERIFY(loaded);
        QVERIFY(loaded.value() == w.session().lut().table());
        QCOMPARE(w.session().lut().path(), path);

        // Saving where it cannot be written keeps the edits and says so in the window.
        w.tools().activate(QStringLiteral("click"));
        QTest::mouseClick(&w.view(), Qt::LeftButton, {}, at({20, 220}));
        QVERIFY(w.session().lut().modified());
        QVERIFY(!w.files().saveLutAs(m_dir.filePath("missing/folder/x.lut")));
        QVERIFY(w.session().lut().modified());
        QVERIFY2(w.lastMessage().contains("not saved"), qPrintable(w.lastMessage()));
    }

    void unsavedEditsAreOfferedAfterACrash()
    {
        ColourLut edited;
        {
            MainWindow w;
            w.show();
            QVERIFY(openAndWait(w));
            showPixelsOneToOne(w);
            w.session().lut().setAutosaveDelay(50);
            w.tools().settings().setColour(Colour::Pink);
            w.tools().activate(QStringLiteral("click"));
            w.tools().settings().setTolerance({10, 10, 10});
            QTest::mouseClick(&w.view(), Qt::LeftButton, {}, at({60, 60}));
            edited = w.session().lut().table();
            QTRY_VERIFY(w.session().lut().findRecovery().has_value());
            // The window goes away without closing (a crash): the recovery file stays.
        }
        MainWindow w;
        w.show();
        QVERIFY(openAndWait(w));
        auto* recover = w.recoveryBar().findChild<QPushButton*>("accept");
        QVERIFY(recover);
        QVERIFY(recover->isVisible());
        QVERIFY(!(w.session().lut().table() == edited));
        QTest::mouseClick(recover, Qt::LeftButton);
        QVERIFY(w.session().lut().table() == edited);
        QVERIFY(w.session().lut().modified());
        QVERIFY(waitForLut(w, w.session().lut().version()));

        // Once saved, nothing is offered any more.
        QVERIFY(w.files().saveLutAs(m_dir.filePath("recovered.lut")));
        QVERIFY(!w.session().lut().findRecovery());
    }

    void theWholeStreamScanMarksAnUnreadableFrameAndGoesOn()
    {
        // A copy of the sample stream's first five frames with the second cut short.
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        for (int i = 0; i < 5; ++i) {
            const QString frame = QStringLiteral("frame_%1.png").arg(i, 6, 10, QLatin1Char('0'));
            QVERIFY(QFile::copy(sampleStream() + "/" + frame, dir.filePath(frame)));
        }
        QFile cut(dir.filePath("frame_000001.png"));
        QVERIFY(cut.resize(200));
        auto lut = ColourLut::load((sampleStream() + "/default.lut").toStdString());
        QVERIFY(lut);

        ui::EditEffectScan scan;
        scan.setThreads(2);
        scan.setStream(dir.path(), std::make_shared<const ColourLut>(std::move(lut).value()));
        QVERIFY(waitForScan(scan));
        QVERIFY2(scan.error().isEmpty(), qPrintable(scan.error()));
        QCOMPARE(scan.effects().size(), std::size_t(5));
        for (std::size_t i = 0; i < 5; ++i) {
            QVERIFY(scan.effects()[i].done);
            QCOMPARE(scan.effects()[i].unreadable, i == 1);
            QCOMPARE(scan.effects()[i].pixels, i == 1 ? 0u : 320u * 240u);
        }
        QCOMPARE(scan.unreadableFrames(), std::size_t(1));
        QCOMPARE(scan.firstUnreadable(), std::size_t(1));
        QVERIFY(scan.unreadableReason(1).contains("truncated PNG"));
        QVERIFY(scan.unreadableReason(0).isEmpty());

        // The status line says which frame and why.
        QSlider slider(Qt::Horizontal);
        slider.setRange(0, 4);
        ui::EffectStrip strip(scan, slider);
        QVERIFY2(strip.summary().contains("unreadable frame 1: ") &&
                     strip.summary().contains("frame_000001.png"),
                 qPrintable(strip.summary()));
    }

    /// A stage switched off (a settings change, same table) shows on the strip as the detections
    /// it made vanish, frame by frame (the trial: a parameter edit did not update the strip).
    void theEffectStripFollowsAParameterChange()
    {
        MainWindow w;
        QVERIFY(showAndOpen(w));
        ui::EditEffectScan& scan = w.session().effectScan();
        QVERIFY(waitForScan(scan));
        // The last stage that can be switched off and finds something on this stream.
        std::string stage;
        for (const StageDescriptor& d : w.session().pipeline().descriptors())
            if (d.info.skippable)
                stage = d.info.id;
        QVERIFY(!stage.empty());
        QVERIFY(w.session().settings().setStageEnabled(stage, false));
        QVERIFY(QTest::qWaitFor([&] { return scan.running() || scan.showsEdit(); }, 5000));
        QVERIFY(waitForScan(scan));
        QVERIFY(scan.showsEdit());
        QVERIFY(scan.showsSettingsChange());
        long long vanished = 0;
        for (const FrameEffect& e : scan.effects())
            for (const KindDelta& k : e.delta.kinds) {
                vanished += k.vanished;
                QCOMPARE(int(k.appeared), 0);
            }
        QVERIFY(vanished > 0);
        const QString summary = w.timeline().effectStrip().summary();
        QVERIFY2(summary.startsWith("Last parameter change"), qPrintable(summary));
        QVERIFY2(summary.contains(QStringLiteral("\u2212")), qPrintable(summary));
    }

    void theEffectStripCountsWhatAnEditChangedOnEveryFrame()
    {
        MainWindow w;
        QVERIFY(showAndOpen(w));
        ui::EditEffectScan& scan = w.session().effectScan();
        QVERIFY(waitForScan(scan)); // the first scan records every frame's detections
        QVERIFY(!scan.showsEdit());
        QCOMPARE(scan.effects().size(), w.session().stream().frameCount());

        // A known edit: a field pixel's box becomes pink.
        showPixelsOneToOne(w);
        const ColourLut before = w.session().lut().table();
        w.tools().settings().setColour(Colour::Pink);
        w.tools().activate(QStringLiteral("click"));
        w.tools().settings().setTolerance({10, 6, 6});
        QTest::mouseClick(&w.view(), Qt::LeftButton, {}, at(QPoint(160, 220)));
        QVERIFY(waitForScan(scan));
        QVERIFY(scan.showsEdit());
        const ColourLut after = w.session().lut().table();
        QCOMPARE(scan.changedCells(), differences(before, after).size());

        // Every frame's count, recomputed here pixel by pixel.
        auto reader = openStream(sampleStream().toStdString());
        QVERIFY(reader);
        std::size_t frames_changed = 0;
        for (std::size_t i = 0; i < scan.effects().size(); ++i) {
            auto frame = reader.value()->read(i);
            QVERIFY(frame);
            const cv::Mat& px = frame.value().ycbcr;
            std::uint32_t changed = 0;
            std::uint32_t unclassified = 0;
            for (int y = 0; y < px.rows; ++y)
                for (int x = 0; x < px.cols; ++x) {
                    const cv::Vec3b c = px.at<cv::Vec3b>(y, x);
                    changed +=
                        before.classify(c[0], c[1], c[2]) != after.classify(c[0], c[1], c[2]);
                    unclassified += after.classify(c[0], c[1], c[2]) == Colour::Unclassified;
                }
            const ui::FrameEffect& e = scan.effects()[i];
            QVERIFY(e.done);
            QCOMPARE(e.changed_pixels, changed);
            QCOMPARE(e.unclassified, unclassified);
            frames_changed += changed > 0;
        }
        QVERIFY(frames_changed > 0);
        QVERIFY(w.timeline().effectStrip().summary().contains(QString::number(frames_changed)));

        // Erasing every orange cell makes every ball the previous table found vanish.
        auto input = openStreamInput(sampleStream().toStdString(), "");
        QVERIFY(input);
        input.value().lut = std::make_shared<const ColourLut>(after);
        auto run = runStream(input.value(), firstFrames(scan.effects().size()), 1);
        QVERIFY(run);
        std::vector<std::uint32_t> orange;
        for (std::uint32_t i = 0; i < ColourLut::kCells; ++i)
            if (after.cell(i) == Colour::Orange)
                orange.push_back(i);
        QVERIFY(!orange.empty());
        w.session().lut().edit("erase orange", changesTo(after, orange, Colour::Unclassified));
        QVERIFY(waitForScan(scan));
        int balls = 0;
        for (const FrameResult& r : run.value().frames) {
            const int n = int(r.percepts.list<Ball>().size());
            QCOMPARE(scan.effects()[r.index].delta.of("balls").vanished, n);
            QCOMPARE(scan.effects()[r.index].delta.of("balls").appeared, 0);
            balls += n;
        }
        QVERIFY(balls > 0);
        // The status line names the kind as before the delta was keyed by kind: "−3 ball".
        QVERIFY2(
            w.timeline().effectStrip().summary().contains(QStringLiteral("−%1 ball").arg(balls)),
            qPrintable(w.timeline().effectStrip().summary()));

        // A click on the strip goes to that frame.
        ui::EffectStrip& strip = w.timeline().effectStrip();
        const int x = strip.width() * 3 / 4;
        const long long target = strip.frameAt(x);
        QVERIFY(target > 0);
        QTest::mouseClick(&strip, Qt::LeftButton, {}, QPoint(x, strip.height() / 2));
        QCOMPARE((long long)w.session().stream().currentIndex(), target);
    }

    void paintingInTheUvPlaneChangesTheCellsUnderTheBrush()
    {
        MainWindow w;
        QVERIFY(openWithUvPlane(w));
        ui::UvPlanePanel& uv = w.uvPanel();
        uv.setYLevels(100, 131); // Y cells 50..65
        ui::UvCanvas& canvas = uv.canvas();
        QCOMPARE(canvas.yLow(), 50);
        QCOMPARE(canvas.yHigh(), 65);
        QTRY_VERIFY(canvas.isVisible() && canvas.width() >= 120);

        // Zoomed in around the stroke: cells keep their place under the cursor.
        const QPointF anchor = canvas.cellCentre(42, 90);
        canvas.zoomBy(3, anchor);
        QCOMPARE(canvas.zoom(), 3.0);
        QVERIFY((canvas.cellCentre(42, 90) - anchor).manhattanLength() < 1.0);
        QCOMPARE(*canvas.cellAt(canvas.cellCentre(40, 90)), QPoint(40, 90));

        const ColourLut before = w.session().lut().table();
        w.tools().settings().setColour(Colour::Orange);
        w.tools().activate(QStringLiteral("brush"));
        w.tools().settings().setBrushRadius(2);
        const int undo_steps = w.session().lut().undoStack().count();
        QTest::mousePress(&canvas, Qt::LeftButton, {}, canvas.cellCentre(40, 90).toPoint());
        QTest::mouseMove(&canvas, canvas.cellCentre(42, 90).toPoint());
        QTest::mouseMove(&canvas, canvas.cellCentre(44, 90).toPoint());
        QTest::mouseRelease(&canvas, Qt::LeftButton, {}, canvas.cellCentre(44, 90).toPoint());
        QCOMPARE(w.session().lut().undoStack().count(), undo_steps + 1); // one stroke, one step

        // Every cell within 2 cells of the path (40..44, 90), at Y cells 50..65, not already
        // orange.
        std::set<std::uint32_t> expected;
        for (int y = 50; y <= 65; ++y)
            for (int cb = 0; cb < 128; ++cb)
                for (int cr = 0; cr < 128; ++cr) {
                    bool under = false;
                    for (int k = 40; k <= 44; ++k)
                        under |= (cb - k) * (cb - k) + (cr - 90) * (cr - 90) <= 4;
                    const auto cell = std::uint32_t((y << 14) | (cb << 7) | cr);
                    if (under && before.cell(cell) != Colour::Orange)
                        expected.insert(cell);
                }
        QVERIFY(!expected.empty());
        QCOMPARE(differences(before, w.session().lut().table()), expected);
        for (std::uint32_t cell : expected)
            QCOMPARE(w.session().lut().table().cell(cell), Colour::Orange);
        w.session().lut().undoStack().undo();
        QVERIFY(w.session().lut().table() == before);
    }

    void aUvSelectionLightsUpItsPixelsAndTheImageToolItsCells()
    {
        MainWindow w;
        QVERIFY(openWithUvPlane(w));
        ui::UvCanvas& canvas = w.uvPanel().canvas();
        QTRY_VERIFY(canvas.isVisible() && canvas.width() >= 120);
        w.uvPanel().setYLevels(0, 255);

        // UV -> image: right-drag over the cells of a field pixel's colour.
        showPixelsOneToOne(w);
        const cv::Vec3b field = colourAt(w, QPoint(160, 220));
        const int cb = field[1] >> 1, cr = field[2] >> 1;
        QTest::mousePress(&canvas, Qt::RightButton, {},
                          canvas.cellCentre(cb - 1, cr - 1).toPoint());
        QTest::mouseMove(&canvas, canvas.cellCentre(cb + 1, cr + 1).toPoint());
        QTest::mouseRelease(&canvas, Qt::RightButton, {},
                            canvas.cellCentre(cb + 1, cr + 1).toPoint());
        QVERIFY(canvas.selection().has_value());
        const QImage lit = w.view().highlight("uv_selection");
        QVERIFY(!lit.isNull());
        const cv::Mat& px = w.session().stream().current()->frame.ycbcr;
        int expected = 0, shown = 0;
        for (int y = 0; y < px.rows; ++y)
            for (int x = 0; x < px.cols; ++x) {
                const cv::Vec3b c = px.at<cv::Vec3b>(y, x);
                const bool in = std::abs((c[1] >> 1) - cb) <= 1 && std::abs((c[2] >> 1) - cr) <= 1;
                expected += in;
                shown += qAlpha(lit.pixel(x, y)) > 0;
                if (in != (qAlpha(lit.pixel(x, y)) > 0))
                    QFAIL(qPrintable(QString("pixel %1,%2 wrongly lit").arg(x).arg(y)));
            }
        QVERIFY(expected > 100);
        QCOMPARE(shown, expected);

        // Image -> UV: hovering with the click tool outlines the cells a click would change,
        // highlights the pixels, and counts the cells taken from another class.
        const ColourLut before_preview = w.session().lut().table();
        const int steps_before_preview = w.session().lut().undoStack().count();
        w.tools().settings().setColour(Colour::Pink);
        w.tools().activate(QStringLiteral("click"));
        w.tools().settings().setTolerance({6, 3, 3});
        QTest::mouseMove(&w.view(), at(QPoint(160, 220)));
        QTRY_VERIFY(!w.tools().preview().changes.empty());
        const auto cells = cellsInBox(field[0], field[1], field[2], {6, 3, 3});
        std::size_t green = 0;
        for (std::uint32_t c : cells)
            green += w.session().lut().table().cell(c) == Colour::Green;
        QCOMPARE(w.tools().preview().changes.size(), cells.size());
        QVERIFY(green > 0); // a field pixel's box is mostly green already
        QVERIFY2(w.tools().preview().text.contains(QString::number(green) + " green"),
                 qPrintable(w.tools().preview().text));
        QVERIFY(qAlpha(w.view().highlight("preview").pixel(160, 220)) > 0);
        // A preview edits nothing: the table, its undo stack and its saved state are as they
        // were before the mouse came, though the preview would take green cells.
        QCOMPARE(differences(before_preview, w.session().lut().table()), std::set<std::uint32_t>());
        QCOMPARE(w.session().lut().undoStack().count(), steps_before_preview);
        QVERIFY(!w.session().lut().modified());
    }

    void comparingTwoKnownTablesListsTheRightCellsAndMergesByClass()
    {
        MainWindow w;
        QVERIFY(showAndOpen(w));
        const ColourLut here = w.session().lut().table();
        // The other table: 5 orange cells become pink, 3 unclassified cells become yellow, and
        // 2 green cells become unclassified.
        ColourLut other = here;
        std::vector<std::uint32_t> orange, empty, green;
        for (std::uint32_t i = 0; i < ColourLut::kCells; ++i) {
            if (here.cell(i) == Colour::Orange && orange.size() < 5)
                orange.push_back(i);
            else if (here.cell(i) == Colour::Unclassified && empty.size() < 3)
                empty.push_back(i);
            else if (here.cell(i) == Colour::Green && green.size() < 2)
                green.push_back(i);
        }
        QCOMPARE(orange.size() + empty.size() + green.size(), std::size_t(10));
        for (std::uint32_t c : orange)
            other.setCell(c, Colour::Pink);
        for (std::uint32_t c : empty)
            other.setCell(c, Colour::Yellow);
        for (std::uint32_t c : green)
            other.setCell(c, Colour::Unclassified);
        const QString path = m_dir.filePath("other.lut");
        QVERIFY(other.save(path.toStdString()));

        ui::LutCompareDialog* dialog = w.files().compareLut(path);
        QVERIFY(dialog);
        using Pair = std::pair<Colour, Colour>;
        const std::map<Pair, std::size_t> expected = {{{Colour::Unclassified, Colour::Yellow}, 3},
                                                      {{Colour::Green, Colour::Unclassified}, 2},
                                                      {{Colour::Orange, Colour::Pink}, 5}};
        QCOMPARE(dialog->pairs(), expected);
        auto* table = dialog->findChild<QTableWidget*>("compare_table");
        QCOMPARE(table->rowCount(), 3);

        // Choosing a row outlines exactly its cells in the UV plane.
        QSignalSpy chosen(dialog, &ui::LutCompareDialog::cellsChosen);
        for (int row = 0; row < 3; ++row)
            if (table->item(row, 1)->text() == "pink")
                table->selectRow(row);
        QCOMPARE(chosen.count(), 1);
        const auto cells = chosen.front().front().value<std::vector<std::uint32_t>>();
        QCOMPARE(std::set<std::uint32_t>(cells.begin(), cells.end()),
                 std::set<std::uint32_t>(orange.begin(), orange.end()));

        // Merging pink only: the 5 cells, all taken from orange (conflicts), as one undo step.
        dialog->setMergeClasses({Colour::Pink});
        QVERIFY(dialog->mergePreview().contains("5 cells; 5 of them"));
        dialog->setMergeKeepsOthers(true);
        QVERIFY(dialog->mergePreview().contains("nothing"));
        dialog->setMergeKeepsOthers(false);
        QVERIFY(dialog->merge());
        for (std::uint32_t c : orange)
            QCOMPARE(w.session().lut().table().cell(c), Colour::Pink);
        QCOMPARE(differences(here, w.session().lut().table()),
                 std::set<std::uint32_t>(orange.begin(), orange.end()));
        QCOMPARE(dialog->pairs().size(), std::size_t(2)); // the pink row is gone
        w.session().lut().undoStack().undo();
        QVERIFY(w.session().lut().table() == here);

        // A table that cannot be read is a message in the window, no dialog.
        QFile bad(m_dir.filePath("bad.lut"));
        QVERIFY(bad.open(QIODevice::WriteOnly));
        bad.write("short");
        bad.close();
        QVERIFY(!w.files().compareLut(bad.fileName()));
        QVERIFY(w.lastMessage().contains("bad.lut"));
    }

    void retargetingMovesTheGreenOntoAFieldUnderNewLight()
    {
        MainWindow w;
        QVERIFY(showAndOpen(w));
        const ColourLut lab = w.session().lut().table();
        std::size_t samples = 0;
        const ColourShift none = w.session().lut().estimateRetarget(shownFrame(w), &samples);
        QCOMPARE(samples, std::size_t(320 * (240 - 160)));
        // The lab's own frame: the table fits it, the estimate is small.
        QVERIFY(std::abs(none.y) <= 12 && std::abs(none.cb) <= 6 && std::abs(none.cr) <= 6);

        // The same table moved away by a known shift is brought back close to where it was.
        const ColourShift away{-20, 8, -8};
        QVERIFY(w.session().lut().retarget(away));
        const ColourShift back = w.session().lut().estimateRetarget(shownFrame(w));
        QVERIFY2(std::abs(back.y - (none.y + 20)) <= 2 && std::abs(back.cb - (none.cb - 8)) <= 2 &&
                     std::abs(back.cr - (none.cr + 8)) <= 2,
                 qPrintable(QString("%1 %2 %3").arg(back.y).arg(back.cb).arg(back.cr)));
        const int steps = w.session().lut().undoStack().count();
        QVERIFY(w.session().lut().retarget(back));
        QCOMPARE(w.session().lut().undoStack().count(), steps + 1);
        // Green is where the field is again: most of the bottom third classifies green.
        QVERIFY(waitForLut(w, w.session().lut().version()));
        const cv::Mat& classes = w.session().stream().current()->classes;
        int green = 0;
        for (int y = 160; y < 240; ++y)
            for (int x = 0; x < 320; ++x)
                green += classes.at<std::uint8_t>(y, x) == std::uint8_t(Colour::Green);
        int green_lab = 0;
        const cv::Mat& px = w.session().stream().current()->frame.ycbcr;
        for (int y = 160; y < 240; ++y)
            for (int x = 0; x < 320; ++x) {
                const cv::Vec3b c = px.at<cv::Vec3b>(y, x);
                green_lab += lab.classify(c[0], c[1], c[2]) == Colour::Green;
            }
        QVERIFY2(green > green_lab * 8 / 10,
                 qPrintable(QString("%1 of %2").arg(green).arg(green_lab)));
        w.session().lut().undoStack().undo();
        w.session().lut().undoStack().undo();
        QVERIFY(w.session().lut().table() == lab);
    }

    void sampleRegionsAreKeptBesideTheStreamAndBuildTheTable()
    {
        // A copy of a bundled stream: the samples file is written beside it.
        const QString copy = m_dir.filePath("lab2_copy");
        QDir().mkpath(copy);
        const QString source = QString::fromStdString(test::sampleStreamsDir() + "/lab2");
        for (const QString& f : QDir(source).entryList(QDir::Files))
            QVERIFY(QFile::copy(source + "/" + f, copy + "/" + f));
        MainWindow w;
        w.show();
        QVERIFY(QTest::qWaitForWindowActive(&w));
        QSignalSpy opened(&w.files(), &ui::SessionFiles::streamOpened);
        w.files().openStream(copy);
        QVERIFY(opened.wait(10000));
        QVERIFY(waitForLut(w, w.session().lut().version()));
        showPixelsOneToOne(w);
        ui::SamplesDocument& sampler = w.session().samples();
        QCOMPARE(sampler.path(), copy + "/lut_samples.json");

        // A drag with the Sample tool marks a rectangle of the class.
        QTest::keyClick(&w, Qt::Key_S);
        QCOMPARE(w.tools().active().info().id, QStringLiteral("sample"));
        w.tools().settings().setColour(Colour::Green);
        QTest::mousePress(&w.view(), Qt::LeftButton, {}, at(QPoint(100, 200)));
        QTest::mouseMove(&w.view(), at(QPoint(120, 215)));
        QTest::mouseMove(&w.view(), at(QPoint(140, 230)));
        QTest::mouseRelease(&w.view(), Qt::LeftButton, {}, at(QPoint(140, 230)));
        QCOMPARE(sampler.samples().samples.size(), std::size_t(1));
        const LutSample& sample = sampler.samples().samples.front();
        QCOMPARE(sample.colour, Colour::Green);
        QCOMPARE(sample.frame, w.session().stream().current()->frame.name);
        const std::vector<cv::Point> corners = {{100, 200}, {140, 200}, {140, 230}, {100, 230}};
        QCOMPARE(sample.polygon, corners);
        auto saved = loadLutSamples(sampler.path().toStdString());
        QVERIFY(saved);
        QCOMPARE(saved.value().samples.size(), std::size_t(1));
        sampler.undoStack().undo();
        QCOMPARE(loadLutSamples(sampler.path().toStdString()).value().samples.size(),
                 std::size_t(0));
        sampler.undoStack().redo();
        QCOMPARE(loadLutSamples(sampler.path().toStdString()).value().samples.size(),
                 std::size_t(1));

        // Built with the annotations, in the background; nothing changes until the user has
        // seen what each way would change and chosen one: replace, only unclassified, cancel.
        auto expected = ui::SamplesDocument::buildTable(copy.toStdString(), sampler.samples(), true,
                                                        nullptr, nullptr, nullptr);
        QVERIFY(expected);
        const ColourLut before = w.session().lut().table();
        const int steps = w.session().lut().undoStack().count();
        w.findChild<QCheckBox*>("samples.annotations")->setChecked(true);
        test::ScriptedDialogs dialogs;
        QSignalSpy built(&sampler, &ui::SamplesDocument::built);
        QSignalSpy ready(&sampler, &ui::SamplesDocument::buildReady);

        dialogs.choices = {-1};
        w.lutPanel().buildFromSamples();
        QVERIFY(ready.wait(20000));
        QVERIFY(w.session().lut().table() == before);
        QCOMPARE(w.session().lut().undoStack().count(), steps);
        QVERIFY(!sampler.hasBuild());
        QCOMPARE(dialogs.asked.count(QStringLiteral("Build from samples")), 1);
        const QString shown = dialogs.texts_asked.back();
        const LutDiff replace = diffLuts(before, expected.value().table);
        QVERIFY2(shown.contains(QLocale().toString(qulonglong(replace.cells.size())) + " cells"),
                 qPrintable(shown));
        QVERIFY2(shown.contains("green +"), qPrintable(shown));
        QVERIFY2(shown.contains("pixels change class"), qPrintable(shown));

        dialogs.choices = {1};
        w.lutPanel().buildFromSamples();
        QVERIFY(built.wait(20000));
        QVERIFY2(built.back().front().toBool(), qPrintable(built.back().back().toString()));
        QVERIFY(w.session().lut().table() == expected.value().table);
        QCOMPARE(w.session().lut().undoStack().count(), steps + 1);
        QCOMPARE(sampler.ambiguous().size(), expected.value().ambiguous.size());
        w.session().lut().undoStack().undo();
        QVERIFY(w.session().lut().table() == before);

        // Only unclassified cells: every cell the table had keeps its class.
        dialogs.choices = {0};
        w.lutPanel().buildFromSamples();
        QVERIFY(built.wait(20000));
        const ColourLut& merged = w.session().lut().table();
        std::size_t kept = 0;
        std::size_t filled = 0;
        for (std::size_t i = 0; i < ColourLut::kCells; ++i) {
            if (before.data()[i] != 0) {
                QCOMPARE(merged.data()[i], before.data()[i]);
                ++kept;
            } else {
                QCOMPARE(merged.data()[i], expected.value().table.data()[i]);
                filled += merged.data()[i] != 0;
            }
        }
        QVERIFY(kept > 0);
        QVERIFY(filled > 0);
        QVERIFY(!(merged == expected.value().table));
        w.session().lut().undoStack().undo();

        // A window opened later finds the samples again.
        MainWindow again;
        QSignalSpy reopened(&again.files(), &ui::SessionFiles::streamOpened);
        again.files().openStream(copy);
        QVERIFY(reopened.wait(10000));
        QCOMPARE(again.session().samples().samples().samples.size(), std::size_t(1));
    }
};

FIELDSIGHT_TEST_SUITE(TestLutEditor, Widgets)

#include "test_lut_editor.moc"
