// The eval matching rules of SPEC §5.3 on hand-made detections and truths, so every scorer agrees.
#include "support/test_suite.h"
#include "visioncore/percepts/field_boundary.h"
#include "visioncore/services/evaluation.h"

#include <QtTest>

using namespace fieldsight;

namespace {

Goalpost detectedPost(double base_x, int bottom)
{
    Goalpost g;
    g.left = int(base_x) - 4;
    g.right = int(base_x) + 4;
    g.top = 0;
    g.bottom = bottom;
    g.base_x = base_x;
    g.base_y = bottom;
    return g;
}

Goalpost truePost(int left, int right, int top, int bottom)
{
    Goalpost g;
    g.left = left;
    g.right = right;
    g.top = top;
    g.bottom = bottom;
    return g;
}

Obstacle obstacle(int left, int right)
{
    return Obstacle{left, right, 50, 100};
}

} // namespace

class TestEvaluation : public QObject
{
    Q_OBJECT
private slots:
    void ballWithinTwoPixelsIsAHit()
    {
        const MatchResult r = matchBalls({{102, 100, 4}}, {{100, 100, 4}});
        QCOMPARE(r.score, (ClassScore{1, 0, 0}));
        QCOMPARE(r.pairs.size(), std::size_t(1));
    }

    void smallBallFourPixelsAwayIsAMiss()
    {
        // Radius 4: the limit is max(3, 2) = 3 px.
        const MatchResult r = matchBalls({{100, 104, 4}}, {{100, 100, 4}});
        QCOMPARE(r.score, (ClassScore{0, 1, 1}));
        QVERIFY(r.pairs.empty());
        // Exactly 3 px still counts (<=).
        QCOMPARE(matchBalls({{103, 100, 4}}, {{100, 100, 4}}).score, (ClassScore{1, 0, 0}));
    }

    void largeBallUsesHalfItsRadius()
    {
        // Radius 20: the limit is 10 px.
        const std::vector<Ball> truth{{100, 100, 20}};
        QCOMPARE(matchBalls({{106, 108, 20}}, truth).score, (ClassScore{1, 0, 0})); // exactly 10
        QCOMPARE(matchBalls({{109.5, 100, 20}}, truth).score, (ClassScore{1, 0, 0}));
        QCOMPARE(matchBalls({{110.5, 100, 20}}, truth).score, (ClassScore{0, 1, 1}));
    }

    void twoDetectionsOfOneBallAreOneHitAndOneFalsePositive()
    {
        const MatchResult r = matchBalls({{101.5, 100, 4}, {100.5, 100, 4}}, {{100, 100, 4}});
        QCOMPARE(r.score, (ClassScore{1, 1, 0}));
        QCOMPARE(r.pairs.size(), std::size_t(1));
        QCOMPARE(r.pairs[0], (MatchPair{1, 0})); // the nearer one wins
    }

    void matchingIsNearestFirst()
    {
        // D0 is nearest to T1 (1.4) but a detection-by-detection matcher would give D0 T1 and
        // leave D1 unmatched; nearest first pairs D1-T1 (1.0) then D0-T0 (1.6).
        const std::vector<Ball> truth{{0, 50, 6}, {3, 50, 6}};
        const std::vector<Ball> detected{{1.6, 50, 6}, {4, 50, 6}};
        const MatchResult r = matchBalls(detected, truth);
        QCOMPARE(r.score, (ClassScore{2, 0, 0}));
        QCOMPARE(r.pairs.size(), std::size_t(2));
        QCOMPARE(r.pairs[0], (MatchPair{1, 1}));
        QCOMPARE(r.pairs[1], (MatchPair{0, 0}));
    }

    void greedyMatchingIsNotAnOptimalAssignment()
    {
        // D0 takes T0 (1.0) first; D1 could only have matched T0, so it stays unmatched even
        // though a different assignment would have matched both.
        const std::vector<Ball> truth{{0, 50, 6}, {2.5, 50, 6}};
        const std::vector<Ball> detected{{1, 50, 6}, {-2.5, 50, 6}};
        const MatchResult r = matchBalls(detected, truth);
        QCOMPARE(r.score, (ClassScore{1, 1, 1}));
        QCOMPARE(r.pairs[0], (MatchPair{0, 0}));
    }

    void goalpostBaseWithinThePostWidth()
    {
        // Columns 130..139: centre 134.5, width 10, so the base limit is 10 px.
        const std::vector<Goalpost> truth{truePost(130, 139, 0, 60)};
        QCOMPARE(matchGoalposts({detectedPost(144.5, 60)}, truth, 240).score,
                 (ClassScore{1, 0, 0}));
        QCOMPARE(matchGoalposts({detectedPost(124.5, 60)}, truth, 240).score,
                 (ClassScore{1, 0, 0}));
        QCOMPARE(matchGoalposts({detectedPost(145, 60)}, truth, 240).score, (ClassScore{0, 1, 1}));
    }

    void narrowGoalpostUsesFourPixels()
    {
        // Columns 100..101: width 2, so the limit is max(4, 2) = 4 px around 100.5.
        const std::vector<Goalpost> truth{truePost(100, 101, 0, 60)};
        QCOMPARE(matchGoalposts({detectedPost(104.5, 60)}, truth, 240).score,
                 (ClassScore{1, 0, 0}));
        QCOMPARE(matchGoalposts({detectedPost(105, 60)}, truth, 240).score, (ClassScore{0, 1, 1}));
    }

    void goalpostBottomWithinSixPixelsOrTenPercent()
    {
        // Height 61: 10% is 6.1 px.
        const std::vector<Goalpost> shortPost{truePost(130, 139, 0, 60)};
        QCOMPARE(matchGoalposts({detectedPost(135, 66)}, shortPost, 240).score,
                 (ClassScore{1, 0, 0}));
        QCOMPARE(matchGoalposts({detectedPost(135, 54)}, shortPost, 240).score,
                 (ClassScore{1, 0, 0}));
        QCOMPARE(matchGoalposts({detectedPost(135, 67)}, shortPost, 240).score,
                 (ClassScore{0, 1, 1}));
        // Height 200: 10% is 20 px.
        const std::vector<Goalpost> tallPost{truePost(130, 139, 0, 199)};
        QCOMPARE(matchGoalposts({detectedPost(135, 180)}, tallPost, 240).score,
                 (ClassScore{1, 0, 0}));
        QCOMPARE(matchGoalposts({detectedPost(135, 178)}, tallPost, 240).score,
                 (ClassScore{0, 1, 1}));
    }

    void goalpostTouchingTheImageBottomIgnoresTheBottom()
    {
        const std::vector<Goalpost> touching{truePost(130, 139, 100, 239)};
        QCOMPARE(matchGoalposts({detectedPost(135, 150)}, touching, 240).score,
                 (ClassScore{1, 0, 0}));
        // The base rule still applies.
        QCOMPARE(matchGoalposts({detectedPost(150, 239)}, touching, 240).score,
                 (ClassScore{0, 1, 1}));
        // One row above the bottom does not touch it.
        const std::vector<Goalpost> above{truePost(130, 139, 100, 238)};
        QCOMPARE(matchGoalposts({detectedPost(135, 150)}, above, 240).score, (ClassScore{0, 1, 1}));
    }

    void goalpostsMatchNearestBaseFirst()
    {
        const std::vector<Goalpost> truth{truePost(100, 109, 0, 60), truePost(112, 121, 0, 60)};
        // D0 at 110 is 5.5 from T0 and 6.5 from T1; D1 at 116 is 0.5 from T1.
        const MatchResult r =
            matchGoalposts({detectedPost(110, 60), detectedPost(116, 60)}, truth, 240);
        QCOMPARE(r.score, (ClassScore{2, 0, 0}));
        QCOMPARE(r.pairs[0], (MatchPair{1, 1}));
        QCOMPARE(r.pairs[1], (MatchPair{0, 0}));
    }

    void obstacleHorizontalIouThresholdIsPointThree()
    {
        // Truth columns 0..9 (10 wide).
        const std::vector<Obstacle> truth{obstacle(0, 9)};
        QCOMPARE(horizontalIou(obstacle(0, 2), obstacle(0, 9)), 0.3);
        QCOMPARE(matchObstacles({obstacle(0, 2)}, truth).score, (ClassScore{1, 0, 0}));
        QCOMPARE(matchObstacles({obstacle(0, 1)}, truth).score, (ClassScore{0, 1, 1})); // 0.2
        // A detection wider than the truth: 10 / 33 passes, 10 / 34 does not.
        QCOMPARE(matchObstacles({obstacle(0, 32)}, truth).score, (ClassScore{1, 0, 0}));
        QCOMPARE(matchObstacles({obstacle(0, 33)}, truth).score, (ClassScore{0, 1, 1}));
        // Overlap from the other side: columns 7..16 share 3 of 17.
        QCOMPARE(matchObstacles({obstacle(7, 16)}, truth).score, (ClassScore{0, 1, 1}));
        QCOMPARE(matchObstacles({obstacle(-2, 7)}, truth).score, (ClassScore{1, 0, 0})); // 8/12
        QCOMPARE(horizontalIou(obstacle(20, 29), obstacle(0, 9)), 0.0);
    }

    void obstaclesMatchHighestIouFirst()
    {
        const std::vector<Obstacle> truth{obstacle(0, 9)};
        const MatchResult r = matchObstacles({obstacle(0, 5), obstacle(0, 8)}, truth);
        QCOMPARE(r.score, (ClassScore{1, 1, 0}));
        QCOMPARE(r.pairs[0], (MatchPair{1, 0}));
    }

    void boundaryErrorOfKnownPolylines()
    {
        const std::vector<PointF> flat10{{0, 10}, {99, 10}};
        const std::vector<PointF> flat20{{0, 20}, {99, 20}};
        QCOMPARE(polylineMeanAbsDifference(flat10, flat20, 100), 10.0);
        QCOMPARE(polylineMeanAbsDifference(flat20, flat10, 100), 10.0);

        // A ramp 0..100 over x = 0..100 against y = 0: the mean of 0..100 is 50.
        const std::vector<PointF> ramp{{0, 0}, {100, 100}};
        const std::vector<PointF> zero{{0, 0}, {100, 0}};
        QCOMPARE(polylineMeanAbsDifference(ramp, zero, 101), 50.0);

        // A polyline that stops at x = 10 is held at its last y: sum 0..10 is 55, then 10 x 10.
        const std::vector<PointF> shortRamp{{0, 0}, {10, 10}};
        QVERIFY(qFuzzyCompare(polylineMeanAbsDifference(shortRamp, zero, 21), 155.0 / 21.0));

        // Interpolation through an inner vertex.
        const std::vector<PointF> peak{{0, 10}, {50, 0}, {100, 10}};
        QCOMPARE(polylineYAt(peak, 25), 5.0);
        QCOMPARE(polylineYAt(peak, 75), 5.0);
        QCOMPARE(polylineYAt(peak, 50), 0.0);
        QCOMPARE(polylineYAt(peak, -5), 10.0);
        // Crossing polylines: |y - 5| along the V sums to 130 on x = 0..50 and 125 on 51..100.
        const std::vector<PointF> five{{0, 5}, {100, 5}};
        QVERIFY(qAbs(polylineMeanAbsDifference(peak, five, 101) - 255.0 / 101.0) < 1e-9);

        QVERIFY(polylineMeanAbsDifference({}, zero, 100) < 0);
        QVERIFY(polylineMeanAbsDifference(zero, {}, 100) < 0);
    }

    void precisionAndRecallEdgeCases()
    {
        QCOMPARE((ClassScore{0, 0, 0}).precision(), 1.0);
        QCOMPARE((ClassScore{0, 0, 0}).recall(), 1.0);
        QCOMPARE((ClassScore{0, 3, 0}).precision(), 0.0);
        QCOMPARE((ClassScore{0, 3, 0}).recall(), 1.0);
        QCOMPARE((ClassScore{0, 0, 2}).precision(), 1.0);
        QCOMPARE((ClassScore{0, 0, 2}).recall(), 0.0);
        QCOMPARE((ClassScore{3, 1, 1}).precision(), 0.75);
        QCOMPARE((ClassScore{3, 1, 1}).recall(), 0.75);
    }

    void framesThatAreNotDoneAreIgnored()
    {
        Annotations truth;
        FrameAnnotation done;
        done.done = true;
        done.truth.output<Ball>() = {{50, 50, 5}};
        done.truth.output<Goalpost>() = {truePost(10, 19, 0, 60)};
        done.truth.output<FieldBoundary>() = {{{{0, 30}, {99, 30}}}};
        FrameAnnotation notDone = done;
        notDone.done = false;
        FrameAnnotation emptyDone;
        emptyDone.done = true;
        emptyDone.truth.output<FieldBoundary>() = {{{{0, 40}, {99, 40}}}};
        truth.frames["a.png"] = done;
        truth.frames["b.png"] = notDone;
        truth.frames["c.png"] = emptyDone;
        truth.frames["d.png"] = emptyDone; // done, but no detections given

        std::map<std::string, PerceptSet> detected;
        detected["a.png"].output<Ball>() = {{51, 50, 5}};
        detected["a.png"].output<FieldBoundary>() = {{{{0, 32}, {99, 32}}}};
        detected["b.png"].output<Ball>() = {{10, 10, 5}}; // would be a false positive if scored
        detected["b.png"].output<Obstacle>() = {obstacle(0, 9)};
        detected["c.png"].output<Obstacle>() = {obstacle(0, 9)};
        detected["c.png"].output<FieldBoundary>() = {{{{0, 44}, {99, 44}}}};

        const EvaluationScores s = evaluate(detected, truth, 100, 120);
        QCOMPARE(s.frames, std::size_t(3));
        QCOMPARE(s.frames_not_done, std::size_t(1));
        QCOMPARE(s.frames_missing, std::size_t(1));
        QCOMPARE(s.of<Ball>(), (ClassScore{1, 0, 0}));
        QCOMPARE(s.of<Goalpost>(), (ClassScore{0, 0, 1}));
        QCOMPARE(s.of<Obstacle>(), (ClassScore{0, 1, 0}));
        // Frames a (2 px) and c (4 px); d has no detected boundary.
        QCOMPARE(s.boundary_frames, std::size_t(2));
        QCOMPARE(s.boundaryMeanError(), 3.0);
    }
};

FIELDSIGHT_TEST_SUITE(TestEvaluation, Core)

#include "test_evaluation.moc"
