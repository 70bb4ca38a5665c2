// Tracks of annotated objects: flags that stay with their object, fresh track ids, keyframes with
// linear interpolation between them (switchable per keyframe), propagation to the next and the
// previous frames.
#include "support/test_suite.h"
#include "visioncore/services/annotation_tracks.h"

#include "visioncore/percepts/ball.h"
#include "visioncore/percepts/field_boundary.h"
#include "visioncore/percepts/goalpost.h"

#include <QtTest>

using namespace fieldsight;

namespace {

const PerceptKind& circles()
{
    return perceptKind<Ball>();
}

/// Ten frames "f0" .. "f9", in stream order.
std::vector<std::string> tenFrames()
{
    std::vector<std::string> names;
    for (int i = 0; i < 10; ++i)
        names.push_back("f" + std::to_string(i));
    return names;
}

EditShape circle(double x, double y, double r)
{
    return {{{x, y}}, r};
}

ObjectFlags keyframeOf(int track)
{
    ObjectFlags f;
    f.track = track;
    f.keyframe = true;
    return f;
}

/// `changes` applied to `annotations`.
void apply(Annotations& annotations, const AnnotationChanges& changes)
{
    for (auto& [name, frame] : changes.frames()) {
        if (frame)
            annotations.frames[name] = *frame;
        else
            annotations.frames.erase(name);
    }
}

} // namespace

class TestAnnotationTracks : public QObject
{
    Q_OBJECT

private slots:
    void aFreshTrackIsOneAboveTheHighestInTheFile()
    {
        Annotations a;
        QCOMPARE(freshTrack(a), 1);
        ObjectFlags f;
        f.track = 7;
        addObject(a.frames["f1"], circles(), {circle(1, 1, 1), f});
        f.track = 3;
        addObject(a.frames["f4"], circles(), {circle(2, 2, 1), f});
        addObject(a.frames["f4"], circles(), {circle(3, 3, 1), {}});
        QCOMPARE(freshTrack(a), 8);
        AnnotationChanges changes(a);
        f.track = 12;
        addObject(changes.edit("f9"), circles(), {circle(4, 4, 1), f});
        QCOMPARE(changes.freshTrack(), 13);
    }

    void removingAnObjectTakesItsFlagsAlong()
    {
        FrameAnnotation frame;
        for (int track : {1, 2, 3}) {
            ObjectFlags f;
            f.track = track;
            f.concealed = track == 3;
            QCOMPARE(addObject(frame, circles(), {circle(10.0 * track, 5, 2), f}),
                     std::size_t(track - 1));
        }
        removeObject(frame, circles(), 1);
        const std::vector<EditShape> left = shapesOf(frame, circles());
        QCOMPARE(left.size(), std::size_t(2));
        QCOMPARE(left[1].points[0].x, 30.0);
        QCOMPARE(frame.flagsOf(circles().truth_key, 1).track, 3);
        QVERIFY(frame.flagsOf(circles().truth_key, 1).concealed);
        QCOMPARE(findTrack(frame, circles(), 3), std::optional<std::size_t>(1));
        QCOMPARE(findTrack(frame, circles(), 2), std::nullopt);
    }

    void aCircleIsInterpolatedLinearlyBetweenTwoKeyframes()
    {
        const auto frames = tenFrames();
        Annotations a;
        addObject(a.frames["f2"], circles(), {circle(10, 20, 4), keyframeOf(5)});
        addObject(a.frames["f6"], circles(), {circle(30, 40, 8), keyframeOf(5)});
        AnnotationChanges changes(a);
        interpolateTrack(changes, frames, circles(), 5);
        apply(a, changes);
        QCOMPARE(a.frames.size(), std::size_t(5)); // f2..f6
        for (int i : {3, 4, 5}) {
            const FrameAnnotation& f = a.frames.at("f" + std::to_string(i));
            const auto balls = f.truth.list<Ball>();
            QCOMPARE(balls.size(), std::size_t(1));
            const double t = (i - 2) / 4.0;
            QCOMPARE(balls[0].x, 10 + 20 * t);
            QCOMPARE(balls[0].y, 20 + 20 * t);
            QCOMPARE(balls[0].radius, 4 + 4 * t);
            const ObjectFlags flags = f.flagsOf(circles().truth_key, 0);
            QVERIFY(flags.interpolated);
            QVERIFY(!flags.keyframe);
            QCOMPARE(flags.track, 5);
        }

        // The later keyframe moves: the frames between follow.
        AnnotationChanges moved(a);
        setShape(moved.edit("f6"), circles(), 0, circle(50, 20, 4));
        interpolateTrack(moved, frames, circles(), 5);
        apply(a, moved);
        QCOMPARE(a.frames.at("f4").truth.list<Ball>()[0].x, 30.0);
        QCOMPARE(a.frames.at("f4").truth.list<Ball>()[0].radius, 4.0);

        // Interpolation switched off on the later keyframe: the frames between are empty again
        // and no longer in the file.
        AnnotationChanges off(a);
        QVERIFY(setInterpolate(off, frames, 6, circles(), 0, false));
        apply(a, off);
        QCOMPARE(a.frames.size(), std::size_t(2));
        QVERIFY(!a.frames.at("f6").flagsOf(circles().truth_key, 0).interpolate);

        // Only a keyframe switches interpolation.
        addObject(a.frames["f8"], circles(), {circle(1, 1, 1), {}});
        AnnotationChanges plain(a);
        QVERIFY(!setInterpolate(plain, frames, 8, circles(), 0, false));
        QVERIFY(plain.frames().empty());
    }

    void aPlainObjectOfTheTrackBetweenKeyframesIsReplacedInPlace()
    {
        const auto frames = tenFrames();
        Annotations a;
        addObject(a.frames["f0"], circles(), {circle(0, 0, 2), keyframeOf(1)});
        // Frame 1: another object first, then the track's copy (concealed).
        addObject(a.frames["f1"], circles(), {circle(99, 99, 9), {}});
        ObjectFlags copy;
        copy.track = 1;
        copy.concealed = true;
        addObject(a.frames["f1"], circles(), {circle(0, 0, 2), copy});
        addObject(a.frames["f2"], circles(), {circle(20, 10, 2), {}});
        AnnotationChanges changes(a);
        // Marking the object on f2 a keyframe gives it a fresh track, not track 1.
        QVERIFY(setKeyframe(changes, frames, 2, circles(), 0, true));
        apply(a, changes);
        QCOMPARE(a.frames.at("f2").flagsOf(circles().truth_key, 0).track, 2);
        QCOMPARE(a.frames.at("f1").truth.list<Ball>()[1].x, 0.0);

        // Put on track 1 and marked: frame 1's copy becomes the interpolation, in place.
        AnnotationChanges join(a);
        join.edit("f2").setFlags(circles().truth_key, 0, keyframeOf(1));
        interpolateTrack(join, frames, circles(), 1);
        apply(a, join);
        const FrameAnnotation& f1 = a.frames.at("f1");
        QCOMPARE(f1.truth.list<Ball>().size(), std::size_t(2));
        QCOMPARE(f1.truth.list<Ball>()[0].x, 99.0);
        QCOMPARE(f1.truth.list<Ball>()[1].x, 10.0);
        QCOMPARE(f1.truth.list<Ball>()[1].y, 5.0);
        QVERIFY(f1.flagsOf(circles().truth_key, 1).interpolated);
        QVERIFY(f1.flagsOf(circles().truth_key, 1).concealed);

        // The first keyframe unmarked: nothing to interpolate between, the copy on f1 goes.
        AnnotationChanges unmark(a);
        QVERIFY(setKeyframe(unmark, frames, 0, circles(), 0, false));
        apply(a, unmark);
        QCOMPARE(a.frames.at("f1").truth.list<Ball>().size(), std::size_t(1));
        QCOMPARE(a.frames.at("f1").truth.list<Ball>()[0].x, 99.0);
        QVERIFY(!a.frames.at("f0").flagsOf(circles().truth_key, 0).keyframe);
    }

    void aDeletedInterpolatedObjectStaysDeleted()
    {
        const auto frames = tenFrames();
        Annotations a;
        addObject(a.frames["f2"], circles(), {circle(10, 20, 4), keyframeOf(5)});
        addObject(a.frames["f6"], circles(), {circle(30, 40, 8), keyframeOf(5)});
        addObject(a.frames["f8"], circles(), {circle(50, 40, 8), keyframeOf(5)});
        AnnotationChanges fill(a);
        interpolateTrack(fill, frames, circles(), 5);
        apply(a, fill);
        QCOMPARE(a.frames.size(), std::size_t(7)); // f2..f8

        // The interpolated ball on f4 deleted: f3 and f5 keep their shapes as plain objects of
        // the track, the span f2..f6 is no longer interpolated; the next span is untouched.
        AnnotationChanges del(a);
        QVERIFY(removeFromTrack(del, frames, 4, circles(), 0));
        apply(a, del);
        QVERIFY(a.frames.count("f4") == 0 || a.frames.at("f4").truth.list<Ball>().empty());
        for (const char* name : {"f3", "f5"}) {
            const ObjectFlags f = a.frames.at(name).flagsOf(circles().truth_key, 0);
            QVERIFY(!f.interpolated);
            QCOMPARE(f.track, 5);
        }
        QCOMPARE(a.frames.at("f3").truth.list<Ball>()[0].x, 15.0);
        QVERIFY(!a.frames.at("f6").flagsOf(circles().truth_key, 0).interpolate);
        QVERIFY(a.frames.at("f8").flagsOf(circles().truth_key, 0).interpolate);
        QVERIFY(a.frames.at("f7").flagsOf(circles().truth_key, 0).interpolated);

        // A keyframe moved afterwards does not bring the deleted ball back.
        AnnotationChanges moved(a);
        setShape(moved.edit("f2"), circles(), 0, circle(0, 0, 4));
        interpolateTrack(moved, frames, circles(), 5);
        apply(a, moved);
        QVERIFY(a.frames.count("f4") == 0 || a.frames.at("f4").truth.list<Ball>().empty());
        QCOMPARE(a.frames.at("f3").truth.list<Ball>()[0].x, 15.0);

        // A keyframe deleted: the span it ended is interpolated again from the keyframes left.
        AnnotationChanges key(a);
        QVERIFY(removeFromTrack(key, frames, 8, circles(), 0));
        apply(a, key);
        QVERIFY(a.frames.count("f7") == 0 || a.frames.at("f7").truth.list<Ball>().empty());
        QVERIFY(!removeFromTrack(key, frames, 8, circles(), 0)); // nothing left there
    }

    void boxesInterpolateToWholePixels()
    {
        const auto frames = tenFrames();
        const PerceptKind& boxes = perceptKind<Goalpost>();
        Annotations a;
        addObject(a.frames["f0"], boxes, {{{{0, 0}, {10, 10}}, 0}, keyframeOf(4)});
        addObject(a.frames["f4"], boxes, {{{{20, 10}, {30, 30}}, 0}, keyframeOf(4)});
        AnnotationChanges changes(a);
        interpolateTrack(changes, frames, boxes, 4);
        apply(a, changes);
        const Goalpost& mid = a.frames.at("f2").truth.list<Goalpost>().at(0);
        QCOMPARE(mid.left, 10);
        QCOMPARE(mid.top, 5);
        QCOMPARE(mid.right, 20);
        QCOMPARE(mid.bottom, 20);
        const Goalpost& q = a.frames.at("f1").truth.list<Goalpost>().at(0);
        QCOMPARE(q.left, 5);
        QCOMPARE(q.bottom, 15);
    }

    void propagationCopiesToTheNextAndPreviousFrames()
    {
        const auto frames = tenFrames();
        Annotations a;
        addObject(a.frames["f5"], circles(), {circle(40, 30, 5), {}});
        ObjectFlags other;
        other.track = 9;
        addObject(a.frames["f7"], circles(), {circle(1, 1, 1), other});

        AnnotationChanges forward(a);
        // Past the stream's end: f6..f9 only.
        QCOMPARE(propagate(forward, frames, 5, circles(), 0, 10), std::size_t(4));
        apply(a, forward);
        const int track = a.frames.at("f5").flagsOf(circles().truth_key, 0).track;
        QCOMPARE(track, 10); // fresh: above track 9
        for (int i = 6; i <= 9; ++i) {
            const FrameAnnotation& f = a.frames.at("f" + std::to_string(i));
            const auto index = findTrack(f, circles(), track);
            QVERIFY(index);
            QCOMPARE(shapesOf(f, circles())[*index], circle(40, 30, 5));
            QVERIFY(!f.flagsOf(circles().truth_key, *index).keyframe);
        }
        QCOMPARE(a.frames.at("f7").truth.list<Ball>().size(), std::size_t(2));

        // Backwards two frames; a keyframe of the track there is kept as placed.
        addObject(a.frames["f3"], circles(), {circle(7, 7, 7), keyframeOf(track)});
        AnnotationChanges back(a);
        setShape(back.edit("f5"), circles(), 0, circle(41, 31, 5));
        QCOMPARE(propagate(back, frames, 5, circles(), 0, -2), std::size_t(1));
        apply(a, back);
        QCOMPARE(a.frames.at("f4").truth.list<Ball>().at(0).x, 41.0);
        QCOMPARE(a.frames.at("f3").truth.list<Ball>().at(0).x, 7.0);
        QCOMPARE(a.frames.count("f2"), std::size_t(0));
        // The copy on f6 still has the shape propagated first.
        QCOMPARE(a.frames.at("f6").truth.list<Ball>().at(0).x, 40.0);
    }

    void aPolylineReplacesTheFramesOneAndHasNoKeyframes()
    {
        const auto frames = tenFrames();
        const PerceptKind& line = perceptKind<FieldBoundary>();
        Annotations a;
        addObject(a.frames["f0"], line, {{{{0, 50}, {100, 40}, {199, 45}}, 0}, {}});
        addObject(a.frames["f1"], line, {{{{0, 10}, {199, 10}}, 0}, {}});
        AnnotationChanges changes(a);
        QVERIFY(!setKeyframe(changes, frames, 0, line, 0, true));
        QCOMPARE(propagate(changes, frames, 0, line, 0, 2), std::size_t(2));
        apply(a, changes);
        for (const char* name : {"f1", "f2"}) {
            const auto shapes = shapesOf(a.frames.at(name), line);
            QCOMPARE(shapes.size(), std::size_t(1));
            QCOMPARE(shapes[0].points.size(), std::size_t(3));
            QCOMPARE(shapes[0].points[1].y, 40.0);
        }
    }
};

FIELDSIGHT_TEST_SUITE(TestAnnotationTracks, Core)

#include "test_annotation_tracks.moc"
