// What a LUT edit touches (visioncore/services/lut_editing.h): the tolerance box, the brush, the
// magic wand, and changes that undo exactly.
#include "support/test_suite.h"
#include "support/synthetic_frames.h"
#include "visioncore/services/lut_editing.h"

#include <QtTest>

#include <algorithm>
#include <map>
#include <set>

using namespace fieldsight;

namespace {

std::uint32_t cellOf(int y, int cb, int cr)
{
    return std::uint32_t(ColourLut::index(std::uint8_t(y), std::uint8_t(cb), std::uint8_t(cr)));
}

} // namespace

class TestLutEditing : public QObject
{
    Q_OBJECT

private slots:
    void aZeroToleranceBoxIsTheColoursOwnCell()
    {
        const auto cells = cellsInBox(100, 90, 200, {});
        QCOMPARE(cells.size(), std::size_t(1));
        QCOMPARE(cells[0], cellOf(100, 90, 200));
    }

    void theBoxCoversEveryLevelWithinTheTolerance()
    {
        // Y 97..103 is cells 48..51; Cb 88..92 is 44..46; Cr 200 alone is 100.
        const auto cells = cellsInBox(100, 90, 200, {3, 2, 0});
        QCOMPARE(cells.size(), std::size_t(4 * 3 * 1));
        for (int y = 97; y <= 103; ++y)
            for (int cb = 88; cb <= 92; ++cb)
                QVERIFY(std::binary_search(cells.begin(), cells.end(), cellOf(y, cb, 200)));
        QVERIFY(!std::binary_search(cells.begin(), cells.end(), cellOf(95, 90, 200)));
        QVERIFY(std::is_sorted(cells.begin(), cells.end()));
    }

    void theBoxIsClampedAtTheEndsOfTheRange()
    {
        const auto cells = cellsInBox(1, 254, 128, {10, 10, 0});
        // Y 0..11 -> cells 0..5; Cb 244..255 -> cells 122..127.
        QCOMPARE(cells.size(), std::size_t(6 * 6));
        QCOMPARE(cells.front(), cellOf(0, 244, 128));
        QCOMPARE(cells.back(), cellOf(11, 255, 128));
    }

    void aBrushIsADiscClippedToTheImage()
    {
        QCOMPARE(brushPixels({5, 5}, 0, {10, 10}).size(), std::size_t(1));
        QCOMPARE(brushPixels({5, 5}, 1, {10, 10}).size(), std::size_t(5));
        QCOMPARE(brushPixels({5, 5}, 2, {10, 10}).size(), std::size_t(13));
        QCOMPARE(brushPixels({0, 0}, 1, {10, 10}).size(), std::size_t(3)); // a corner
        QVERIFY(brushPixels({-5, -5}, 1, {10, 10}).empty());
    }

    void theWandTakesOnlyTheConnectedSimilarPixels()
    {
        cv::Mat frame = test::filledFrame(40, 30, Colour::Green);
        test::fillRect(frame, 2, 2, 9, 9, Colour::Orange);     // 8x8, the seed's
        test::fillRect(frame, 20, 20, 24, 24, Colour::Orange); // apart: not taken
        const auto pixels = wandPixels(frame, {5, 5}, {4, 4, 4});
        QCOMPARE(pixels.size(), std::size_t(64));
        for (const cv::Point& p : pixels)
            QVERIFY(p.x >= 2 && p.x <= 9 && p.y >= 2 && p.y <= 9);
        QVERIFY(wandPixels(frame, {50, 5}, {}).empty());
        // A tolerance wide enough for both colours takes the whole frame.
        QCOMPARE(wandPixels(frame, {5, 5}, {255, 255, 255}).size(), std::size_t(40 * 30));
    }

    void cellsOfPixelsAreTheirColoursCells()
    {
        cv::Mat frame = test::filledFrame(10, 10, Colour::Green);
        test::fillRect(frame, 0, 0, 0, 0, Colour::Orange);
        const auto cells = cellsOfPixels(frame, {{0, 0}, {5, 5}, {6, 6}, {99, 99}});
        const test::ClassPixel o = test::pixelFor(Colour::Orange);
        const test::ClassPixel g = test::pixelFor(Colour::Green);
        const std::set<std::uint32_t> want{cellOf(o.y, o.cb, o.cr), cellOf(g.y, g.cb, g.cr)};
        QCOMPARE(std::set<std::uint32_t>(cells.begin(), cells.end()), want);
        QCOMPARE(cells.size(), want.size());
    }

    void changesLeaveOutCellsAlreadyRightAndCanSpareOtherClasses()
    {
        ColourLut lut;
        lut.setCell(10, Colour::Orange);
        lut.setCell(11, Colour::Green);
        const auto all = changesTo(lut, {10, 11, 12}, Colour::Orange);
        QCOMPARE(all.size(), std::size_t(2)); // 10 is orange already
        const auto spare = changesTo(lut, {10, 11, 12}, Colour::Orange, true);
        QCOMPARE(spare.size(), std::size_t(1));
        QCOMPARE(spare[0].cell, std::uint32_t(12));
    }

    void changesUndoToTheExactBytes()
    {
        ColourLut lut = test::testLut();
        const ColourLut before = lut;
        auto first = changesTo(lut, cellsInBox(120, 100, 160, {20, 20, 20}), Colour::Blue);
        applyChanges(lut, first);
        auto second = changesTo(lut, cellsInBox(110, 110, 150, {20, 20, 20}), Colour::White);
        applyChanges(lut, second);
        QVERIFY(lut != before);
        // One list (a merged stroke) with repeated cells, undone in reverse.
        std::vector<CellChange> merged = first;
        merged.insert(merged.end(), second.begin(), second.end());
        applyChanges(lut, merged, false);
        QVERIFY(lut == before);
        applyChanges(lut, merged, true);
        QCOMPARE(lut.cell(cellOf(110, 110, 150)), Colour::White);
        QCOMPARE(cellsPerClass(lut)[std::size_t(Colour::White)] > 0, true);
    }

    void aShiftIsEstimatedFromKnownPixelsAndMovesTheTable()
    {
        // Green cells around (100, 90, 120); the venue's field reads 12 brighter, Cb -6, Cr +8.
        ColourLut lut;
        for (std::uint32_t c : cellsInBox(100, 90, 120, {10, 6, 6}))
            lut.setCell(c, Colour::Green);
        std::vector<cv::Vec3b> field;
        for (int i = -5; i <= 5; ++i)
            field.emplace_back(std::uint8_t(112 + i), std::uint8_t(84 - i / 2),
                               std::uint8_t(128 + i / 3));
        const ColourShift shift = estimateShift(lut, Colour::Green, field);
        QVERIFY(std::abs(shift.y - 12) <= 2 && std::abs(shift.cb + 6) <= 2 &&
                std::abs(shift.cr - 8) <= 2);
        QCOMPARE(estimateShift(lut, Colour::Orange, field), ColourShift{}); // no orange cells

        ColourLut moved = lut;
        applyChanges(moved, shiftChanges(lut, {12, -6, 8}));
        QCOMPARE(moved.classify(112, 84, 128), Colour::Green);
        QCOMPARE(moved.classify(100 - 10, 90, 120), Colour::Unclassified); // left behind
        QCOMPARE(cellsPerClass(moved)[std::size_t(Colour::Green)],
                 cellsPerClass(lut)[std::size_t(Colour::Green)]);
        // Undone exactly.
        applyChanges(moved, shiftChanges(lut, {12, -6, 8}), false);
        QVERIFY(moved == lut);
    }

    void softClassesAppearWhereTwoClassesMeet()
    {
        ColourLut lut;
        lut.setCell(1, Colour::Pink);
        lut.setCell(2, Colour::Yellow);
        lut.setCell(3, Colour::Green);
        lut.setCell(4, Colour::PinkOrange);
        const auto changes = changesTo(lut, {0, 1, 2, 3, 4}, Colour::Orange, false, true);
        std::map<std::uint32_t, Colour> after;
        for (const CellChange& c : changes)
            after[c.cell] = c.after;
        const std::map<std::uint32_t, Colour> expected = {{0, Colour::Orange},
                                                          {1, Colour::PinkOrange},
                                                          {2, Colour::YellowOrange},
                                                          {3, Colour::Orange}};
        QCOMPARE(after, expected); // cell 4 is already soft with orange: unchanged
        QCOMPARE(softMeet(Colour::Orange, Colour::Pink), Colour::PinkOrange);
        QCOMPARE(softMeet(Colour::YellowOrange, Colour::Yellow), Colour::YellowOrange);
        QCOMPARE(softMeet(Colour::YellowOrange, Colour::Pink), Colour::Pink);
        // Without the option, the painted class wins.
        for (const CellChange& c : changesTo(lut, {1, 2}, Colour::Orange))
            QCOMPARE(c.after, Colour::Orange);
    }

    void aStrokeLeavesNoGapBetweenDistantEvents()
    {
        // A drag from (0, 0) to (10, 4): one centre per column, each next to the one before.
        const auto points = strokePoints({0, 0}, {10, 4}, true);
        QCOMPARE(points.size(), std::size_t(11));
        QCOMPARE(points.front(), cv::Point(0, 0));
        QCOMPARE(points.back(), cv::Point(10, 4));
        for (std::size_t i = 1; i < points.size(); ++i) {
            QCOMPARE(points[i].x - points[i - 1].x, 1);
            QVERIFY(std::abs(points[i].y - points[i - 1].y) <= 1);
        }
    }

    void aStrokesLaterPieceStartsAfterWhereTheLastEnded()
    {
        const auto points = strokePoints({5, 5}, {5, 8}, false);
        QCOMPARE(points, (std::vector<cv::Point>{{5, 6}, {5, 7}, {5, 8}}));
        QCOMPARE(strokePoints({5, 5}, {5, 5}, false), std::vector<cv::Point>{cv::Point(5, 5)});
        QCOMPARE(strokePoints({5, 5}, {5, 5}, true), std::vector<cv::Point>{cv::Point(5, 5)});
    }

    void strokePixelsCoverTheBrushAlongThePath()
    {
        const auto pixels = strokePixels({2, 2}, {12, 2}, 1, {20, 10}, true);
        const std::set<std::pair<int, int>> covered = [&] {
            std::set<std::pair<int, int>> s;
            for (const cv::Point& p : pixels)
                s.insert({p.x, p.y});
            return s;
        }();
        for (int x = 2; x <= 12; ++x)
            for (int y = 1; y <= 3; ++y)
                QVERIFY2(covered.count({x, y}), qPrintable(QStringLiteral("%1,%2").arg(x).arg(y)));
        QVERIFY(!covered.count({14, 2}));
        QVERIFY(!covered.count({2, 4}));
    }

    void aUvStrokeCoversEveryCellOnItsWayOnce()
    {
        const auto cells = strokeUvCells({10, 10}, {20, 10}, 0, 5, 6, true);
        QCOMPARE(cells.size(), std::size_t(11 * 2));
        QVERIFY(std::is_sorted(cells.begin(), cells.end()));
        QVERIFY(std::adjacent_find(cells.begin(), cells.end()) == cells.end());
        for (int cb = 10; cb <= 20; ++cb)
            QVERIFY(std::binary_search(cells.begin(), cells.end(),
                                       std::uint32_t((5 << 14) | (cb << 7) | 10)));
    }

    void takenCellsAreCountedByTheirClassBefore()
    {
        const std::vector<CellChange> changes{{1, Colour::Green, Colour::Orange},
                                              {2, Colour::Green, Colour::Orange},
                                              {3, Colour::White, Colour::Orange},
                                              {4, Colour::Unclassified, Colour::Orange}};
        const auto taken = cellsTakenByClass(changes);
        QCOMPARE(taken[std::size_t(Colour::Green)], std::size_t(2));
        QCOMPARE(taken[std::size_t(Colour::White)], std::size_t(1));
        QCOMPARE(taken[std::size_t(Colour::Unclassified)], std::size_t(0));
        QCOMPARE(taken[std::size_t(Colour::Orange)], std::size_t(0));
    }
};

FIELDSIGHT_TEST_SUITE(TestLutEditing, None)

#include "test_lut_editing.moc"
