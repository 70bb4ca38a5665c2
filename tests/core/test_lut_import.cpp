// Importing other teams' colour tables: B-Human .c64, rUNSWift .nnmc.bz2, UPenn .raw.
#include "support/child_process.h"
#include "support/test_suite.h"
#include "visioncore/io/lut_import.h"

#include "support/synthetic_frames.h"
#include "support/test_images.h"

#include <QtTest>

#include <bzlib.h>

#include <array>
#include <cstring>
#include <fstream>

using namespace fieldsight;

namespace {

void putRun(std::string& out, std::uint32_t length, std::uint8_t value)
{
    char raw[4];
    std::memcpy(raw, &length, 4);
    out.append(raw, 4);
    if (length != 0)
        out.push_back(char(value));
}

std::array<std::size_t, kColourCount> histogram(const ColourLut& lut)
{
    std::array<std::size_t, kColourCount> counts{};
    for (std::size_t i = 0; i < ColourLut::kCells; ++i)
        ++counts[std::size_t(lut.cell(i))];
    return counts;
}

std::string bzip2(const std::string& data)
{
    std::string out(data.size() + data.size() / 100 + 600, '\0');
    unsigned int size = unsigned(out.size());
    const int code = BZ2_bzBuffToBuffCompress(out.data(), &size, const_cast<char*>(data.data()),
                                              unsigned(data.size()), 9, 0, 0);
    if (code != BZ_OK)
        return {};
    out.resize(size);
    return out;
}

std::string errorOf(const Result<ColourLut>& result)
{
    return result.ok() ? std::string("(imported)") : result.error().message;
}

} // namespace

class TestLutImport : public QObject
{
    Q_OBJECT

private slots:
    // --- B-Human .c64 --------------------------------------------------------------------------

    void c64CellCoversTwoByTwoByTwoCellsAndMapsClasses()
    {
        // One 64^3 cell (Y>>2 = 10, Cb>>2 = 20, Cr>>2 = 30) is orange (1), one is robotBlue (8).
        const std::size_t orange_cell = 10u << 12 | 20u << 6 | 30u;
        const std::size_t robot_blue_cell = orange_cell + 1;
        std::string rle;
        putRun(rle, std::uint32_t(orange_cell), 0);
        putRun(rle, 1, 1);
        putRun(rle, 1, 8);
        putRun(rle, std::uint32_t(64 * 64 * 64 - robot_blue_cell - 1), 5);
        putRun(rle, 0, 0);
        QTemporaryDir dir;
        const std::string path = dir.filePath("table.c64").toStdString();
        test::writeBytes(path, rle);

        auto lut = importLut(path);
        QVERIFY2(lut.ok(), errorOf(lut).c_str());
        const ColourLut& t = lut.value();
        QCOMPARE(t.classify(40, 80, 120), Colour::Orange);
        QCOMPARE(t.classify(43, 83, 123), Colour::Orange);
        QCOMPARE(t.classify(39, 80, 120), Colour::Unclassified);
        QCOMPARE(t.classify(40, 80, 119), Colour::Unclassified);
        QCOMPARE(t.classify(40, 80, 124), Colour::ShadowBlue); // next source cell: robotBlue
        QCOMPARE(t.classify(40, 80, 128), Colour::Green);
        const auto counts = histogram(t);
        QCOMPARE(counts[std::size_t(Colour::Orange)], std::size_t(8));
        QCOMPARE(counts[std::size_t(Colour::ShadowBlue)], std::size_t(8));
        QCOMPARE(counts[std::size_t(Colour::Unclassified)], orange_cell * 8);
    }

    void c64MapsEveryBHumanClass()
    {
        // Classes 0..8 in the first nine cells, then none.
        std::string rle;
        for (std::uint8_t c = 0; c <= 8; ++c)
            putRun(rle, 1, c);
        putRun(rle, 64 * 64 * 64 - 9, 0);
        putRun(rle, 0, 0);
        QTemporaryDir dir;
        const std::string path = dir.filePath("classes.c64").toStdString();
        test::writeBytes(path, rle);
        auto lut = importLut(path);
        QVERIFY2(lut.ok(), errorOf(lut).c_str());
        const Colour expected[] = {Colour::Unclassified, Colour::Orange, Colour::Yellow,
                                   Colour::Blue,         Colour::White,  Colour::Green,
                                   Colour::ShadowObject, Colour::Pink,   Colour::ShadowBlue};
        for (std::uint8_t c = 0; c <= 8; ++c)
            QCOMPARE(lut.value().classify(0, 0, std::uint8_t(4 * c)), expected[c]);
    }

    void c64RunOverrunIsAnError()
    {
        std::string rle;
        putRun(rle, 64 * 64 * 64 - 1, 0);
        putRun(rle, 2, 5);
        putRun(rle, 0, 0);
        QTemporaryDir dir;
        const std::string path = dir.filePath("over.c64").toStdString();
        test::writeBytes(path, rle);
        QCOMPARE(errorOf(importLut(path)),
                 path + ": run-length data overruns the 64x64x64 table at byte offset 5 "
                        "(run of 2 after 262143 cells)");
    }

    void c64ShortOrTruncatedDataIsAnError()
    {
        QTemporaryDir dir;
        const std::string path = dir.filePath("short.c64").toStdString();
        std::string rle;
        putRun(rle, 1000, 0);
        putRun(rle, 0, 0);
        test::writeBytes(path, rle);
        QCOMPARE(errorOf(importLut(path)),
                 path + ": run-length data ends after 1000 of 262144 cells");

        test::writeBytes(path, rle.substr(0, 7)); // no end marker
        QCOMPARE(errorOf(importLut(path)),
                 path + ": truncated at byte offset 5 (expected a run length or the end marker)");

        std::string bad_class;
        putRun(bad_class, 64 * 64 * 64, 9);
        putRun(bad_class, 0, 0);
        test::writeBytes(path, bad_class);
        QCOMPARE(errorOf(importLut(path)), path + ": unknown colour class 9 at byte offset 4");
    }

    void realBHumanTableKeepsItsClassCountsAndSegmentsTheField()
    {
        const std::string ref = test::referenceDataDir();
        if (ref.empty())
            QSKIP("reference data absent");
        const std::string base = ref + "/bhuman2009_log_coltable/";
        auto lut = importLut(base + "coltable.c64");
        QVERIFY2(lut.ok(), errorOf(lut).c_str());
        // README cell counts of the 64^3 table; each source cell becomes 8 of ours.
        const auto counts = histogram(lut.value());
        QCOMPARE(counts[std::size_t(Colour::Unclassified)], std::size_t(257518 * 8));
        QCOMPARE(counts[std::size_t(Colour::Orange)], std::size_t(1051 * 8));
        QCOMPARE(counts[std::size_t(Colour::Yellow)], std::size_t(683 * 8));
        QCOMPARE(counts[std::size_t(Colour::Blue)], std::size_t(707 * 8));
        QCOMPARE(counts[std::size_t(Colour::White)], std::size_t(1126 * 8));
        QCOMPARE(counts[std::size_t(Colour::Green)], std::size_t(1059 * 8));

        // f000 shows carpet below the far goal area and an orange ball near (170, 148).
        const cv::Mat png =
            fieldsight::test::imread(base + "frames_ycbcr/f000.png", cv::IMREAD_COLOR);
        QVERIFY(!png.empty());
        auto classify = [&](int x, int y) {
            const cv::Vec3b bgr = png.at<cv::Vec3b>(y, x); // B, G, R = Cr, Cb, Y
            return lut.value().classify(bgr[2], bgr[1], bgr[0]);
        };
        QCOMPARE(classify(250, 110), Colour::Green);
        QCOMPARE(classify(80, 200), Colour::Green);
        std::array<int, kColourCount> lower{};
        for (int y = 160; y < 240; ++y)
            for (int x = 0; x < 320; ++x)
                ++lower[std::size_t(classify(x, y))];
        // Carpet dominates the lower third, with the centre circle and line in white.
        const int green = lower[std::size_t(Colour::Green)];
        const int white = lower[std::size_t(Colour::White)];
        QVERIFY2(green > 320 * 80 * 6 / 10, qPrintable(QString("green pixels: %1").arg(green)));
        QVERIFY2(white > 320 * 80 * 5 / 100, qPrintable(QString("white pixels: %1").arg(white)));
        int ball_orange = 0;
        for (int y = 136; y < 162; ++y)
            for (int x = 158; x < 184; ++x)
                ball_orange += classify(x, y) == Colour::Orange;
        QVERIFY2(ball_orange > 50, qPrintable(QString("orange ball pixels: %1").arg(ball_orange)));
    }

    // --- rUNSWift .nnmc.bz2 --------------------------------------------------------------------

    void nnmcIndexHasCrSlowestAndYFastest()
    {
        std::string table(ColourLut::kCells, char(9)); // unclassified
        table[3u << 14 | 5u << 7 | 7u] = char(0);      // V7 = 3, U7 = 5, Y7 = 7: ball
        table[7u << 14 | 5u << 7 | 3u] = char(5);      // the transposed cell: green
        table[0] = char(4);                            // red robot
        QTemporaryDir dir;
        const std::string path = dir.filePath("t.nnmc.bz2").toStdString();
        test::writeBytes(path, bzip2(table));
        auto lut = importLut(path);
        QVERIFY2(lut.ok(), errorOf(lut).c_str());
        QCOMPARE(lut.value().classify(14, 10, 6), Colour::Orange); // Y = 2*7, Cb = 2*5, Cr = 2*3
        QCOMPARE(lut.value().classify(6, 10, 14), Colour::Green);
        QCOMPARE(lut.value().classify(0, 0, 0), Colour::Pink);
        const auto counts = histogram(lut.value());
        QCOMPARE(counts[std::size_t(Colour::Unclassified)], ColourLut::kCells - 3);
    }

    void nnmcBadDataIsAnError()
    {
        QTemporaryDir dir;
        const std::string path = dir.filePath("bad.nnmc.bz2").toStdString();
        test::writeBytes(path, "definitely not bzip2");
        QCOMPARE(errorOf(importLut(path)), path + ": not bzip2 data");

        test::writeBytes(path, bzip2(std::string(1000, char(9))));
        QCOMPARE(errorOf(importLut(path)),
                 path + ": wrong size: 1000 bytes unpacked, expected 2097152 (128x128x128)");

        const std::string packed = bzip2(std::string(ColourLut::kCells, char(9)));
        test::writeBytes(path, packed.substr(0, packed.size() / 2));
        QCOMPARE(errorOf(importLut(path)), path + ": truncated bzip2 data");

        std::string bad_value(ColourLut::kCells, char(9));
        bad_value[777] = char(42);
        test::writeBytes(path, bzip2(bad_value));
        QCOMPARE(errorOf(importLut(path)), path + ": unknown colour class 42 at offset 777");
    }

    void realRunswiftTableKeepsItsClassCounts()
    {
        const std::string ref = test::referenceDataDir();
        if (ref.empty())
            QSKIP("reference data absent");
        auto lut = importLut(ref + "/runswift2014_nnmc/top_9am_cloudy.nnmc.bz2");
        QVERIFY2(lut.ok(), errorOf(lut).c_str());
        // README counts (top camera), through the class mapping.
        const auto counts = histogram(lut.value());
        QCOMPARE(counts[std::size_t(Colour::Orange)], std::size_t(25253));
        QCOMPARE(counts[std::size_t(Colour::Blue)], std::size_t(38459));
        QCOMPARE(counts[std::size_t(Colour::Yellow)], std::size_t(84979));
        QCOMPARE(counts[std::size_t(Colour::Pink)], std::size_t(75784));
        QCOMPARE(counts[std::size_t(Colour::Green)], std::size_t(117938));
        QCOMPARE(counts[std::size_t(Colour::White)], std::size_t(63771));
        QCOMPARE(counts[std::size_t(Colour::ShadowObject)], std::size_t(26842));
        QCOMPARE(counts[std::size_t(Colour::Unclassified)], std::size_t(44022 + 1620104));

        auto bottom = importLut(ref + "/runswift2014_nnmc/bot_9am_cloudy.nnmc.bz2");
        QVERIFY2(bottom.ok(), errorOf(bottom).c_str());
        QCOMPARE(histogram(bottom.value())[std::size_t(Colour::Orange)], std::size_t(68745));
    }

    // --- UPenn .raw ----------------------------------------------------------------------------

    void upennFlagsPickTheMostSpecificClass()
    {
        std::string table(64 * 64 * 64, char(0));
        table[0] = char(1 | 8);    // orange + green
        table[1] = char(2 | 16);   // yellow + white
        table[2] = char(4 | 16);   // cyan + white
        table[3] = char(8 | 16);   // green + white
        table[4] = char(8);        // green
        table[5u << 12] = char(4); // Y>>2 = 5: cyan
        QTemporaryDir dir;
        const std::string path = dir.filePath("t.raw").toStdString();
        test::writeBytes(path, table);
        auto lut = importLut(path);
        QVERIFY2(lut.ok(), errorOf(lut).c_str());
        const ColourLut& t = lut.value();
        QCOMPARE(t.classify(0, 0, 0), Colour::Orange);
        QCOMPARE(t.classify(3, 3, 3), Colour::Orange);
        QCOMPARE(t.classify(0, 0, 4), Colour::Yellow);
        QCOMPARE(t.classify(0, 0, 8), Colour::Blue);
        QCOMPARE(t.classify(0, 0, 12), Colour::White);
        QCOMPARE(t.classify(0, 0, 16), Colour::Green);
        QCOMPARE(t.classify(0, 0, 20), Colour::Unclassified);
        QCOMPARE(t.classify(20, 0, 0), Colour::Blue);
    }

    void upennWrongSizeIsAnError()
    {
        QTemporaryDir dir;
        const std::string path = dir.filePath("t.raw").toStdString();
        test::writeBytes(path, std::string(1234, '\0'));
        QCOMPARE(errorOf(importLut(path)),
                 path + ": wrong size: 1234 bytes, expected 262144 (64x64x64)");
    }

    void realUpennTableKeepsItsClassCounts()
    {
        const std::string ref = test::referenceDataDir();
        if (ref.empty())
            QSKIP("reference data absent");
        auto lut = importLut(ref + "/upenn2012_lut/lut_NaoV4_Grasp.raw");
        QVERIFY2(lut.ok(), errorOf(lut).c_str());
        const auto counts = histogram(lut.value());
        QCOMPARE(counts[std::size_t(Colour::Orange)], std::size_t(142 * 8));
        QCOMPARE(counts[std::size_t(Colour::Yellow)], std::size_t(447 * 8));
        QCOMPARE(counts[std::size_t(Colour::Green)], std::size_t(4148 * 8));
        QCOMPARE(counts[std::size_t(Colour::White)], std::size_t(827 * 8));
        QCOMPARE(counts[std::size_t(Colour::Unclassified)], std::size_t(256580 * 8));
    }

    // --- dispatch ------------------------------------------------------------------------------

    void nativeLutImportsUnchangedAndUnknownSuffixIsAnError()
    {
        QTemporaryDir dir;
        const std::string path = dir.filePath("NATIVE.LUT").toStdString();
        ColourLut lut = test::testLut();
        QVERIFY(lut.save(path).ok());
        auto imported = importLut(path);
        QVERIFY2(imported.ok(), errorOf(imported).c_str());
        QVERIFY(imported.value() == lut);

        const std::string other = dir.filePath("table.txt").toStdString();
        test::writeBytes(other, "x");
        QCOMPARE(
            errorOf(importLut(other)),
            other +
                ": unknown colour table format (expected .lut, .c64, .nnmc.bz2, .nnmc or .raw)");
    }

    void realNubotsLutImportsWithItsClassCounts()
    {
        const std::string ref = test::referenceDataDir();
        if (ref.empty())
            QSKIP("reference data absent");
        auto lut = importLut(ref + "/nubots_robocup_2013_luts/default_lab.lut");
        QVERIFY2(lut.ok(), errorOf(lut).c_str());
        const auto counts = histogram(lut.value());
        QCOMPARE(counts[std::size_t(Colour::White)], std::size_t(38300));
        QCOMPARE(counts[std::size_t(Colour::Orange)], std::size_t(46491));
        QCOMPARE(counts[std::size_t(Colour::Blue)], std::size_t(20663));
    }
};

FIELDSIGHT_TEST_SUITE(TestLutImport, None)

#include "test_lut_import.moc"
