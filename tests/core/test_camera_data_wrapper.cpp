// The live camera's DataWrapper: the newest frame wins (frames that came while the core was busy
// are dropped, not queued), the core runs through it, and a failing or silent camera is an error,
// never a hang. A stand-in camera (a reader with a frame period) replaces the device; a real
// camera:0 is tried when the machine has one.
#include "support/synthetic_frames.h"
#include "visioncore/framework/control_wrapper.h"
#include "visioncore/datawrappers/camera_data_wrapper.h"
#include "visioncore/percepts/ball.h"

#include <QElapsedTimer>
#include <QtTest>

#include <atomic>
#include <chrono>
#include <memory>
#include <thread>

using namespace fieldsight;
using namespace std::chrono_literals;

namespace {

/// A camera stand-in: frame_<i> every `period`, failing after `count` frames. The ball is drawn
/// into every frame so the core has something to find.
class FakeCamera : public StreamReader
{
public:
    FakeCamera(std::chrono::milliseconds period, std::size_t count, std::atomic<int>* alive)
        : m_period(period), m_count(count), m_alive(alive)
    {
        m_info.path = "camera:fake";
        m_info.kind = StreamKind::Camera;
        m_info.width = 320;
        m_info.height = 240;
        if (m_alive)
            ++*m_alive;
    }
    ~FakeCamera() override
    {
        if (m_alive)
            --*m_alive;
    }
    const StreamInfo& info() const override { return m_info; }
    std::string frameName(std::size_t index) const override
    {
        return "frame_" + std::to_string(index);
    }
    Result<Frame> read(std::size_t) override
    {
        std::this_thread::sleep_for(m_period);
        if (m_next >= m_count)
            return Error{"camera:fake: the camera was unplugged"};
        Frame frame;
        frame.ycbcr = test::filledFrame(320, 240, Colour::Unclassified);
        test::fillRect(frame.ycbcr, 0, 60, 319, 239, Colour::Green);
        test::fillCircle(frame.ycbcr, 120.0, 160.0, 9, Colour::Orange);
        frame.name = frameName(m_next);
        ++m_next;
        return frame;
    }

private:
    StreamInfo m_info;
    std::chrono::milliseconds m_period;
    std::size_t m_count;
    std::size_t m_next = 0;
    std::atomic<int>* m_alive;
};

std::shared_ptr<const ColourLut> lut()
{
    return std::make_shared<const ColourLut>(test::testLut());
}

std::size_t frameNumber(const CameraDataWrapper& camera)
{
    return std::stoul(camera.frame().name.substr(std::string("frame_").size()));
}

} // namespace

class TestCameraDataWrapper : public QObject
{
    Q_OBJECT

private slots:
    void theNewestFrameWinsAndOlderOnesAreDropped()
    {
        CameraDataWrapper camera(std::make_unique<FakeCamera>(2ms, 100000, nullptr), lut());
        QVERIFY(camera.latch(2000ms));
        const std::size_t first = frameNumber(camera);
        std::this_thread::sleep_for(60ms); // a slow consumer: about 30 frames come meanwhile
        const std::size_t captured_before = camera.captured();
        QVERIFY(camera.latch(2000ms));
        // The latched frame is at least as new as the newest captured before the latch.
        QVERIFY2(frameNumber(camera) + 1 >= captured_before,
                 qPrintable(QStringLiteral("latched %1, captured %2")
                                .arg(frameNumber(camera))
                                .arg(captured_before)));
        QVERIFY(frameNumber(camera) > first + 5);
        QVERIFY2(camera.dropped() >= 5, qPrintable(QString::number(camera.dropped())));
        // The latched frame stays as it is while capture goes on.
        const std::size_t held = frameNumber(camera);
        std::this_thread::sleep_for(20ms);
        QCOMPARE(frameNumber(camera), held);
    }

    void theCoreRunsThroughIt()
    {
        CameraDataWrapper camera(std::make_unique<FakeCamera>(5ms, 100000, nullptr), lut());
        ControlWrapper core(camera);
        for (int i = 0; i < 3; ++i) {
            QVERIFY(camera.latch(2000ms));
            auto report = core.runFrame();
            QVERIFY2(report, report ? "" : report.error().message.c_str());
            const auto& balls = core.blackboard().percepts.list<Ball>();
            QCOMPARE(balls.size(), std::size_t(1));
            QVERIFY(std::abs(balls[0].x - 120.0) < 1.0);
        }
    }

    void anUnpluggedCameraIsAnErrorNotAHang()
    {
        CameraDataWrapper camera(std::make_unique<FakeCamera>(1ms, 3, nullptr), lut());
        QElapsedTimer clock;
        clock.start();
        Status status;
        for (int i = 0; i < 10 && status; ++i)
            status = camera.latch(2000ms);
        QVERIFY(!status);
        QVERIFY2(status.error().message.find("unplugged") != std::string::npos,
                 status.error().message.c_str());
        QVERIFY(clock.elapsed() < 2000);
        QVERIFY(!camera.latch(10ms)); // and stays an error
    }

    void aSilentCameraTimesOutAndKeepsItsFrame()
    {
        std::atomic<int> alive = 0;
        {
            CameraDataWrapper camera(std::make_unique<FakeCamera>(300ms, 100000, &alive), lut());
            QVERIFY(camera.latch(2000ms));
            const std::size_t held = frameNumber(camera);
            const Status late = camera.latch(20ms);
            QVERIFY(!late);
            QVERIFY(late.error().message.find("within 20 ms") != std::string::npos);
            QCOMPARE(frameNumber(camera), held);
            QCOMPARE(alive.load(), 1);
        }
        QCOMPARE(alive.load(), 0); // the capture thread stopped and released the camera
    }

    void aRealCameraWhenThereIsOne()
    {
        auto reader = openStream("camera:0");
        if (!reader)
            QSKIP("no camera:0 on this machine");
        CameraDataWrapper camera(std::move(reader).value(), lut());
        QVERIFY(camera.latch(3000ms));
        QCOMPARE(camera.image().type(), CV_8UC3);
        QVERIFY(!camera.image().empty());
    }
};

QTEST_APPLESS_MAIN(TestCameraDataWrapper)
#include "test_camera_data_wrapper.moc"
