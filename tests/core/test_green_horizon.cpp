// The green horizon's rules on small synthetic frames whose field edge is known: a straight
// edge, a robot hiding it, green walls and seats behind the field, a corner, the camera's own body
// at the image's side.
#include "support/test_suite.h"
#include "stages/green_horizon/edge_lines.h"
#include "support/field_frames.h"
#include "support/recording_sink.h"
#include "support/synthetic_frames.h"
#include "visioncore/datawrappers/memory_data_wrapper.h"
#include "visioncore/framework/control_wrapper.h"
#include "visioncore/percepts/obstacle.h"

#include <QtTest>

#include <algorithm>
#include <cmath>
#include <random>
#include <limits>
#include <memory>

using namespace fieldsight;
using test::fillRect;

namespace {

using test::fieldFrame;
using test::runOrDie;

/// Field green from row edge(x) down in every column, unclassified above.
template <class Edge> cv::Mat edgeFrame(Edge edge)
{
    cv::Mat f = test::filledFrame(320, 240, Colour::Unclassified);
    for (int x = 0; x < 320; ++x)
        fillRect(f, x, int(std::lround(edge(x))), x, 239, Colour::Green);
    return f;
}

/// The green horizon of `frame` with edge_lines at `tolerance` (0: off); the thrown points'
/// layer recorded into `sink` when given.
int horizonAt(const cv::Mat& frame, double tolerance, int x, test::RecordingSink* sink = nullptr)
{
    MemoryDataWrapper data(frame, test::testLut());
    if (sink) {
        sink->layers = {"green_horizon.thrown_points"};
        data.setDebugSink(sink);
    }
    ControlWrapper core(data);
    if (!core.setParam("green_horizon", "edge_lines", tolerance).ok())
        qFatal("edge_lines refused");
    return runOrDie(core).green_horizon.yAt(x);
}

} // namespace

namespace reference {

// fitEdge's search as it was first written: every pair's line scored over every point, in order,
// no shortcut. The fit's shortcuts must choose what this chooses.
struct Fit
{
    EdgeLine line;
    int support = 0;
    int above = 0;
    double residual = 0;
    double merit() const { return support - 0.5 * above; }
};

Fit score(const std::vector<PixelPoint>& pool, const EdgeLine& line, double tolerance)
{
    Fit f{line};
    for (const PixelPoint& p : pool) {
        const double d = p.y - line.at(p.x);
        if (std::abs(d) <= tolerance) {
            ++f.support;
            f.residual += std::abs(d);
        } else if (d < 0) {
            ++f.above;
        }
    }
    return f;
}

template <class Allowed>
Fit bestLine(const std::vector<PixelPoint>& pool, double tolerance, Allowed allowed)
{
    Fit best;
    for (std::size_t i = 0; i < pool.size(); ++i)
        for (std::size_t j = i + 1; j < pool.size(); ++j) {
            if (pool[i].x == pool[j].x)
                continue;
            const double b = double(pool[j].y - pool[i].y) / double(pool[j].x - pool[i].x);
            const Fit f = score(pool, {pool[i].y - b * pool[i].x, b}, tolerance);
            const bool better = f.merit() > best.merit() ||
                                (f.merit() == best.merit() && f.residual < best.residual);
            if ((best.support > 0 && !better) || !allowed(f.line))
                continue;
            best = f;
        }
    if (best.support < 2)
        return best;
    double n = 0, sx = 0, sy = 0, sxx = 0, sxy = 0;
    for (const PixelPoint& p : pool)
        if (std::abs(p.y - best.line.at(p.x)) <= tolerance) {
            n += 1;
            sx += p.x;
            sy += p.y;
            sxx += double(p.x) * p.x;
            sxy += double(p.x) * p.y;
        }
    const double det = n * sxx - sx * sx;
    if (det > 0) {
        const double b = (n * sxy - sx * sy) / det;
        const EdgeLine refit{(sy - b * sx) / n, b};
        if (allowed(refit))
            best.line = refit;
    }
    return best;
}

std::optional<EdgeModel> fitEdge(const std::vector<PixelPoint>& points, double tolerance,
                                 int min_support)
{
    const Fit first = bestLine(points, tolerance, [](const EdgeLine&) { return true; });
    if (first.support < std::max(2, min_support))
        return std::nullopt;
    EdgeModel model{first.line, std::nullopt};
    std::vector<PixelPoint> on_first, below;
    for (const PixelPoint& p : points) {
        const double d = p.y - first.line.at(p.x);
        if (std::abs(d) <= tolerance)
            on_first.push_back(p);
        else if (d > tolerance)
            below.push_back(p);
    }
    if (int(below.size()) < min_support)
        return model;
    const Fit second = bestLine(below, tolerance, [&](const EdgeLine& line) {
        return std::all_of(on_first.begin(), on_first.end(), [&](const PixelPoint& p) {
            return line.at(p.x) <= first.line.at(p.x) + tolerance;
        });
    });
    if (second.support >= std::max(2, min_support))
        model.second = second.line;
    return model;
}

} // namespace reference

class TestGreenHorizon : public QObject
{
    Q_OBJECT
private slots:
    void greenHorizonFollowsAStraightFieldEdge()
    {
        MemoryDataWrapper data(fieldFrame(60), test::testLut());
        ControlWrapper core(data);
        const Blackboard& bb = runOrDie(core);
        for (int x : {0, 77, 160, 319})
            QCOMPARE(bb.green_horizon.yAt(x), 60);
        QCOMPARE(bb.gh_scan_points.size(), std::size_t(30)); // every 11 px over 320
    }

    void greenHorizonBridgesTheDipOfAnObstacle()
    {
        cv::Mat f = fieldFrame(60);
        fillRect(f, 100, 30, 139, 150, Colour::ShadowObject); // a robot hiding the field edge
        MemoryDataWrapper data(f, test::testLut());
        ControlWrapper core(data);
        const Blackboard& bb = runOrDie(core);
        for (int x = 0; x < 320; x += 20)
            QVERIFY2(std::abs(bb.green_horizon.yAt(x) - 60) <= 1, qPrintable(QString::number(x)));
        // The columns behind the robot saw green only below it.
        int low = 0;
        for (const PixelPoint& p : bb.gh_scan_points)
            low += p.y > 140;
        QVERIFY(low >= 3);
        // ...and the obstacle stage reports it where it is.
        QCOMPARE(bb.percepts.list<Obstacle>().size(), std::size_t(1));
        QVERIFY(std::abs(bb.percepts.list<Obstacle>()[0].left - 100) <= 2);
        QVERIFY(std::abs(bb.percepts.list<Obstacle>()[0].right - 139) <= 2);
        QVERIFY(std::abs(bb.percepts.list<Obstacle>()[0].bottom - 150) <= 1);
    }

    void thrownGreenHorizonPointsSayWhy()
    {
        cv::Mat f = fieldFrame(100);
        fillRect(f, 0, 20, 319, 40, Colour::Green); // a green wall above a wide gap
        // Green rising from the field near enough to the wall that two columns bridge the gap and
        // start on the wall, far above all the others.
        fillRect(f, 150, 70, 170, 99, Colour::Green);
        MemoryDataWrapper data(f, test::testLut());
        test::RecordingSink sink;
        sink.layers = {"green_horizon.thrown_points"};
        data.setDebugSink(&sink);
        ControlWrapper core(data);
        QVERIFY(core.setParam("green_horizon", "max_field_gap", 30).ok());
        const Blackboard& bb = runOrDie(core);
        QCOMPARE(bb.green_horizon.yAt(10), 100);
        const DebugDrawing& thrown = sink.published.at("green_horizon.thrown_points");
        QCOMPARE(thrown.shapes.size(), std::size_t(2));
        QCOMPARE(thrown.shapes[0].points.size(), std::size_t(28)); // the wall, the other columns
        QVERIFY(thrown.notes.at(0).find("max_field_gap") != std::string::npos);
        QCOMPARE(thrown.shapes[1].points.size(), std::size_t(2));
        for (const PointF& p : thrown.shapes[1].points)
            QVERIFY(p.y == 20 && p.x >= 150 && p.x <= 170);
        QVERIFY(thrown.notes.at(1).find("upper_threshold_mult") != std::string::npos);
    }

    void greenHorizonIgnoresGreenAboveTheKinematicHorizon()
    {
        cv::Mat f = fieldFrame(100);
        fillRect(f, 0, 0, 319, 20, Colour::Green); // a green banner in the stands
        MemoryDataWrapper data(std::make_shared<const ColourLut>(test::testLut()), f,
                               Horizon{40, 40});
        ControlWrapper core(data);
        const Blackboard& bb = runOrDie(core);
        QCOMPARE(bb.green_horizon.yAt(160), 100);
    }

    void anImplausibleKinematicHorizonIsADiagnosticAndTheWholeImageIsSearched()
    {
        const double nan = std::numeric_limits<double>::quiet_NaN();
        for (const Horizon& h : {Horizon{4, 6.9e65}, Horizon{nan, 40}, Horizon{-2e6, 40}}) {
            MemoryDataWrapper data(std::make_shared<const ColourLut>(test::testLut()),
                                   fieldFrame(100), h);
            ControlWrapper core(data);
            const Blackboard& bb = runOrDie(core);
            QCOMPARE(bb.kinematic_horizon, Horizon{});
            QCOMPARE(bb.green_horizon.yAt(160), 100);
            QCOMPARE(bb.diagnostics.size(), std::size_t(1));
            QCOMPARE(bb.diagnostics[0].stage, std::string("kinematic_horizon"));
            QVERIFY2(bb.diagnostics[0].message.find("is not two rows within 1e6 px; the whole "
                                                    "image was searched") != std::string::npos,
                     bb.diagnostics[0].message.c_str());
        }
        // A plausible one, even far below the image, is taken as it is.
        MemoryDataWrapper data(std::make_shared<const ColourLut>(test::testLut()), fieldFrame(100),
                               Horizon{5e5, 5e5});
        ControlWrapper core(data);
        const Blackboard& bb = runOrDie(core);
        QCOMPARE(bb.kinematic_horizon, (Horizon{5e5, 5e5}));
        QVERIFY(bb.diagnostics.empty());
    }

    void greenBehindTheFieldAboveTheEdgesLineIsThrown()
    {
        // A green seat behind the field, over seven columns: too many for the outlier rule.
        cv::Mat f = fieldFrame(100);
        fillRect(f, 100, 60, 180, 90, Colour::Green);
        QCOMPARE(horizonAt(f, 0, 140), 60);
        test::RecordingSink sink;
        QCOMPARE(horizonAt(f, 3, 140), 100);
        for (int x : {0, 90, 200, 319})
            QCOMPARE(horizonAt(f, 3, x), 100);
        horizonAt(f, 3, 0, &sink);
        const DebugDrawing& thrown = sink.published.at("green_horizon.thrown_points");
        QCOMPARE(thrown.shapes.size(), std::size_t(1));
        QCOMPARE(thrown.shapes[0].points.size(), std::size_t(7)); // columns 110 to 176
        QVERIFY(thrown.notes.at(0).find("edge_lines") != std::string::npos);
    }

    void theEdgeFitChoosesWhatEveryPairsFullScoreChooses()
    {
        // Random scan points on integer rows: edges, corners, clutter above and below, and many
        // lines level on merit (points exactly on a line, or at the tolerance from it), where
        // the first pair of the least residual must win. The fit's shortcuts (merit first, two
        // points a step, the residual exactly only where it can win) choose what scoring every
        // pair in full chooses, to the bit.
        std::mt19937 random(20261204);
        EdgeFitScratch scratch;
        int corners = 0;
        for (int trial = 0; trial < 400; ++trial) {
            std::vector<PixelPoint> points;
            const int n = 3 + int(random() % 45);
            const double slope = (int(random() % 9) - 4) * 0.05;
            const int corner = int(random() % 320);
            for (int k = 0; k < n; ++k) {
                const int x = 8 * k;
                int y = 80 + int(std::lround(slope * std::abs(x - corner)));
                switch (random() % 6) {
                case 0:
                    y -= int(random() % 40);
                    break; // above: a wall
                case 1:
                    y += int(random() % 60);
                    break; // below: a robot's feet
                case 2:
                    y += int(random() % 7) - 3;
                    break;
                default:
                    break;
                }
                points.push_back({x, y});
            }
            const double tolerance = double(1 + random() % 4);
            const int min_support = 2 + int(random() % 4);
            const std::optional<EdgeModel> want =
                reference::fitEdge(points, tolerance, min_support);
            const std::optional<EdgeModel> got = fitEdge(points, tolerance, min_support, scratch);
            const QByteArray at = QByteArray::number(trial);
            QVERIFY2(got.has_value() == want.has_value(), at);
            if (!got)
                continue;
            QVERIFY2(got->first.a == want->first.a && got->first.b == want->first.b, at);
            QVERIFY2(got->second.has_value() == want->second.has_value(), at);
            if (got->second) {
                ++corners;
                QVERIFY2(got->second->a == want->second->a && got->second->b == want->second->b,
                         at);
            }
        }
        QVERIFY(corners > 20); // the second line's search is exercised too
    }

    void aCornerKeepsBothSidesOfTheEdge()
    {
        // The field's corner is its farthest point: the edge rises to it from both sides.
        const auto corner = [](int x) { return 60 + 0.25 * std::abs(x - 160); };
        const cv::Mat f = edgeFrame(corner);
        for (int x : {0, 80, 160, 240, 319})
            QVERIFY2(std::abs(horizonAt(f, 3, x) - corner(x)) <= 1.5,
                     qPrintable(QString::number(x)));
        // A robot in front of one side leaves the points behind it low, in a line of their own
        // that would cut the edge off: the edge is still the corner's.
        cv::Mat robot = f.clone();
        fillRect(robot, 200, 40, 260, 150, Colour::ShadowObject);
        for (int x : {80, 160, 230, 300})
            QVERIFY2(std::abs(horizonAt(robot, 3, x) - corner(x)) <= 1.5,
                     qPrintable(QString::number(x)));
    }

    void ofTwoParallelLinesTheUpperIsTheEdge()
    {
        // In patches along the edge something else lies on the carpet (the field's border, a
        // wall's foot): those columns start 10 rows lower, more of them (17 scan columns) than
        // start at the edge (13). Green above a line counts against it, so the edge's line wins.
        cv::Mat f = fieldFrame(100);
        for (int i = 0; i < 30; ++i)
            if (i % 2 == 1 || i > 24)
                fillRect(f, std::max(0, 11 * i - 5), 100, std::min(319, 11 * i + 5), 109,
                         Colour::Unclassified);
        test::RecordingSink sink;
        QCOMPARE(horizonAt(f, 3, 50, &sink), 100);
        const DebugDrawing& thrown = sink.published.at("green_horizon.thrown_points");
        QVERIFY2(thrown.shapes.empty(),
                 thrown.notes.empty() ? "" : thrown.notes.begin()->second.c_str());
    }

    void aDeepDipAtTheImagesSideFollowsTheEdgesLine()
    {
        // The observing robot's shoulder over the lower left: the leftmost columns see the field
        // only far below the edge, and the hull cannot bridge a dip at the image's side.
        const auto slope = [](int x) { return 100 - 0.1 * x; };
        cv::Mat f = edgeFrame(slope);
        fillRect(f, 0, 90, 60, 200, Colour::ShadowObject);
        QVERIFY(horizonAt(f, 0, 0) > 110);
        QVERIFY(std::abs(horizonAt(f, 3, 0) - slope(0)) <= 1.5);
        QVERIFY(std::abs(horizonAt(f, 3, 30) - slope(30)) <= 1.5);
        // A shallow dip there is the edge curving away, and stays.
        cv::Mat shallow = edgeFrame(slope);
        fillRect(shallow, 0, 90, 30, 108, Colour::ShadowObject);
        QVERIFY(horizonAt(shallow, 3, 0) >= 108);
    }
};

FIELDSIGHT_TEST_SUITE(TestGreenHorizon, None)

#include "test_green_horizon.moc"
