// A frame's display keeps the pixels the reader made for it instead of a copy (issue 33, frames of
// any size: a copy of a 1280x720 frame is 2.7 MB of fresh pages per step), and yet no output
// shown is ever written over: every read goes into a Frame of its own.
#include "support/test_suite.h"
#include "support/test_files.h"
#include "ui/document/editing_session.h"
#include "ui/worker/read_ahead.h"
#include "visioncore/io/stream_reader.h"

#include <opencv2/core.hpp>

#include <QFile>
#include <QTemporaryDir>
#include <QtTest>

#include <memory>
#include <vector>

using namespace fieldsight;
using namespace fieldsight::test;

class TestDisplayPixels : public QObject
{
    Q_OBJECT

    QTemporaryDir m_dir;

private slots:
    void initTestCase()
    {
        QCOMPARE(test::startWindowSuite("test_display_pixels", m_dir), QString());
    }

    void aFreshFrameIsSharedAndAnyOtherCopied()
    {
        Frame frame;
        frame.ycbcr = cv::Mat(24, 32, CV_8UC3, cv::Scalar(90, 120, 140));
        ui::FrameDisplay shared;
        ui::makeFrameDisplay(frame, nullptr, shared, ui::FramePixels::Share);
        QCOMPARE(shared.ycbcr.data, frame.ycbcr.data);
        ui::FrameDisplay copied;
        ui::makeFrameDisplay(frame, nullptr, copied, ui::FramePixels::Copy);
        QVERIFY(copied.ycbcr.data != frame.ycbcr.data);
        QCOMPARE(cv::norm(copied.ycbcr, frame.ycbcr, cv::NORM_INF), 0.0);
        QCOMPARE(shared.raw, copied.raw);
        QVERIFY(shared.classified.isNull()); // no table: nothing classified
    }

    void noOutputShownIsWrittenOver()
    {
        // Turned frames: the turning reader writes into the Frame it is given, in place.
        const QString folder = copySampleFrames(m_dir.filePath("turned"), 8);
        QFile manifest(folder + "/stream.json");
        QVERIFY(manifest.open(QIODevice::WriteOnly));
        manifest.write(R"({"format": "fieldsight-stream/1", "orientation": 180})");
        manifest.close();

        ui::EditingSession session;
        QVERIFY(session.open(folder));
        ui::StreamDocument& stream = session.stream();
        std::vector<std::shared_ptr<const ui::FrameOutput>> shown;
        // Jumps (read by the worker itself) and steps (read ahead), forward and back.
        for (const std::size_t index : {0u, 5u, 2u, 3u, 4u, 7u, 1u, 6u, 0u, 3u}) {
            stream.setCurrentIndex(index);
            QVERIFY(QTest::qWaitFor(
                [&] {
                    return !stream.waiting() && stream.current() &&
                           stream.current()->index == index;
                },
                20000));
            QVERIFY(stream.current()->error.isEmpty());
            shown.push_back(stream.current());
        }
        const ui::FrameWorker::LoadCounts& counts = stream.frameLoads();
        QVERIFY(counts.read > 0); // some were read by the worker itself
        auto reader = openStream(folder.toStdString(), {});
        QVERIFY(reader.ok());
        for (const auto& output : shown) {
            auto frame = reader.value()->read(output->index);
            QVERIFY(frame.ok());
            QCOMPARE(output->frame.ycbcr.size(), frame.value().ycbcr.size());
            QCOMPARE(cv::norm(output->frame.ycbcr, frame.value().ycbcr, cv::NORM_INF), 0.0);
        }
    }
};

FIELDSIGHT_TEST_SUITE(TestDisplayPixels, Widgets)
#include "test_display_pixels.moc"
