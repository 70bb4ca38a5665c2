// Video-file streams through OpenCV videoio: random access and the RGB to YCbCr conversion.
#include "support/test_suite.h"
#include "visioncore/io/image_files.h"
#include "visioncore/io/stream_reader.h"

#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>

#include <QtTest>

#include <fstream>

using namespace fieldsight;

namespace {

cv::Scalar bgrOf(int frame)
{
    return cv::Scalar(40 * frame, 100, 220 - 40 * frame);
}

/// The Y, Cb, Cr that a BGR colour converts to (BT.601 full range).
cv::Vec3b yCbCrOf(const cv::Scalar& bgr)
{
    cv::Mat pixel(1, 1, CV_8UC3, bgr), ycrcb;
    cv::cvtColor(pixel, ycrcb, cv::COLOR_BGR2YCrCb);
    const cv::Vec3b v = ycrcb.at<cv::Vec3b>(0, 0);
    return {v[0], v[2], v[1]};
}

bool near(const cv::Vec3b& a, const cv::Vec3b& b, int tolerance)
{
    for (int c = 0; c < 3; ++c)
        if (std::abs(int(a[c]) - int(b[c])) > tolerance)
            return false;
    return true;
}

} // namespace

class TestVideoStream : public QObject
{
    Q_OBJECT

private slots:
    void videoFramesAreRandomlyAccessibleAsYCbCr()
    {
        QTemporaryDir dir;
        const std::string path = dir.filePath("clip.avi").toStdString();
        {
            std::vector<cv::Mat> frames;
            for (int i = 0; i < 6; ++i)
                frames.emplace_back(48, 64, CV_8UC3, bgrOf(i));
            if (Status s = writeVideo(path, "MJPG", 10, frames); !s)
                QSKIP(
                    ("no OpenCV video writer backend for MJPG/AVI: " + s.error().message).c_str());
        }
        auto opened = openStream(path);
        QVERIFY2(opened.ok(), opened.ok() ? "" : opened.error().message.c_str());
        StreamReader& reader = *opened.value();
        QCOMPARE(reader.info().kind, StreamKind::Video);
        QCOMPARE(reader.info().frame_count, std::size_t(6));
        QCOMPARE(reader.info().width, 64);
        QCOMPARE(reader.info().height, 48);
        for (std::size_t i : {4u, 1u, 2u, 5u, 0u}) {
            auto frame = reader.read(i);
            QVERIFY2(frame.ok(), frame.ok() ? "" : frame.error().message.c_str());
            QCOMPARE(frame.value().name, "frame_00000" + std::to_string(i));
            const cv::Vec3b got = frame.value().ycbcr.at<cv::Vec3b>(24, 32);
            const cv::Vec3b want = yCbCrOf(bgrOf(int(i)));
            // JPEG compression moves values by a few levels.
            QVERIFY2(near(got, want, 4), qPrintable(QString("frame %1: %2,%3,%4 vs %5,%6,%7")
                                                        .arg(i)
                                                        .arg(got[0])
                                                        .arg(got[1])
                                                        .arg(got[2])
                                                        .arg(want[0])
                                                        .arg(want[1])
                                                        .arg(want[2])));
        }
        auto beyond = reader.read(6);
        QVERIFY(!beyond.ok());
        QCOMPARE(beyond.error().message, path + ": frame 6 out of range (6 frames)");
    }

    void fileThatIsNoVideoIsAnError()
    {
        QTemporaryDir dir;
        const std::string path = dir.filePath("notes.mp4").toStdString();
        std::ofstream(path) << "not a video";
        auto opened = openStream(path);
        QVERIFY(!opened.ok());
        QVERIFY2(opened.error().message.rfind(path + ": ", 0) == 0, opened.error().message.c_str());
    }
};

FIELDSIGHT_TEST_SUITE(TestVideoStream, None)

#include "test_video_stream.moc"
