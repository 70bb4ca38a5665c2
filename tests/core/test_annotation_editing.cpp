// Frame-level annotation edits (services/annotation_editing): copying a frame, detections made
// truth, "reviewed, nothing here", and the next frame not done.
#include "support/percept_kinds.h"
#include "support/test_suite.h"
#include "visioncore/framework/controller.h"
#include "visioncore/percepts/ball.h"
#include "visioncore/percepts/goalpost.h"
#include "visioncore/percepts/obstacle.h"
#include "visioncore/services/annotation_editing.h"

#include "support/fake_stage.h"

#include <QtTest>

#include <nlohmann/json.hpp>

using namespace fieldsight;

namespace {

/// A frame with a ball (a track's keyframe, concealed) and a goalpost, done, balls reviewed.
FrameAnnotation sampleFrame()
{
    FrameAnnotation f;
    f.done = true;
    f.truth.output<Ball>() = {{100, 80, 6}};
    f.truth.output<Goalpost>() = {{}};
    f.truth.output<Goalpost>()[0].left = 10;
    f.truth.output<Goalpost>()[0].right = 20;
    f.truth.output<Goalpost>()[0].bottom = 90;
    ObjectFlags flags;
    flags.concealed = true;
    flags.track = 7;
    flags.keyframe = true;
    f.setFlags(perceptKind<Ball>().truth_key, 0, flags);
    f.reviewed.emplace(perceptKind<Obstacle>().truth_key);
    return f;
}

std::string json(const PerceptSet& set)
{
    nlohmann::ordered_json j = nlohmann::ordered_json::object();
    set.toJson(j, PerceptNames::Truth);
    return j.dump();
}

} // namespace

class TestAnnotationEditing : public QObject
{
    Q_OBJECT

private slots:
    void frameStatesMatchFramesByStem()
    {
        Annotations a;
        a.frames["frame_000001.png"].done = true;
        a.frames["frame_000003.png"].done = false;
        const std::vector<std::string> names{"frame_000000", "frame_000001", "frame_000002",
                                             "frame_000003"};
        const FrameStates s = frameStates(names, a);
        QCOMPARE(s.annotated, (std::vector<bool>{false, true, false, true}));
        QCOMPARE(s.done, (std::vector<bool>{false, true, false, false}));
    }

    void copyKeepsObjectsAndFlagsButIsNotDone()
    {
        const FrameAnnotation from = sampleFrame();
        const FrameAnnotation copy = copiedAnnotation(from);
        QVERIFY(!copy.done);
        QVERIFY(copy.reviewed.empty());
        QCOMPARE(json(copy.truth), json(from.truth));
        const ObjectFlags f = copy.flagsOf(perceptKind<Ball>().truth_key, 0);
        QCOMPARE(f.track, 7);
        QVERIFY(f.concealed);
        QVERIFY(f.keyframe);
        QVERIFY(!(copy == from)); // done and reviewed differ
    }

    void previousAnnotatedIsTheNearestEarlierFrame()
    {
        const std::vector<bool> annotated{true, false, true, false, false};
        QCOMPARE(previousAnnotated(annotated, 4), std::optional<std::size_t>(2));
        QCOMPARE(previousAnnotated(annotated, 2), std::optional<std::size_t>(0));
        QCOMPARE(previousAnnotated(annotated, 0), std::optional<std::size_t>());
        QCOMPARE(previousAnnotated(annotated, 99), std::optional<std::size_t>(2));
    }

    void detectionsReplaceTheKindsTheDetectorRan()
    {
        PerceptSet detections;
        detections.output<Ball>() = {{30, 40, 5}, {200, 100, 9}};
        detections.output<Obstacle>(); // ran, found nothing
        const FrameAnnotation before = sampleFrame();
        const FrameAnnotation after = detectionsAsTruth(before, detections, test::standardKinds());

        QVERIFY(!after.done);
        // Exactly the detected balls, with default flags (the old ball's track is gone).
        QCOMPARE(after.truth.list<Ball>().size(), std::size_t(2));
        QCOMPARE(after.truth.list<Ball>()[1].x, 200.0);
        QCOMPARE(after.truth.list<Ball>()[1].radius, 9.0);
        QVERIFY(after.flagsOf(perceptKind<Ball>().truth_key, 0).isDefault());
        // The obstacles' list present and empty, and no longer "reviewed".
        QVERIFY(after.truth.find<Obstacle>());
        QVERIFY(after.truth.find<Obstacle>()->empty());
        QVERIFY(!after.reviewed.count(std::string(perceptKind<Obstacle>().truth_key)));
        // The goalposts' stage did not run: the annotated post stays.
        QCOMPARE(after.truth.list<Goalpost>().size(), std::size_t(1));
        QCOMPARE(after.truth.list<Goalpost>()[0].right, 20);
    }

    void detectionsOfAKindNotDrawnByHandAreLeftOut()
    {
        PerceptSet detections;
        detections.output<test::FakeMark>() = {{1, 2, 3}};
        std::vector<const PerceptKind*> with_fake = test::standardKinds();
        with_fake.push_back(&perceptKind<test::FakeMark>());
        const FrameAnnotation after = detectionsAsTruth({}, detections, with_fake);
        QVERIFY(!after.truth.find<test::FakeMark>());
        QCOMPARE(after.truth.presentCount(), std::size_t(0));
    }

    void reviewedNothingHereEmptiesTheList()
    {
        const FrameAnnotation before = sampleFrame();
        const FrameAnnotation after = reviewedNothingHere(before, perceptKind<Ball>());
        QVERIFY(after.truth.find<Ball>());
        QVERIFY(after.truth.find<Ball>()->empty());
        QVERIFY(after.reviewed.count("balls"));
        QVERIFY(after.flags.find("balls") == after.flags.end());
        QCOMPARE(after.truth.list<Goalpost>().size(), std::size_t(1));
        QCOMPARE(objectCount(before), std::size_t(2));
        QCOMPARE(objectCount(after), std::size_t(1));
    }

    void nextNotDoneGoesRoundAndSaysSo()
    {
        const std::vector<bool> done{false, true, true, false, true};
        auto hit = nextNotDone(done, 0, 1);
        QVERIFY(hit);
        QCOMPARE(hit->index, std::size_t(3));
        QVERIFY(!hit->wrapped);
        hit = nextNotDone(done, 3, 1);
        QVERIFY(hit);
        QCOMPARE(hit->index, std::size_t(0));
        QVERIFY(hit->wrapped);
        hit = nextNotDone(done, 3, -1);
        QCOMPARE(hit->index, std::size_t(0));
        QVERIFY(!hit->wrapped);
        hit = nextNotDone(done, 0, -1);
        QCOMPARE(hit->index, std::size_t(3));
        QVERIFY(hit->wrapped);
        // The only frame not done is the one shown: found last, after going round.
        hit = nextNotDone({true, false, true}, 1, 1);
        QCOMPARE(hit->index, std::size_t(1));
        QVERIFY(hit->wrapped);
        QVERIFY(!nextNotDone({true, true}, 0, 1));
        QVERIFY(!nextNotDone({}, 0, 1));
    }
};

FIELDSIGHT_TEST_SUITE(TestAnnotationEditing, None)

#include "test_annotation_editing.moc"
