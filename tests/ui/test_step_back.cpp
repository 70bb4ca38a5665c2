// Stepping back through a stream (issue 33, frames of any size): the frames shown lately are kept
// decoded by the frame worker, so a step back to one of them decodes nothing (a 1280x720 PNG takes
// 10+ ms). Counted by where each frame made current came from, not timed.
#include "support/test_suite.h"
#include "support/test_files.h"
#include "ui/document/editing_session.h"

#include <QTemporaryDir>
#include <QtTest>

using namespace fieldsight;
using namespace fieldsight::test;

namespace {

std::uint64_t stepBackLoads(const ui::FrameWorker::LoadCounts& c)
{
    return c.read + c.read_ahead + c.recent;
}

} // namespace

class TestStepBack : public QObject
{
    Q_OBJECT

    QTemporaryDir m_dir;

    /// Shows frame `index` and waits until the worker has made it current (the `loads`-th frame
    /// made current since the stream opened) and answered.
    static bool showFrame(ui::EditingSession& session, std::size_t index, std::uint64_t loads)
    {
        ui::StreamDocument& stream = session.stream();
        stream.setCurrentIndex(index);
        return QTest::qWaitFor(
            [&] {
                return !stream.waiting() && stream.current() && stream.current()->index == index &&
                       stepBackLoads(stream.frameLoads()) >= loads;
            },
            20000);
    }

private slots:
    void initTestCase() { QCOMPARE(test::startWindowSuite("test_step_back", m_dir), QString()); }

    void aStepBackToAFrameShownLatelyDecodesNothing()
    {
        ui::EditingSession session;
        QVERIFY(
            session.open(copyFolderFiles(sampleStream(), m_dir.filePath("back"), isFrameOrTable)));
        const ui::FrameWorker::LoadCounts& counts = session.stream().frameLoads();
        QVERIFY(showFrame(session, 0, 1));
        const std::uint64_t start = stepBackLoads(counts);
        QVERIFY(showFrame(session, 1, start + 1));
        QVERIFY(showFrame(session, 2, start + 2));
        QCOMPARE(stepBackLoads(counts), start + 2);
        const std::uint64_t read = counts.read, ahead = counts.read_ahead;
        QCOMPARE(counts.recent.load(), std::uint64_t(0));

        QVERIFY(showFrame(session, 1, start + 3));
        QVERIFY(showFrame(session, 0, start + 4));
        QCOMPARE(counts.recent.load(), std::uint64_t(2));
        QCOMPARE(counts.read.load(), read); // nothing decoded for the steps back
        QCOMPARE(counts.read_ahead.load(), ahead);
        QCOMPARE(session.stream().current()->frame.name, std::string("frame_000000.png"));

        // Forward again: frame 1 was kept too (the look-ahead may have taken it already).
        QVERIFY(showFrame(session, 1, start + 5));
        QCOMPARE(counts.read.load(), read);
    }
};

FIELDSIGHT_TEST_SUITE(TestStepBack, Widgets)
#include "test_step_back.moc"
