// Each stage on small synthetic frames whose correct answer is known.
#include "stages/common/line_fit.h"
#include "stages/common/ransac.h"
#include "support/synthetic_frames.h"
#include "visioncore/control_wrapper.h"

#include <QtTest>

#include <cmath>

using namespace fieldsight;
using test::drawLine;
using test::fillCircle;
using test::fillRect;

namespace {

class FrameData : public DataWrapper
{
public:
    explicit FrameData(cv::Mat image, Horizon horizon = {})
        : m_image(std::move(image)), m_lut(test::testLut()), m_horizon(horizon)
    {
    }
    const cv::Mat& image() const override { return m_image; }
    Horizon kinematicHorizon() const override { return m_horizon; }
    const ColourLut& lut() const override { return m_lut; }

private:
    cv::Mat m_image;
    ColourLut m_lut;
    Horizon m_horizon;
};

/// Sky above row `edge`, field below.
cv::Mat field(int edge = 60)
{
    cv::Mat f = test::filledFrame(320, 240, Colour::Unclassified);
    fillRect(f, 0, edge, 319, 239, Colour::Green);
    return f;
}

const Blackboard& run(ControlWrapper& core)
{
    auto r = core.runFrame();
    if (!r.ok())
        qFatal("runFrame failed: %s", r.error().message.c_str());
    return core.blackboard();
}

} // namespace

class TestStages : public QObject
{
    Q_OBJECT
private slots:
    void greenHorizonFollowsAStraightFieldEdge()
    {
        FrameData data(field(60));
        ControlWrapper core(data);
        const Blackboard& bb = run(core);
        for (int x : {0, 77, 160, 319})
            QCOMPARE(bb.green_horizon.yAt(x), 60);
        QCOMPARE(bb.gh_scan_points.size(), std::size_t(30)); // every 11 px over 320
    }

    void greenHorizonBridgesTheDipOfAnObstacle()
    {
        cv::Mat f = field(60);
        fillRect(f, 100, 30, 139, 150, Colour::ShadowObject); // a robot hiding the field edge
        FrameData data(f);
        ControlWrapper core(data);
        const Blackboard& bb = run(core);
        for (int x = 0; x < 320; x += 20)
            QVERIFY2(std::abs(bb.green_horizon.yAt(x) - 60) <= 1, qPrintable(QString::number(x)));
        // The columns behind the robot saw green only below it.
        int low = 0;
        for (const PixelPoint& p : bb.gh_scan_points)
            low += p.y > 140;
        QVERIFY(low >= 3);
        // ...and the obstacle stage reports it where it is.
        QCOMPARE(bb.obstacles.size(), std::size_t(1));
        QVERIFY(std::abs(bb.obstacles[0].left - 100) <= 2);
        QVERIFY(std::abs(bb.obstacles[0].right - 139) <= 2);
        QVERIFY(std::abs(bb.obstacles[0].bottom - 150) <= 1);
    }

    void greenHorizonIgnoresGreenAboveTheKinematicHorizon()
    {
        cv::Mat f = field(100);
        fillRect(f, 0, 0, 319, 20, Colour::Green); // a green banner in the stands
        FrameData data(f, Horizon{40, 40});
        ControlWrapper core(data);
        const Blackboard& bb = run(core);
        QCOMPARE(bb.green_horizon.yAt(160), 100);
    }

    void scanlinesCoverTheImageWithExclusiveEnds()
    {
        FrameData data(field(60));
        ControlWrapper core(data);
        const Blackboard& bb = run(core);
        QCOMPARE(bb.horizontal_scan_ys.size(), std::size_t(60)); // 239, 235, ..., 3
        QCOMPARE(bb.horizontal_scan_ys.front(), 239);
        QCOMPARE(bb.horizontal_scan_ys.back(), 3);
        QCOMPARE(bb.vertical_scan_starts.size(), std::size_t(80));
        for (std::size_t i = 0; i < bb.horizontal_segments.size(); ++i) {
            int total = 0;
            for (const ColourSegment& s : bb.horizontal_segments[i])
                total += s.length();
            QCOMPARE(total, 320);
        }
        // A vertical scan from the horizon to the bottom is one green run of 180 px.
        QCOMPARE(bb.vertical_segments[0].size(), std::size_t(1));
        QCOMPARE(bb.vertical_segments[0][0].length(), 180);
        QCOMPARE(bb.vertical_segments[0][0].colour, Colour::Green);
    }

    void replacementRulesRemoveFieldNoise()
    {
        cv::Mat f = field(60);
        // One unclassified pixel in the middle of the field on scan line y = 203.
        f.at<cv::Vec3b>(203, 150) = cv::Vec3b(10, 10, 10);
        FrameData data(f);
        ControlWrapper core(data);
        const Blackboard& bb = run(core);
        std::size_t row = 0;
        while (bb.horizontal_scan_ys[row] != 203)
            ++row;
        QCOMPARE(bb.horizontal_segments[row].size(), std::size_t(3));
        QCOMPARE(bb.horizontal_filtered[row].size(), std::size_t(1));
        QCOMPARE(bb.horizontal_filtered[row][0].length(), 320);
    }

    void ballIsFoundAtItsKnownCentre()
    {
        cv::Mat f = field(60);
        fillCircle(f, 120.0, 160.0, 9, Colour::Orange);
        FrameData data(f);
        ControlWrapper core(data);
        const Blackboard& bb = run(core);
        QCOMPARE(bb.balls.size(), std::size_t(1));
        QVERIFY2(std::abs(bb.balls[0].x - 120.0) < 0.75, qPrintable(QString::number(bb.balls[0].x)));
        QVERIFY2(std::abs(bb.balls[0].y - 160.0) < 0.75, qPrintable(QString::number(bb.balls[0].y)));
        QVERIFY2(std::abs(bb.balls[0].radius - 9.5) < 1.0,
                 qPrintable(QString::number(bb.balls[0].radius)));
    }

    void ballHalfHiddenByARobotIsStillCentred()
    {
        cv::Mat f = field(60);
        fillCircle(f, 150.0, 170.0, 12, Colour::Orange);
        fillRect(f, 150, 100, 200, 200, Colour::ShadowObject); // hides the right half
        FrameData data(f);
        ControlWrapper core(data);
        const Blackboard& bb = run(core);
        QCOMPARE(bb.balls.size(), std::size_t(1));
        QVERIFY(std::hypot(bb.balls[0].x - 150, bb.balls[0].y - 170) < 2.0);
    }

    void noBallWithoutBallColour()
    {
        FrameData data(field(60));
        ControlWrapper core(data);
        QCOMPARE(run(core).balls.size(), std::size_t(0));
    }

    void goalpostIsFoundAtItsKnownColumn()
    {
        cv::Mat f = field(60);
        fillRect(f, 200, 5, 209, 100, Colour::Yellow); // 10 px wide, foot at y = 100
        FrameData data(f);
        ControlWrapper core(data);
        const Blackboard& bb = run(core);
        QCOMPARE(bb.goalposts.size(), std::size_t(1));
        const Goalpost& g = bb.goalposts[0];
        QCOMPARE(g.left, 200);
        QCOMPARE(g.right, 209);
        QVERIFY(std::abs(g.base_x - 204.5) < 1.0);
        QCOMPARE(g.bottom, 100);
        QVERIFY(g.top <= 8);
    }

    void twoPostsFarApartAreLeftAndRight()
    {
        cv::Mat f = field(60);
        fillRect(f, 60, 5, 69, 100, Colour::Yellow);
        fillRect(f, 240, 5, 249, 100, Colour::Yellow);
        FrameData data(f);
        ControlWrapper core(data);
        const Blackboard& bb = run(core);
        QCOMPARE(bb.goalposts.size(), std::size_t(2));
        const auto& left = bb.goalposts[0].base_x < bb.goalposts[1].base_x ? bb.goalposts[0]
                                                                            : bb.goalposts[1];
        QCOMPARE(left.side, GoalpostSide::Left);
        QVERIFY(std::abs(left.base_x - 64.5) < 1.0);
    }

    void straightFieldLineIsFound()
    {
        cv::Mat f = field(60);
        drawLine(f, 0, 200, 319, 140, 3, Colour::White);
        FrameData data(f);
        ControlWrapper core(data);
        const Blackboard& bb = run(core);
        QCOMPARE(bb.field_lines.size(), std::size_t(1));
        const FieldLine& l = bb.field_lines[0];
        const double slope = (l.y2 - l.y1) / (l.x2 - l.x1);
        QVERIFY(std::abs(slope - (-60.0 / 319.0)) < 0.02);
        const double y_at_160 = l.y1 + slope * (160 - l.x1);
        QVERIFY(std::abs(y_at_160 - (200 - 60.0 * 160 / 319)) < 1.5);
        QVERIFY(std::min(l.x1, l.x2) < 10 && std::max(l.x1, l.x2) > 309);
    }

    void robotInOpenFieldIsAnObstacle()
    {
        cv::Mat f = field(50);
        fillRect(f, 60, 120, 79, 170, Colour::ShadowObject);
        fillRect(f, 64, 130, 75, 136, Colour::Pink); // team marker
        FrameData data(f);
        ControlWrapper core(data);
        const Blackboard& bb = run(core);
        QCOMPARE(bb.obstacles.size(), std::size_t(1));
        QVERIFY(std::abs(bb.obstacles[0].left - 60) <= 2);
        QVERIFY(std::abs(bb.obstacles[0].right - 79) <= 2);
        QCOMPARE(bb.obstacles[0].bottom, 170);
        QVERIFY(std::abs(bb.obstacles[0].top - 120) <= 1);
    }

    void ransacWithAFixedSeedIsReproducible()
    {
        std::vector<PointF> pts;
        for (int i = 0; i < 40; ++i)
            pts.push_back({double(i), 2.0 * i + 1}); // y = 2x + 1
        for (int i = 0; i < 20; ++i)
            pts.push_back({double((i * 37) % 40), double((i * 53) % 90)}); // clutter
        RansacParams params{1.0, 10, 50, ConsensusSelection::Largest};
        RansacRng rng1{7}, rng2{7};
        auto a = ransacFindModels<ImageLine>(pts, params, 2, rng1);
        auto b = ransacFindModels<ImageLine>(pts, params, 2, rng2);
        QVERIFY(!a.empty());
        QCOMPARE(a.size(), b.size());
        QCOMPARE(a[0].inliers.size(), b[0].inliers.size());
        QVERIFY(a[0].inliers.size() >= 40);
        const ImageLine fit = fitLineTls(a[0].inliers);
        QVERIFY(std::abs(fit.direction.y / fit.direction.x - 2.0) < 0.05);
    }

    void sameFrameTwiceGivesTheSameOutput()
    {
        cv::Mat f = field(60);
        fillCircle(f, 100, 150, 7, Colour::Orange);
        drawLine(f, 0, 220, 319, 120, 3, Colour::White);
        drawLine(f, 30, 239, 200, 70, 3, Colour::White);
        FrameData data(f);
        ControlWrapper core(data);
        run(core);
        const std::vector<FieldLine> first = core.blackboard().field_lines;
        run(core);
        const auto& second = core.blackboard().field_lines;
        QCOMPARE(second.size(), first.size());
        for (std::size_t i = 0; i < first.size(); ++i)
            QCOMPARE(second[i].x1, first[i].x1);
    }
};

QTEST_APPLESS_MAIN(TestStages)
#include "test_stages.moc"
