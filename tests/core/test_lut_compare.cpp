// Comparing colour tables (visioncore/services/lut_compare.h): the diff of two known tables lists
// exactly the cells that differ, by class pair; a merge by class copies only those classes and
// counts conflicts; the pixel tally and mask agree with a pixel-by-pixel count; and the detection
// delta of two runs follows the eval matching rules.
#include "support/test_suite.h"
#include "visioncore/percepts/ball.h"
#include "visioncore/services/evaluation.h"
#include "visioncore/services/lut_compare.h"

#include <opencv2/core.hpp>

#include <QtTest>

#include <random>

using namespace fieldsight;

class TestLutCompare : public QObject
{
    Q_OBJECT

private slots:
    void theDiffOfTwoKnownTablesListsExactlyTheChangedCells()
    {
        ColourLut a, b;
        a.setCell(10, Colour::Green);
        b.setCell(10, Colour::Green); // the same: not listed
        a.setCell(20, Colour::Orange);
        b.setCell(20, Colour::Pink);
        b.setCell(30, Colour::White);
        a.setCell(ColourLut::kCells - 1, Colour::Blue);
        const LutDiff diff = diffLuts(a, b);
        QCOMPARE(diff.cells.size(), std::size_t(3));
        QCOMPARE(diff.cells[0].cell, 20u);
        QCOMPARE(diff.cells[0].before, Colour::Orange);
        QCOMPARE(diff.cells[0].after, Colour::Pink);
        QCOMPARE(diff.cells[1].cell, 30u);
        QCOMPARE(diff.cells[1].before, Colour::Unclassified);
        QCOMPARE(diff.cells[2].cell, std::uint32_t(ColourLut::kCells - 1));
        const auto pairs = diff.pairCounts();
        QCOMPARE(pairs[std::size_t(Colour::Orange)][std::size_t(Colour::Pink)], std::size_t(1));
        QCOMPARE(pairs[0][std::size_t(Colour::White)], std::size_t(1));
        QCOMPARE(pairs[std::size_t(Colour::Blue)][0], std::size_t(1));
        QCOMPARE(pairs[std::size_t(Colour::Green)][std::size_t(Colour::Green)], std::size_t(0));

        // Applying the diff turns the first table into the second; the mask holds its cells.
        ColourLut c = a;
        applyChanges(c, diff.cells);
        QVERIFY(c == b);
        const CellMask mask = CellMask::differences(a, b);
        QCOMPARE(mask.count(), std::size_t(3));
        QVERIFY(mask.test(20) && mask.test(30) && !mask.test(10));
    }

    void aMergeCopiesOnlyTheChosenClasses()
    {
        ColourLut into, from;
        into.setCell(1, Colour::Green);
        from.setCell(1, Colour::Orange); // a conflict
        from.setCell(2, Colour::Orange); // new
        from.setCell(3, Colour::White);  // not chosen
        into.setCell(4, Colour::Yellow); // the source leaves it alone
        const auto all = mergeChanges(into, from, {Colour::Orange});
        QCOMPARE(all.size(), std::size_t(2));
        QCOMPARE(conflictsIn(all), std::size_t(1));
        const auto gentle = mergeChanges(into, from, {Colour::Orange}, true);
        QCOMPARE(gentle.size(), std::size_t(1));
        QCOMPARE(gentle[0].cell, 2u);
        QCOMPARE(conflictsIn(gentle), std::size_t(0));
        applyChanges(into, all);
        QCOMPARE(into.cell(1), Colour::Orange);
        QCOMPARE(into.cell(3), Colour::Unclassified);
        QCOMPARE(into.cell(4), Colour::Yellow);
    }

    void theTallyAgreesWithAPixelByPixelCount()
    {
        std::mt19937 rng(7);
        cv::Mat frame(37, 53, CV_8UC3);
        cv::randu(frame, 0, 256);
        ColourLut lut;
        std::vector<std::uint32_t> cells;
        for (int i = 0; i < 200000; ++i) {
            const auto cell = std::uint32_t(rng() % ColourLut::kCells);
            lut.setCell(cell, Colour::Green);
            if (i % 3 == 0)
                cells.push_back(cell);
        }
        const CellMask mask = CellMask::of(cells);
        std::size_t in = 0, unclassified = 0;
        for (int y = 0; y < frame.rows; ++y)
            for (int x = 0; x < frame.cols; ++x) {
                const cv::Vec3b c = frame.at<cv::Vec3b>(y, x);
                in += mask.test(c[0], c[1], c[2]);
                unclassified += lut.classify(c[0], c[1], c[2]) == Colour::Unclassified;
            }
        QVERIFY(in > 0 && unclassified > 0);
        const PixelTally tally = PixelTallier(lut, mask)(frame);
        QCOMPARE(tally.in_mask, in);
        QCOMPARE(tally.unclassified, unclassified);
        QCOMPARE(tally.pixels, std::size_t(37 * 53));
        QCOMPARE(std::size_t(cv::countNonZero(pixelsIn(frame, mask))), in);
    }

    void theDetectionDeltaUsesTheMatchingRules()
    {
        PerceptSet before, after;
        before.output<Ball>() = {{100, 100, 10}, {200, 50, 4}};
        after.output<Ball>() = {{102, 101, 10}, {20, 20, 5}}; // one moved a little, one new
        const DetectionDelta d = compareDetections(before, after, 320, 240);
        QCOMPARE(d.of("balls").appeared, 1);
        QCOMPARE(d.of("balls").vanished, 1);
        QCOMPARE(d.appeared(), 1);
        QCOMPARE(compareDetections(before, before, 320, 240), DetectionDelta{});
    }
};

FIELDSIGHT_TEST_SUITE(TestLutCompare, None)

#include "test_lut_compare.moc"
