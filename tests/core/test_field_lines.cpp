// The field-line stage's merge and centre-circle rules, and the ellipse fit under them, on
// small synthetic frames whose correct answer is known (issue 34).
#include "support/test_suite.h"
#include "stages/common/ellipse_fit.h"
#include "support/field_frames.h"
#include "support/recording_sink.h"
#include "support/synthetic_frames.h"
#include "visioncore/datawrappers/memory_data_wrapper.h"
#include "visioncore/framework/control_wrapper.h"
#include "visioncore/percepts/field_line.h"

#include <QtTest>

#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

using namespace fieldsight;
using test::drawLine;
using test::fieldFrame;
using test::runOrDie;

namespace {

/// Points on the ellipse (centre, semi-axes a along x turned by `turn` rad, b across) from angle
/// `from` to `to`, rounded to whole pixels as scan-line points are, plus up to `noise` px.
std::vector<PointF> arcPoints(PointF centre, double a, double b, double turn, double from,
                              double to, int count, double noise, unsigned seed = 1)
{
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> jitter(-noise, noise);
    std::vector<PointF> points;
    for (int i = 0; i < count; ++i) {
        const double t = from + (to - from) * i / (count - 1);
        const double x = a * std::cos(t), y = b * std::sin(t);
        points.push_back(
            {std::round(centre.x + x * std::cos(turn) - y * std::sin(turn)),
             std::round(centre.y + x * std::sin(turn) + y * std::cos(turn)) + jitter(rng)});
    }
    return points;
}

/// A line that eval would match to the segment (x1, y1)-(x2, y2) (within max(4 px, 5 %) across
/// it over at least half of the shorter one), its ends on average within `within` px of it.
bool hasLine(const std::vector<FieldLine>& lines, double x1, double y1, double x2, double y2,
             double within = 3)
{
    return std::any_of(lines.begin(), lines.end(), [&](const FieldLine& l) {
        const double cost = fieldLineMatchCost(l, {x1, y1, x2, y2});
        return cost >= 0 && cost <= within;
    });
}

/// A white outline 2 px wide of the ellipse about (cx, cy) with semi-axes a along x and b.
void drawWhiteEllipse(cv::Mat& frame, int cx, int cy, int a, int b)
{
    const test::ClassPixel white = test::pixelFor(Colour::White);
    cv::ellipse(frame, {cx, cy}, {a, b}, 0, 0, 360, cv::Scalar(white.y, white.cb, white.cr), 2);
}

std::size_t notesSaying(const test::RecordingSink& sink, const char* words)
{
    const auto layer = sink.published.find("field_lines.rejected");
    if (layer == sink.published.end())
        return 0;
    return std::size_t(
        std::count_if(layer->second.notes.begin(), layer->second.notes.end(),
                      [&](const auto& n) { return n.second.find(words) != std::string::npos; }));
}

} // namespace

class TestFieldLines : public QObject
{
    Q_OBJECT

private slots:
    /// The fit gives back an ellipse whole from half of it, and a turned one, exactly.
    void ellipseFromExactPoints()
    {
        for (const double turn : {0.0, 0.5}) {
            const auto e =
                fitImageEllipse(arcPoints({215, 113}, 110, 12, turn, 0, M_PI, 60, 0), 2, 1000, 1);
            QVERIFY(e);
            QVERIFY(std::abs(e->centre.x - 215) < 1 && std::abs(e->centre.y - 113) < 1);
            QVERIFY(std::abs(std::max(e->a, e->b) - 110) < 2);
            QVERIFY(std::abs(std::min(e->a, e->b) - 12) < 1);
            // A point on the outline is on it; one 5 px out along the minor axis is 5 px off.
            const double c = std::cos(turn), s = std::sin(turn);
            QVERIFY(e->distance({215 + 110 * c, 113 + 110 * s}) < 1);
            QVERIFY(std::abs(e->distance({215 - 17 * s, 113 + 17 * c}) - 5) < 1);
        }
    }

    /// A flat arc of a far centre circle, as scan lines give it (whole pixels and half a pixel
    /// of noise), still gives an ellipse near the true one; points on a straight line give none.
    void ellipseFromAFlatNoisyArc()
    {
        const auto e =
            fitImageEllipse(arcPoints({215, 113}, 55, 7, 0, 0.3, M_PI - 0.3, 25, 0.5), 2, 640, 1.5);
        QVERIFY(e);
        QVERIFY(std::abs(e->centre.y - 113) < 3);
        QVERIFY(std::max(e->a, e->b) > 45 && std::max(e->a, e->b) < 65);
        std::vector<PointF> straight;
        for (int x = 0; x < 100; x += 4)
            straight.push_back({double(x), 50 + 0.2 * x});
        QVERIFY(!fitImageEllipse(straight, 2, 640, 1.5));
        QVERIFY(!fitImageEllipse({{1, 1}, {2, 2}, {3, 1}}, 2, 640, 1.5)); // too few points
    }

    /// Far away the goal line and the goal area's front line run a few px apart and nearly
    /// parallel: they are two lines, not one merged between them (merge_error 0 merges them).
    void closeParallelLinesStayTwo()
    {
        cv::Mat f = fieldFrame(60);
        drawLine(f, 0, 100, 319, 110, 2, Colour::White);
        drawLine(f, 0, 105, 319, 115, 2, Colour::White);
        MemoryDataWrapper data(f, test::testLut());
        ControlWrapper core(data);
        QVERIFY(core.setParam("field_lines", "merge_error", 0).ok());
        const std::vector<FieldLine> merged = runOrDie(core).percepts.list<FieldLine>();
        QCOMPARE(merged.size(), std::size_t(1));
        const FieldLine& m = merged[0];
        const double y_at_160 = m.y1 + (m.y2 - m.y1) / (m.x2 - m.x1) * (160 - m.x1);
        QVERIFY(y_at_160 > 105.5 + 1.5 && y_at_160 < 110.5 - 1.5); // between the two

        QVERIFY(core.setParam("field_lines", "merge_error", 1).ok());
        const std::vector<FieldLine>& lines = runOrDie(core).percepts.list<FieldLine>();
        QCOMPARE(lines.size(), std::size_t(2));
        // Each on its own line: the merged one lies 2.5 px from both.
        QVERIFY(hasLine(lines, 0, 100.5, 319, 110.5, 1));
        QVERIFY(hasLine(lines, 0, 105.5, 319, 115.5, 1));
    }

    /// A line cut in two by a robot is still merged into one.
    void piecesOfOneLineAreMerged()
    {
        cv::Mat f = fieldFrame(60);
        drawLine(f, 0, 150, 319, 130, 2, Colour::White);
        test::fillRect(f, 120, 100, 180, 160, Colour::ShadowObject);
        MemoryDataWrapper data(f, test::testLut());
        ControlWrapper core(data);
        const std::vector<FieldLine>& lines = runOrDie(core).percepts.list<FieldLine>();
        QCOMPARE(lines.size(), std::size_t(1));
        QVERIFY(std::min(lines[0].x1, lines[0].x2) < 10 &&
                std::max(lines[0].x1, lines[0].x2) > 309);
    }

    /// A short line (under min_points points) stands where its end meets a long line at an
    /// angle, as the goal area's lines do; the same line alone on the carpet is clutter.
    void shortLinesStandAtAJunction()
    {
        cv::Mat f = fieldFrame(60);
        drawLine(f, 0, 200, 319, 180, 2, Colour::White);
        drawLine(f, 200, 188, 209, 162, 2, Colour::White); // from the long line up
        drawLine(f, 60, 140, 69, 114, 2, Colour::White);   // alone
        MemoryDataWrapper data(f, test::testLut());
        ControlWrapper core(data);
        QVERIFY(core.setParam("field_lines", "short_points", 0).ok());
        QCOMPARE(runOrDie(core).percepts.list<FieldLine>().size(), std::size_t(1));
        QVERIFY(core.setParam("field_lines", "short_points", 8).ok());
        const std::vector<FieldLine>& lines = runOrDie(core).percepts.list<FieldLine>();
        QCOMPARE(lines.size(), std::size_t(2));
        QVERIFY(hasLine(lines, 0, 200.5, 319, 180.5));
        QVERIFY(hasLine(lines, 200.5, 188, 209.5, 162));
        QVERIFY(core.setParam("field_lines", "junction", 0).ok()); // no end meets the long line
        QCOMPARE(runOrDie(core).percepts.list<FieldLine>().size(), std::size_t(1));
    }

    /// The centre circle far away is a flat ellipse with the halfway line through it. RANSAC
    /// makes chords of its arcs; one bends and gives the ellipse, and the straighter chords on
    /// it are dropped with it (circle_distance 0 keeps them). The halfway line stays.
    void farCircleChordsAreDropped()
    {
        cv::Mat f = fieldFrame(60);
        drawWhiteEllipse(f, 160, 140, 120, 22);
        drawLine(f, 0, 141, 319, 139, 2, Colour::White);
        MemoryDataWrapper data(f, test::testLut());
        test::RecordingSink sink;
        sink.layers = {"field_lines.rejected"};
        data.setDebugSink(&sink);
        ControlWrapper core(data);
        QVERIFY(core.setParam("field_lines", "circle_distance", 0).ok());
        const std::size_t kept = runOrDie(core).percepts.list<FieldLine>().size();
        QVERIFY(kept >= 2); // the halfway line and a chord at least
        QVERIFY(core.setParam("field_lines", "circle_distance", 3).ok());
        const std::vector<FieldLine>& lines = runOrDie(core).percepts.list<FieldLine>();
        QCOMPARE(lines.size(), std::size_t(1));
        QVERIFY(hasLine(lines, 0, 141.5, 319, 139.5));
        QVERIFY(notesSaying(sink, "centre circle") >= 1);
    }

    /// A near centre circle gives bent chords, each a model of the search; they take no line's
    /// place, so the lines found after them are still found within max_lines.
    void circleChordsTakeNoLinesPlace()
    {
        cv::Mat f = fieldFrame(60);
        drawWhiteEllipse(f, 160, 170, 150, 30);
        drawLine(f, 20, 80, 100, 75, 2, Colour::White);
        drawLine(f, 200, 100, 290, 95, 2, Colour::White);
        MemoryDataWrapper data(f, test::testLut());
        test::RecordingSink sink;
        sink.layers = {"field_lines.rejected"};
        data.setDebugSink(&sink);
        ControlWrapper core(data);
        QVERIFY(core.setParam("field_lines", "max_lines", 2).ok());
        const std::vector<FieldLine>& lines = runOrDie(core).percepts.list<FieldLine>();
        QVERIFY(notesSaying(sink, "bent") >= 2);
        QVERIFY(hasLine(lines, 20, 80.5, 100, 75.5));
        QVERIFY(hasLine(lines, 200, 100.5, 290, 95.5));
    }
};

FIELDSIGHT_TEST_SUITE(TestFieldLines, None)

#include "test_field_lines.moc"
