// The light tracker's check of the level against the table (services/light_level_check.h): the
// levels at which the table reads a frame's post, ball and robot colours best.
#include "services/light_level_check.h"
#include "support/test_suite.h"
#include "visioncore/basics/ycbcr.h"

#include <QtTest>

#include <opencv2/core.hpp>

#include <array>
#include <cmath>
#include <memory>
#include <optional>

using namespace fieldsight;

namespace {

/// A post's olive yellow, dark enough that 1.5 times it clips no channel.
constexpr std::array<double, 3> kYellow{140, 120, 30};

/// A 320 x 240 frame of mid grey (a colour no class claims) with a 100 x 100 patch of `rgb`
/// times `gain`, in Y, Cb, Cr.
cv::Mat frameWithPatch(const std::array<double, 3>& rgb, double gain)
{
    cv::Mat bgr(240, 320, CV_8UC3, cv::Scalar(128, 128, 128));
    bgr(cv::Rect(110, 70, 100, 100)).setTo(cv::Scalar(rgb[2] * gain, rgb[1] * gain, rgb[0] * gain));
    return bgrToYcbcr(bgr);
}

/// A table whose yellow is narrow in Y: the cells within 4 levels in Y and 3 in Cb and Cr of
/// kYellow (about 3% of its level), all else unclassified; with `carpet`, grey is green.
std::shared_ptr<const ColourLut> narrowYellowTable(bool grey_is_green = false)
{
    const cv::Vec3b centre = frameWithPatch(kYellow, 1.0).at<cv::Vec3b>(120, 160);
    ColourLut lut;
    for (int y = centre[0] - 4; y <= centre[0] + 4; ++y)
        for (int cb = centre[1] - 3; cb <= centre[1] + 3; ++cb)
            for (int cr = centre[2] - 3; cr <= centre[2] + 3; ++cr)
                lut.setCell(ColourLut::index(std::uint8_t(y), std::uint8_t(cb), std::uint8_t(cr)),
                            Colour::Yellow);
    if (grey_is_green) {
        const cv::Vec3b grey = frameWithPatch(kYellow, 1.0).at<cv::Vec3b>(0, 0);
        lut.setCell(ColourLut::index(grey[0], grey[1], grey[2]), Colour::Green);
    }
    return std::make_shared<const ColourLut>(std::move(lut));
}

constexpr std::array<double, 3> kTablesLight{1, 1, 1};

/// Whether `range` holds `level` and no level two steps (0.12) or more from it: a pixel is read
/// through its key of 4 levels and the table's cells of 2, so the level next to the true one
/// may read too.
bool holdsOnly(const std::optional<TableLevelCheck::Range>& range, double level)
{
    return range && range->lo <= level + 1e-9 && level - 1e-9 <= range->hi &&
           range->lo > level - 0.1 && range->hi < level + 0.1;
}

QString textOf(const std::optional<TableLevelCheck::Range>& range)
{
    return range ? QString("%1 .. %2").arg(range->lo).arg(range->hi) : QString("none");
}

} // namespace

class TestLightLevelCheck : public QObject
{
    Q_OBJECT

private slots:
    void aPostInTheTablesLightReadsBestAtTheTablesLevel()
    {
        TableLevelCheck check(narrowYellowTable());
        const auto range = check.measure(frameWithPatch(kYellow, 1.0), kTablesLight);
        QVERIFY2(holdsOnly(range, 0.0), qPrintable(textOf(range)));
    }

    void aBrighterPostReadsBestAtTheLevelOfItsLight()
    {
        // 20% brighter: ln 1.2 = 0.18, a level of the grid (0.06 apart).
        TableLevelCheck check(narrowYellowTable());
        const auto range = check.measure(frameWithPatch(kYellow, 1.2), kTablesLight);
        QVERIFY2(holdsOnly(range, 0.18), qPrintable(textOf(range)));
    }

    void theCandidatesFollowTheTrackersLevel()
    {
        // 50% brighter (ln 0.405): out of the 11 levels around the table's own (+-0.30), so
        // nothing is read there; around a tracker already at +0.30 it is read at +0.42.
        TableLevelCheck check(narrowYellowTable());
        const cv::Mat frame = frameWithPatch(kYellow, 1.5);
        QVERIFY(!check.measure(frame, kTablesLight).has_value());
        const double g = std::exp(0.30);
        const auto range = check.measure(frame, {g, g, g});
        QVERIFY2(holdsOnly(range, 0.42), qPrintable(textOf(range)));
    }

    void theCarpetAloneSaysNothing()
    {
        // A frame of carpet (green is not scored: it is broad in Y) and no post: every level
        // reads as many, so the check does not say.
        TableLevelCheck check(narrowYellowTable(true));
        cv::Mat grey = frameWithPatch(kYellow, 1.0);
        grey.setTo(grey.at<cv::Vec3b>(0, 0));
        QVERIFY(!check.measure(grey, kTablesLight).has_value());
    }

    void aSideAtTheCandidatesEndIsOpen()
    {
        // A post read at the last candidate (+0.30 around the table's light): the range is open
        // above, the level may be beyond.
        TableLevelCheck check(narrowYellowTable());
        const auto range = check.measure(frameWithPatch(kYellow, std::exp(0.30)), kTablesLight);
        QVERIFY2(range && range->lo > 0.15 && std::isinf(range->hi) && range->hi > 0,
                 qPrintable(textOf(range)));
    }

    void aSecondLookReadsWhatTheFirstRead()
    {
        // What a pixel key reads is remembered: the same frame reads the same, and a change of
        // the light's colour is worked out afresh (no stale reads of the old colour).
        TableLevelCheck check(narrowYellowTable());
        const cv::Mat frame = frameWithPatch(kYellow, 1.2);
        const auto first = check.measure(frame, kTablesLight);
        const auto again = check.measure(frame, kTablesLight);
        QVERIFY(first && again);
        QCOMPARE(again->lo, first->lo);
        QCOMPARE(again->hi, first->hi);
        // A light 30% redder: the patch's yellow no longer reads at any level.
        QVERIFY(!check.measure(frame, {1.3, 1.0, 1.0}).has_value());
        const auto back = check.measure(frame, kTablesLight);
        QVERIFY(back.has_value());
        QCOMPARE(back->lo, first->lo);
    }
};

FIELDSIGHT_TEST_SUITE(TestLightLevelCheck, None)

#include "test_light_level_check.moc"
