// The evaluation's extensions of SPEC §5.3 (docs/formats.md): concealed objects scored apart,
// kinds reviewed on a frame that is not done, the field line rule, and the per-frame list of
// disagreements that the eval command, the window and the edit-effect scan share.
#include "support/test_suite.h"
#include "visioncore/percepts/field_boundary.h"
#include "visioncore/percepts/obstacle.h"
#include "visioncore/services/evaluation.h"

#include <QtTest>

using namespace fieldsight;

namespace {

FieldLine line(double x1, double y1, double x2, double y2)
{
    return FieldLine{x1, y1, x2, y2};
}

/// Frame "name" of `truth`, done or not, with the given true balls.
FrameAnnotation& frame(Annotations& truth, const std::string& name, bool done,
                       std::vector<Ball> balls = {})
{
    FrameAnnotation& f = truth.frames[name];
    f.done = done;
    f.truth.output<Ball>() = std::move(balls);
    return f;
}

} // namespace

class TestEvaluationMarks : public QObject
{
    Q_OBJECT
private slots:
    void fieldLinesOnTheSameLineMatch()
    {
        // A 200 px line: the limit is max(4, 10) = 10 px from it.
        const FieldLine truth = line(0, 100, 200, 100);
        QCOMPARE(fieldLineMatchCost(line(20, 103, 120, 97), truth), 3.0);
        QCOMPARE(fieldLineMatchCost(line(20, 110, 120, 110), truth), 10.0); // exactly the limit
        QVERIFY(fieldLineMatchCost(line(20, 110.5, 120, 110.5), truth) < 0);
        // Symmetric: the shorter segment is measured against the longer, whichever is which.
        QCOMPARE(fieldLineMatchCost(truth, line(20, 103, 120, 97)), 3.0);
        // A short line: max(4 px, 5% of 40 px) = 4 px.
        QCOMPARE(fieldLineMatchCost(line(0, 4, 40, 4), line(0, 0, 40, 0)), 4.0);
        QVERIFY(fieldLineMatchCost(line(0, 4.5, 40, 4.5), line(0, 0, 40, 0)) < 0);
    }

    void fieldLinesMustOverlapAlongTheLine()
    {
        const FieldLine truth = line(0, 100, 200, 100);
        // On the line but beyond its end: no overlap.
        QVERIFY(fieldLineMatchCost(line(210, 100, 260, 100), truth) < 0);
        // Half of the shorter one over the longer one still matches; less does not.
        QCOMPARE(fieldLineMatchCost(line(150, 100, 250, 100), truth), 0.0);
        QVERIFY(fieldLineMatchCost(line(151, 100, 251, 100), truth) < 0);
        // Crossing at right angles: the far end is off the line.
        QVERIFY(fieldLineMatchCost(line(100, 60, 100, 140), truth) < 0);
        // Reversed ends are the same segment.
        QCOMPARE(fieldLineMatchCost(line(120, 97, 20, 103), truth), 3.0);
    }

    void fieldLinesMatchOneToOneNearestFirst()
    {
        const std::vector<FieldLine> truth{line(0, 100, 200, 100), line(0, 150, 200, 150)};
        const std::vector<FieldLine> detected{line(10, 102, 150, 102), line(10, 101, 190, 101),
                                              line(0, 20, 200, 20)};
        const MatchResult r = matchFieldLines(detected, truth);
        QCOMPARE(r.score, (ClassScore{1, 2, 1}));
        QCOMPARE(r.pairs.size(), std::size_t(1));
        QCOMPARE(r.pairs[0], (MatchPair{1, 0})); // 1 px beats 2 px
    }

    void compareDetectionsCountsFieldLines()
    {
        PerceptSet before;
        before.output<FieldLine>() = {line(0, 100, 200, 100)};
        PerceptSet after;
        after.output<FieldLine>() = {line(0, 102, 200, 102), line(0, 20, 100, 60)};
        const DetectionDelta d = compareDetections(before, after, 320, 240);
        QCOMPARE(d.of("field_lines").appeared, 1);
        QCOMPARE(d.of("field_lines").vanished, 0);
        const DetectionDelta back = compareDetections(after, before, 320, 240);
        QCOMPARE(back.of("field_lines").vanished, 1);
        QCOMPARE(back.appeared(), 0);
    }

    void concealedObjectsAreScoredApart()
    {
        // Truth: a plain ball and a concealed one; the detector finds the concealed one and
        // something else.
        Annotations truth;
        FrameAnnotation& f = frame(truth, "a.png", true, {{50, 50, 5}, {100, 100, 5}});
        f.setFlags("balls", 1, ObjectFlags{.concealed = true});
        std::map<std::string, PerceptSet> detected;
        detected["a.png"].output<Ball>() = {{101, 100, 5}, {10, 10, 5}};
        Evaluation e = evaluateFrames(detected, truth, 200, 200);
        // The concealed ball found: neither a true positive nor a false one.
        QCOMPARE(e.scores.of<Ball>(), (ClassScore{0, 1, 1, 1, 0}));

        // Missed, a concealed ball is no false negative and no disagreement.
        detected["a.png"].output<Ball>() = {{50, 50, 5}};
        e = evaluateFrames(detected, truth, 200, 200);
        QCOMPARE(e.scores.of<Ball>(), (ClassScore{1, 0, 0, 0, 1}));
        QVERIFY(e.disagreements.empty());
        // The same truth without the flag: a plain miss.
        f.setFlags("balls", 1, ObjectFlags{});
        e = evaluateFrames(detected, truth, 200, 200);
        QCOMPARE(e.scores.of<Ball>(), (ClassScore{1, 0, 1}));
        QCOMPARE(e.disagreements.size(), std::size_t(1));
    }

    void aConcealedObjectTakesOnlyADetectionNoPlainOneWants()
    {
        // A plain ball at (50, 50) and a concealed one at (54, 50); the one detection, at
        // (53, 50), is nearer the concealed ball but within reach of both.
        Annotations truth;
        FrameAnnotation& f = frame(truth, "a.png", true, {{50, 50, 8}, {54, 50, 8}});
        f.setFlags("balls", 1, ObjectFlags{.concealed = true});
        std::map<std::string, PerceptSet> detected;
        detected["a.png"].output<Ball>() = {{53, 50, 8}};
        Evaluation e = evaluateFrames(detected, truth, 200, 200);
        // The plain ball has it; the concealed one is left, and is no miss.
        QCOMPARE(e.scores.of<Ball>(), (ClassScore{1, 0, 0, 0, 1}));
        QVERIFY(e.disagreements.empty());
        // A second detection at the concealed ball: it is found there, still no false positive.
        detected["a.png"].output<Ball>() = {{53, 50, 8}, {55, 50, 8}};
        e = evaluateFrames(detected, truth, 200, 200);
        QCOMPARE(e.scores.of<Ball>(), (ClassScore{1, 0, 0, 1, 0}));
        // Both plain: nearest first, so the detection goes to the second and the first is missed.
        f.setFlags("balls", 1, ObjectFlags{});
        detected["a.png"].output<Ball>() = {{53, 50, 8}};
        e = evaluateFrames(detected, truth, 200, 200);
        QCOMPARE(e.scores.of<Ball>(), (ClassScore{1, 0, 1}));
    }

    void aDetectionOfWhatIsSeenOfAConcealedObjectMatchesIt()
    {
        // A ball half behind a robot: the detector fits the seen half, 7 px off the true centre
        // (the ball rule reaches max(3, 5) px), inside the true disc.
        Annotations truth;
        FrameAnnotation& f = frame(truth, "a.png", true, {{50, 50, 10}});
        f.setFlags("balls", 0, ObjectFlags{.concealed = true});
        f.truth.output<Obstacle>() = {Obstacle{100, 139, 20, 99}};
        f.setFlags("obstacles", 0, ObjectFlags{.concealed = true});
        std::map<std::string, PerceptSet> detected;
        detected["a.png"].output<Ball>() = {{57, 50, 4}};
        // A box of the robot's seen part: IoU under the rule's 0.3, its centre inside.
        detected["a.png"].output<Obstacle>() = {Obstacle{130, 139, 60, 99}};
        Evaluation e = evaluateFrames(detected, truth, 200, 200);
        QCOMPARE(e.scores.of<Ball>(), (ClassScore{0, 0, 0, 1, 0}));
        QCOMPARE(e.scores.of<Obstacle>(), (ClassScore{0, 0, 0, 1, 0}));
        // Outside the disc or the box: a false detection, and the concealed object missed.
        detected["a.png"].output<Ball>() = {{61, 50, 4}};
        detected["a.png"].output<Obstacle>() = {Obstacle{141, 160, 60, 99}};
        e = evaluateFrames(detected, truth, 200, 200);
        QCOMPARE(e.scores.of<Ball>(), (ClassScore{0, 1, 0, 0, 1}));
        QCOMPARE(e.scores.of<Obstacle>(), (ClassScore{0, 1, 0, 0, 1}));
        // A plain ball is held to its rule: 7 px off is a miss and a false ball.
        f.setFlags("balls", 0, ObjectFlags{});
        detected["a.png"].output<Ball>() = {{57, 50, 4}};
        e = evaluateFrames(detected, truth, 200, 200);
        QCOMPARE(e.scores.of<Ball>(), (ClassScore{0, 1, 1}));
    }

    void reviewedKindsOfAFrameNotDoneAreScored()
    {
        Annotations truth;
        // Not done, but its balls are reviewed (one ball) and its obstacles ("nothing here").
        FrameAnnotation& partial = frame(truth, "a.png", false, {{50, 50, 5}});
        partial.reviewed = {"balls", "obstacles"};
        partial.truth.output<Goalpost>() = {Goalpost{10, 19, 0, 60}};
        // Not done and nothing reviewed: not scored at all.
        frame(truth, "b.png", false, {{50, 50, 5}});
        std::map<std::string, PerceptSet> detected;
        detected["a.png"].output<Obstacle>() = {Obstacle{0, 9, 50, 100}};
        detected["a.png"].output<Goalpost>() = {}; // the true post is not scored: not reviewed
        detected["a.png"].output<FieldLine>() = {line(0, 0, 50, 50)}; // nor are lines
        detected["b.png"].output<Ball>() = {{10, 10, 5}};

        const Evaluation e = evaluateFrames(detected, truth, 200, 200);
        QCOMPARE(e.scores.frames, std::size_t(0));
        QCOMPARE(e.scores.frames_not_done, std::size_t(2));
        QCOMPARE(e.scores.frames_reviewed, std::size_t(1));
        QCOMPARE(e.scores.of<Ball>(), (ClassScore{0, 0, 1}));
        QCOMPARE(e.scores.of<Obstacle>(), (ClassScore{0, 1, 0}));
        QCOMPARE(e.scores.of<Goalpost>(), (ClassScore{}));
        QCOMPARE(e.scores.of<FieldLine>(), (ClassScore{}));
        QVERIFY(isScored(partial));
        QVERIFY(!isScored(truth.frames.at("b.png")));
        // Done, every kind counts again.
        partial.done = true;
        const Evaluation all = evaluateFrames(detected, truth, 200, 200);
        QCOMPARE(all.scores.of<Goalpost>(), (ClassScore{0, 0, 1}));
        QCOMPARE(all.scores.of<FieldLine>(), (ClassScore{0, 1, 0}));
    }

    void boundaryIsScoredOnlyWhereItsTruthIsComplete()
    {
        Annotations truth;
        FrameAnnotation& f = frame(truth, "a.png", false);
        f.reviewed = {"balls"};
        f.truth.output<FieldBoundary>() = {{{{0, 30}, {99, 30}}}};
        std::map<std::string, PerceptSet> detected;
        detected["a.png"].output<FieldBoundary>() = {{{{0, 34}, {99, 34}}}};
        QCOMPARE(evaluateFrames(detected, truth, 100, 100).scores.boundary_frames, std::size_t(0));
        f.reviewed.insert("field_boundary");
        const EvaluationScores s = evaluateFrames(detected, truth, 100, 100).scores;
        QCOMPARE(s.boundary_frames, std::size_t(1));
        QCOMPARE(s.boundaryMeanError(), 4.0);
    }

    void disagreementsNameTheFrameKindAndObjects()
    {
        Annotations truth;
        frame(truth, "a.png", true, {{50, 50, 5}, {150, 50, 5}});
        frame(truth, "b.png", true, {{50, 50, 5}});
        frame(truth, "c.png", true);
        truth.frames["c.png"].truth.output<Obstacle>() = {Obstacle{0, 9, 50, 100}};
        frame(truth, "d.png", true); // nothing true: a detection is only a false one
        std::map<std::string, PerceptSet> detected;
        detected["a.png"].output<Ball>() = {{10, 190, 5}, {151, 50, 5}};
        detected["b.png"].output<Ball>() = {{50, 51, 5}};
        // c.png: no detections at all (a frame the run lacks).
        detected["d.png"].output<Goalpost>() = {Goalpost{10, 19, 0, 60, 14.5, 60}};

        const Evaluation e = evaluateFrames(detected, truth, 200, 200);
        QCOMPARE(e.disagreements.size(), std::size_t(3));
        const FrameDisagreement& a = e.disagreements[0];
        QCOMPARE(a.frame, std::string("a.png"));
        QCOMPARE(a.kind, &perceptKind<Ball>());
        QCOMPARE(a.false_detections, (std::vector<std::size_t>{0}));
        QCOMPARE(a.missed, (std::vector<std::size_t>{0}));
        const FrameDisagreement& c = e.disagreements[1];
        QCOMPARE(c.frame, std::string("c.png"));
        QCOMPARE(c.kind, &perceptKind<Obstacle>());
        QVERIFY(c.false_detections.empty());
        QCOMPARE(c.missed, (std::vector<std::size_t>{0}));
        const FrameDisagreement& d = e.disagreements[2];
        QCOMPARE(d.frame, std::string("d.png"));
        QCOMPARE(d.kind, &perceptKind<Goalpost>());
        QCOMPARE(d.false_detections, (std::vector<std::size_t>{0}));
        QVERIFY(d.missed.empty());
        QCOMPARE(e.scores.frames_missing, std::size_t(1));
        // The scores are the sum of the frames' matches, as evaluate() gives them.
        QCOMPARE(e.scores.of<Ball>(), evaluate(detected, truth, 200, 200).of<Ball>());
        QCOMPARE(e.scores.of<Ball>(), (ClassScore{2, 1, 1}));
    }

    void matchFrameIsTheOnePathOfScoreFrame()
    {
        // scoreFrame (every kind complete) and matchFrame on a done frame agree.
        FrameAnnotation done;
        done.done = true;
        done.truth.output<Ball>() = {{50, 50, 5}};
        done.truth.output<FieldLine>() = {line(0, 100, 200, 100)};
        PerceptSet detected;
        detected.output<Ball>() = {{52, 50, 5}, {90, 90, 5}};
        detected.output<FieldLine>() = {line(0, 101, 200, 101)};
        EvaluationScores a;
        scoreFrame(detected, done.truth, 200, 200, a);
        EvaluationScores b;
        b.add(matchFrame(detected, done, 200, 200));
        QCOMPARE(a.of<Ball>(), b.of<Ball>());
        QCOMPARE(a.of<FieldLine>(), (ClassScore{1, 0, 0}));
        QCOMPARE(a.of<FieldLine>(), b.of<FieldLine>());
        const auto classes = a.classes();
        QCOMPARE(classes.size(), scoredKinds().size());
        QCOMPARE(classes[0].first, &perceptKind<Ball>());
        QCOMPARE(classes[0].second, (ClassScore{1, 1, 0}));
        QCOMPARE(&boundaryKind(), &perceptKind<FieldBoundary>());
    }
};

FIELDSIGHT_TEST_SUITE(TestEvaluationMarks, Core)

#include "test_evaluation_marks.moc"
