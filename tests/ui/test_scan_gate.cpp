// The whole-stream scans give way while the user steps (issue 33, frames of any size): a step
// holds the stream's scan gate, every scan thread waits at it before its next frame, and once the
// hold ends the scan finishes with the same results as one never held. Times are made long here,
// so nothing depends on how fast the machine is; the waits are counted.
#include "support/test_suite.h"
#include "support/test_files.h"
#include "support/window_waits.h"
#include "ui/document/editing_session.h"
#include "ui/scans/edit_effect_scan.h"
#include "ui/scans/scan_gate.h"
#include "visioncore/services/lut_editing.h"

#include <QTemporaryDir>
#include <QtTest>

using namespace fieldsight;
using namespace fieldsight::test;

namespace {

constexpr std::chrono::milliseconds kGateTestHold{60000};

std::shared_ptr<const ColourLut> gateTestTable()
{
    auto lut = ColourLut::load((sampleStream() + "/default.lut").toStdString());
    return lut ? std::make_shared<const ColourLut>(std::move(lut).value()) : nullptr;
}

/// `lut` with a disc of chroma turned orange: an edit that changes pixels and detections.
std::shared_ptr<const ColourLut> gateTestEdited(const ColourLut& lut)
{
    auto edited = std::make_shared<ColourLut>(lut);
    applyChanges(*edited, changesTo(*edited, cellsInUvDisc(110, 150, 12, 0, 255), Colour::Orange));
    return edited;
}

/// Each frame's effect as text, for comparing two scans.
QStringList gateTestEffects(const ui::EditEffectScan& scan)
{
    QStringList lines;
    for (const FrameEffect& e : scan.effects())
        lines << QStringLiteral("%1 %2 %3 %4 %5 %6 %7")
                     .arg(e.done)
                     .arg(e.unreadable)
                     .arg(e.changed_pixels)
                     .arg(e.unclassified)
                     .arg(e.pixels)
                     .arg(e.delta.appeared())
                     .arg(e.delta.vanished());
    return lines;
}

} // namespace

class TestScanGate : public QObject
{
    Q_OBJECT

    QTemporaryDir m_dir;

private slots:
    void initTestCase() { QCOMPARE(test::startWindowSuite("test_scan_gate", m_dir), QString()); }

    void anOpenGateLetsEveryFrameThroughAtOnce()
    {
        ui::ScanGate gate;
        gate.pass();
        QCOMPARE(gate.waits(), std::uint64_t(0));
        QVERIFY(!gate.held());
        gate.setTimes(kGateTestHold, kGateTestHold);
        gate.hold();
        QVERIFY(gate.held());
        std::atomic<bool> stop{true}; // a scan being stopped does not wait
        gate.pass(&stop);
        QCOMPARE(gate.waits(), std::uint64_t(1));
        gate.release();
        QVERIFY(!gate.held());
    }

    /// An edit's scan started while the gate is held waits before its first frame, and once
    /// the hold ends it finishes with the results of a scan never held.
    void aHeldScanWaitsThenFinishesWithTheSameResults()
    {
        const std::shared_ptr<const ColourLut> lut = gateTestTable();
        QVERIFY(lut);
        const std::shared_ptr<const ColourLut> edited = gateTestEdited(*lut);

        ui::EditEffectScan free_scan;
        free_scan.setThreads(2);
        free_scan.setDelay(0);
        free_scan.setStream(sampleStream(), lut);
        QVERIFY(waitForScan(free_scan));
        free_scan.edited(lut, edited);
        QVERIFY(waitForScan(free_scan));
        const QStringList expected = gateTestEffects(free_scan);
        QVERIFY(expected.join(' ').contains(' ')); // something to compare

        auto gate = std::make_shared<ui::ScanGate>();
        gate->setTimes(kGateTestHold, kGateTestHold);
        ui::EditEffectScan scan;
        scan.setGate(gate);
        scan.setThreads(2);
        scan.setDelay(0);
        scan.setStream(sampleStream(), lut);
        QVERIFY(waitForScan(scan)); // the gate is open: no wait
        QCOMPARE(gate->waits(), std::uint64_t(0));

        gate->hold(); // the user steps
        scan.edited(lut, edited);
        QTRY_VERIFY_WITH_TIMEOUT(gate->waiting() > 0, 10000);
        QTest::qWait(200); // a poll of the scan's progress
        QCOMPARE(scan.framesDone(), std::size_t(0));
        QVERIFY(scan.running());

        gate->release(); // the stepping stopped
        QVERIFY(waitForScan(scan));
        QVERIFY(gate->waits() > 0);
        QCOMPARE(gateTestEffects(scan), expected);
    }

    /// In the session, a step to another frame holds the gate its scans pass; stopping a scan
    /// waiting there (a new edit) does not wait for the hold to end.
    void aStepHoldsTheSessionsScans()
    {
        ui::EditingSession session;
        QVERIFY(
            session.open(copyFolderFiles(sampleStream(), m_dir.filePath("step"), isFrameOrTable)));
        const std::shared_ptr<ui::ScanGate> gate = session.stream().scanGate();
        QVERIFY(gate);
        gate->setTimes(kGateTestHold, kGateTestHold);
        QVERIFY(waitForScan(session.effectScan()));
        QVERIFY(!gate->held());

        session.stream().setCurrentIndex(session.stream().currentIndex());
        QVERIFY(!gate->held()); // the same frame again (a rerun) is no step
        session.stream().setCurrentIndex(1);
        QVERIFY(gate->held());

        ui::EditEffectScan& scan = session.effectScan();
        scan.setDelay(0);
        const std::shared_ptr<const ColourLut> lut = gateTestTable();
        scan.edited(lut, gateTestEdited(*lut));
        QTRY_VERIFY_WITH_TIMEOUT(gate->waiting() > 0, 10000);
        // Opening the stream again stops the waiting scan at once (the hold lasts a minute) and
        // starts the first scan, which waits too.
        QElapsedTimer clock;
        clock.start();
        scan.setStream(session.stream().streamSpec(), lut, scan.streamOptions());
        QVERIFY(clock.elapsed() < kGateTestHold.count() / 2);
        QVERIFY(scan.running());
        QTRY_VERIFY_WITH_TIMEOUT(gate->waiting() > 0, 10000);

        gate->release();
        QVERIFY(waitForScan(scan));
        QCOMPARE(scan.framesDone(), session.stream().frameCount());
    }
};

FIELDSIGHT_TEST_SUITE(TestScanGate, Widgets)
#include "test_scan_gate.moc"
