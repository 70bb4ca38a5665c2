// The native .lut format (SPEC §3) and atomic saving.
#include "support/child_process.h"
#include "support/test_suite.h"
#include "visioncore/basics/atomic_file.h"
#include "visioncore/basics/colour_lut.h"

#include "support/kill_during_save.h"

#include <QtTest>

#include <csignal>
#include <filesystem>
#include <fstream>
#include <random>

#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <sys/sysmacros.h>
#include <unistd.h>

using namespace fieldsight;

namespace {

std::vector<std::uint8_t> fileBytes(const std::string& path)
{
    const std::string bytes = test::readAll(path);
    return {bytes.begin(), bytes.end()};
}

void writeBytes(const std::string& path, const std::vector<std::uint8_t>& bytes)
{
    std::ofstream out(path, std::ios::binary);
    out.write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
}

/// A LUT with a recognisable pattern in every class.
ColourLut patternLut()
{
    ColourLut lut;
    for (std::size_t i = 0; i < ColourLut::kCells; i += 7)
        lut.setCell(i, Colour((i / 7) % kColourCount));
    return lut;
}

std::size_t filesIn(const std::string& folder)
{
    return std::size_t(std::distance(std::filesystem::directory_iterator(folder),
                                     std::filesystem::directory_iterator()));
}

} // namespace

class TestColourLut : public QObject
{
    Q_OBJECT

    QTemporaryDir m_dir;

private slots:
    void newLutIsAllUnclassified()
    {
        const ColourLut lut;
        QCOMPARE(lut.classify(255, 255, 255), Colour::Unclassified);
        const std::uint8_t* cells = lut.data();
        QVERIFY(std::all_of(cells, cells + ColourLut::kCells, [](auto v) { return v == 0; }));
    }

    void indexUsesSevenBitsYSlowestCrFastest()
    {
        QCOMPARE(ColourLut::index(0, 0, 1), std::size_t(0));
        QCOMPARE(ColourLut::index(0, 0, 2), std::size_t(1));
        QCOMPARE(ColourLut::index(0, 2, 0), std::size_t(128));
        QCOMPARE(ColourLut::index(2, 0, 0), std::size_t(16384));
        QCOMPARE(ColourLut::index(255, 255, 255), ColourLut::kCells - 1);
    }

    void classifyImageGivesEachPixelsCellId()
    {
        ColourLut lut;
        lut.setCell(ColourLut::index(200, 100, 50), Colour::Orange);
        lut.setCell(ColourLut::index(31, 128, 129), Colour::Green);
        // A region of interest of a bigger image: rows are not contiguous.
        cv::Mat big(5, 7, CV_8UC3, cv::Scalar(0, 0, 0));
        cv::Mat image = big(cv::Rect(1, 1, 3, 2));
        image.at<cv::Vec3b>(0, 0) = {200, 100, 50};
        image.at<cv::Vec3b>(0, 2) = {201, 101, 51}; // the same cell: 7 bits of each channel
        image.at<cv::Vec3b>(1, 1) = {30, 129, 128};
        cv::Mat classes(1, 1, CV_8UC1, cv::Scalar(99)); // replaced, whatever it held
        lut.classifyImage(image, classes);
        QCOMPARE(classes.type(), CV_8UC1);
        QCOMPARE(classes.size(), image.size());
        const std::uint8_t orange = std::uint8_t(Colour::Orange);
        const std::uint8_t green = std::uint8_t(Colour::Green);
        const std::uint8_t none = std::uint8_t(Colour::Unclassified);
        const std::vector<std::uint8_t> expected{orange, none, orange, none, green, none};
        QCOMPARE(
            std::vector<std::uint8_t>(classes.begin<std::uint8_t>(), classes.end<std::uint8_t>()),
            expected);
    }

    void saveThenLoadIsByteIdentical()
    {
        QTemporaryDir dir;
        const std::string path = dir.filePath("table.lut").toStdString();
        const ColourLut lut = patternLut();
        QVERIFY(lut.save(path).ok());

        const std::vector<std::uint8_t> bytes = fileBytes(path);
        QCOMPARE(bytes.size(), ColourLut::kCells);
        QVERIFY(std::equal(bytes.begin(), bytes.end(), lut.data()));

        auto loaded = ColourLut::load(path);
        QVERIFY2(loaded.ok(), loaded.ok() ? "" : loaded.error().message.c_str());
        QVERIFY(loaded.value() == lut);
        QCOMPARE(filesIn(dir.path().toStdString()), std::size_t(1)); // no temporary left over
    }

    void rejectsLutOfWrongSize()
    {
        QTemporaryDir dir;
        const std::string path = dir.filePath("short.lut").toStdString();
        writeBytes(path, std::vector<std::uint8_t>(1000, 0));
        auto loaded = ColourLut::load(path);
        QVERIFY(!loaded.ok());
        QCOMPARE(loaded.error().message,
                 path + ": wrong size: 1000 bytes, expected 2097152 (128x128x128)");

        auto from_bytes =
            ColourLut::fromBytes(std::vector<std::uint8_t>(ColourLut::kCells + 1), "memory.lut");
        QVERIFY(!from_bytes.ok());
        QCOMPARE(
            from_bytes.error().message,
            std::string("memory.lut: wrong size: 2097153 bytes, expected 2097152 (128x128x128)"));
    }

    void rejectsCellValueAboveTenNamingTheFirstOffset()
    {
        QTemporaryDir dir;
        const std::string path = dir.filePath("bad.lut").toStdString();
        std::vector<std::uint8_t> bytes(ColourLut::kCells, 2);
        bytes[123456] = 11;
        bytes[200000] = 200;
        writeBytes(path, bytes);
        auto loaded = ColourLut::load(path);
        QVERIFY(!loaded.ok());
        const std::string& message = loaded.error().message;
        QVERIFY2(message.rfind(path + ": ", 0) == 0, message.c_str());
        QVERIFY2(message.find("invalid colour id 11 at offset 123456") != std::string::npos,
                 message.c_str());
        QVERIFY2(message.find("2 bad cells") != std::string::npos, message.c_str());
    }

    void rejectsOneBadCellAnywhereInAWord()
    {
        // The check reads eight cells a step: one bad cell at each place of a word, of each kind
        // (just past the last id, below and at 128, the largest), beside cells of the last id.
        std::vector<std::uint8_t> bytes(ColourLut::kCells, 10);
        for (const int bad : {11, 127, 128, 255})
            for (const std::size_t at :
                 {std::size_t(0), std::size_t(1), std::size_t(4), std::size_t(7),
                  std::size_t(1000003), ColourLut::kCells - 1}) {
                bytes[at] = std::uint8_t(bad);
                auto lut = ColourLut::fromBytes(bytes, "one");
                QVERIFY2(!lut.ok(), qPrintable(QString("%1 at %2").arg(bad).arg(at)));
                QVERIFY(lut.error().message.find("at offset " + std::to_string(at)) !=
                        std::string::npos);
                bytes[at] = 10;
            }
        QVERIFY(ColourLut::fromBytes(bytes, "tens").ok());
    }

    void acceptsEveryValidIdAtTheBoundary()
    {
        std::vector<std::uint8_t> bytes(ColourLut::kCells, 10);
        auto lut = ColourLut::fromBytes(bytes, "tens");
        QVERIFY(lut.ok());
        QCOMPARE(lut.value().cell(ColourLut::kCells - 1), Colour::ShadowBlue);
    }

    void loadingAMissingFileNamesIt()
    {
        auto loaded = ColourLut::load("/nonexistent/folder/x.lut");
        QVERIFY(!loaded.ok());
        QCOMPARE(loaded.error().message,
                 std::string("cannot read /nonexistent/folder/x.lut: No such file or directory"));
    }

    void saveIntoMissingFolderFailsWithFileName()
    {
        auto status = patternLut().save("/nonexistent/folder/x.lut");
        QVERIFY(!status.ok());
        QCOMPARE(status.error().message,
                 std::string("cannot write /nonexistent/folder/x.lut: No such file or directory"));
    }

    void failedSaveIntoUnwritableFolderLeavesOldFileIntact()
    {
        if (::geteuid() == 0)
            QSKIP("root ignores folder permissions; see failedSaveMidWriteLeavesOldFileIntact");
        QTemporaryDir dir;
        const std::string path = dir.filePath("table.lut").toStdString();
        const ColourLut old_lut = patternLut();
        QVERIFY(old_lut.save(path).ok());
        QFile::setPermissions(dir.path(), QFile::ReadOwner | QFile::ExeOwner);
        auto status = ColourLut().save(path);
        QFile::setPermissions(dir.path(), QFile::ReadOwner | QFile::WriteOwner | QFile::ExeOwner);
        QVERIFY(!status.ok());
        QCOMPARE(status.error().message, "cannot write " + path + ": Permission denied");
        QVERIFY(ColourLut::load(path).value() == old_lut);
    }

    void failedSaveMidWriteLeavesOldFileIntact()
    {
        QTemporaryDir dir;
        const std::string path = dir.filePath("table.lut").toStdString();
        const ColourLut old_lut = patternLut();
        QVERIFY(old_lut.save(path).ok());

        // Make the write itself fail half-way: a 1 MB file size limit, SIGXFSZ ignored.
        rlimit saved{};
        QVERIFY(::getrlimit(RLIMIT_FSIZE, &saved) == 0);
        const auto old_handler = std::signal(SIGXFSZ, SIG_IGN);
        rlimit small = saved;
        small.rlim_cur = 1 << 20;
        QVERIFY(::setrlimit(RLIMIT_FSIZE, &small) == 0);
        const Status status = ColourLut().save(path);
        ::setrlimit(RLIMIT_FSIZE, &saved);
        std::signal(SIGXFSZ, old_handler);

        QVERIFY(!status.ok());
        QCOMPARE(status.error().message, "cannot write " + path + ": File too large");
        QVERIFY(ColourLut::load(path).value() == old_lut);
        QCOMPARE(filesIn(dir.path().toStdString()), std::size_t(1)); // temporary removed
    }

    void saveOverADirectoryFails()
    {
        QTemporaryDir dir;
        const std::string path = dir.filePath("sub").toStdString();
        QVERIFY(QDir(dir.path()).mkdir("sub"));
        auto status = patternLut().save(path);
        QVERIFY(!status.ok());
        QCOMPARE(status.error().message, "cannot write " + path + ": Is a directory");
        QVERIFY(QFileInfo(QString::fromStdString(path)).isDir());
    }

    void aRefusedFileIsSetAsideBeforeASaveReplacesIt()
    {
        QTemporaryDir dir;
        const std::string path = dir.filePath("marks.json").toStdString();
        const std::string damaged = "{\"format\": \"fieldsight-bookmarks/9\", ...";
        QVERIFY(writeFileAtomically(path, damaged).ok());
        QVERIFY(writeFileAtomically(path + ".unreadable", std::string("earlier")).ok());
        const auto save = [&](const std::string& text) {
            return [&path, text] { return writeFileAtomically(path, text); };
        };

        // A failing save puts the refused file back, to be set aside next time.
        bool unreadable = true;
        auto failed =
            saveReplacingUnreadable(path, unreadable, [] { return Status(Error{"disk full"}); });
        QVERIFY(!failed.ok());
        QVERIFY(unreadable);
        QCOMPARE(readWholeFile(path).value(), damaged);

        // The next one moves it beside (never over an earlier one) and says so.
        auto saved = saveReplacingUnreadable(path, unreadable, save("new"));
        QVERIFY2(saved.ok(), saved.ok() ? "" : saved.error().message.c_str());
        QVERIFY(!unreadable);
        QVERIFY2(saved.value().find(path + ".unreadable-2") != std::string::npos,
                 saved.value().c_str());
        QCOMPARE(readWholeFile(path + ".unreadable-2").value(), damaged);
        QCOMPARE(readWholeFile(path + ".unreadable").value(), std::string("earlier"));
        QCOMPARE(readWholeFile(path).value(), std::string("new"));

        // Once set aside, later saves just save.
        saved = saveReplacingUnreadable(path, unreadable, save("newer"));
        QVERIFY(saved.ok());
        QVERIFY(saved.value().empty());
        QCOMPARE(readWholeFile(path).value(), std::string("newer"));
        QVERIFY(!QFileInfo::exists(QString::fromStdString(path + ".unreadable-3")));

        // Only a regular file is moved: a folder in its place stops the save.
        const std::string folder = dir.filePath("folder.json").toStdString();
        QVERIFY(QDir().mkdir(QString::fromStdString(folder)));
        unreadable = true;
        bool saved_anything = false;
        auto refused = saveReplacingUnreadable(folder, unreadable, [&] {
            saved_anything = true;
            return Status();
        });
        QVERIFY(!refused.ok());
        QVERIFY(!saved_anything);
        QVERIFY2(refused.error().message.find("a folder") != std::string::npos,
                 refused.error().message.c_str());
    }

    void readWholeFileReturnsExactBytes()
    {
        QTemporaryDir dir;
        const std::string path = dir.filePath("t.bin").toStdString();
        const std::string text("a\0b\nc", 5);
        QVERIFY(writeFileAtomically(path, text).ok());
        auto back = readWholeFile(path);
        QVERIFY(back.ok());
        QCOMPARE(back.value(), text);
    }

    void onlyRegularFilesAreReadAndWithinTheirLimit()
    {
        QElapsedTimer clock;
        clock.start();
        const auto zero = readWholeFile("/dev/zero");
        QVERIFY(!zero);
        QVERIFY2(zero.error().message.find("/dev/zero") != std::string::npos &&
                     zero.error().message.find("character device") != std::string::npos,
                 zero.error().message.c_str());
        QVERIFY(!ColourLut::load("/dev/zero"));
        const std::string fifo = (m_dir.path() + "/pipe").toStdString();
        QCOMPARE(::mkfifo(fifo.c_str(), 0600), 0);
        const auto piped = readWholeFile(fifo); // must not wait for a writer
        QVERIFY(!piped && piped.error().message.find("a FIFO") != std::string::npos);
        const std::string big = (m_dir.path() + "/big").toStdString();
        QVERIFY(writeFileAtomically(big, std::string(2000, 'x')).ok());
        const auto capped = readWholeFile(big, 1000);
        QVERIFY(!capped && capped.error().message.find("too large") != std::string::npos);
        QVERIFY(readWholeFile(big, 2000));
        QVERIFY(clock.elapsed() < 2000);
    }

    void savesWriteStraightToADeviceAndReportItsErrors()
    {
        // Device nodes of our own (null and full), so a regression cannot harm the machine's.
        const std::string null_dev = (m_dir.path() + "/null").toStdString();
        const std::string full_dev = (m_dir.path() + "/full").toStdString();
        if (::mknod(null_dev.c_str(), S_IFCHR | 0666, makedev(1, 3)) != 0 ||
            ::mknod(full_dev.c_str(), S_IFCHR | 0666, makedev(1, 7)) != 0)
            QSKIP("cannot make device nodes here (not root)");
        struct stat st
        {
        };
        QVERIFY(writeFileAtomically(null_dev, std::string("data")).ok());
        QCOMPARE(::stat(null_dev.c_str(), &st), 0);
        QVERIFY(S_ISCHR(st.st_mode)); // written to, not replaced by a regular file
        const Status full = writeFileAtomically(full_dev, std::string(4096, 'x'));
        QVERIFY(!full);
        QVERIFY2(full.error().message.find(full_dev) != std::string::npos &&
                     full.error().message.find("No space left") != std::string::npos,
                 full.error().message.c_str());
        QCOMPARE(::stat(full_dev.c_str(), &st), 0);
        QVERIFY(S_ISCHR(st.st_mode));
    }

    void savesKeepALinkAndNeverWaitForAFifo()
    {
        struct stat st
        {
        };
        // A link stays a link; its target gets the new bytes.
        const std::string target = (m_dir.path() + "/target.lut").toStdString();
        const std::string link = (m_dir.path() + "/link.lut").toStdString();
        QVERIFY(writeFileAtomically(target, std::string("old")).ok());
        QCOMPARE(::symlink(target.c_str(), link.c_str()), 0);
        QVERIFY(writeFileAtomically(link, std::string("new")).ok());
        QCOMPARE(::lstat(link.c_str(), &st), 0);
        QVERIFY(S_ISLNK(st.st_mode));
        QCOMPARE(readWholeFile(target).value(), std::string("new"));

        // A FIFO nobody reads is an error at once, not a wait, and stays a FIFO.
        const std::string fifo = (m_dir.path() + "/out_pipe").toStdString();
        QCOMPARE(::mkfifo(fifo.c_str(), 0600), 0);
        QElapsedTimer clock;
        clock.start();
        QVERIFY(!writeFileAtomically(fifo, std::string("x")));
        QVERIFY(clock.elapsed() < 2000);
        QCOMPARE(::lstat(fifo.c_str(), &st), 0);
        QVERIFY(S_ISFIFO(st.st_mode));
        QCOMPARE(QDir(m_dir.path()).entryList({"*.tmp-*"}).size(), 0); // no stray temporaries
    }

    void aWriterKilledMidSaveLeavesTheOldOrTheNewFile()
    {
        // A child process saves two 2 MiB tables in turn through ColourLut::save without end; it
        // is killed at a random moment, 100 times (test::kKillRounds). Every time the file is one
        // table or the other, whole (issue 10).
        const QTemporaryDir dir(test::crashTestDirTemplate());
        QVERIFY(dir.isValid());
        const std::string path = dir.filePath("killed.lut").toStdString();
        ColourLut first, second;
        for (std::size_t i = 0; i < ColourLut::kCells; ++i) {
            first.setCell(i, Colour::Green);
            second.setCell(i, Colour::Orange);
        }
        QVERIFY(first.save(path).ok());
        const std::string first_bytes = readWholeFile(path).value();
        const std::string second_bytes(ColourLut::kCells, char(Colour::Orange));
        QCOMPARE(first_bytes.size(), second_bytes.size());

        const auto result = test::killDuringSaves(
            path, [&](bool two) { (void)(two ? second : first).save(path); }, first_bytes,
            second_bytes);
        QCOMPARE(result.rounds, test::kKillRounds);
        QVERIFY2(result.mixes == 0 && result.unreadable == 0, result.first_problem.c_str());
        QVERIFY(result.saw_second > 0); // the child did get saves through
        // A writer killed between naming its finished file and the rename can leave it: the
        // next save removes it.
        QVERIFY(first.save(path).ok());
        QCOMPARE(test::temporariesOf(path), 0);
        qInfo("%d kills: the new table %d times, the old %d times, %lld temporaries left before "
              "the next save",
              result.rounds, result.saw_second, result.rounds - result.saw_second,
              (long long)result.temporaries);
    }
};

FIELDSIGHT_TEST_SUITE(TestColourLut, None)

#include "test_colour_lut.moc"
