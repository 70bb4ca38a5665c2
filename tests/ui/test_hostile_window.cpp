// Hostile files and machines in the window (issue 21): a settings file that is a FIFO, an open
// stuck in the system when the window quits, frame entries that are no frame, and a recovery
// offer naming a very long path with a time that is not a time.
#include "support/test_suite.h"
#include "support/test_files.h"
#include "support/synthetic_frames.h"
#include "support/window_waits.h"
#include "ui/actions/session_files.h"
#include "ui/document/editing_session.h"
#include "ui/main_window.h"
#include "ui/settings/window_settings.h"
#include "ui/widgets/message_bar.h"
#include "visioncore/basics/colour_lut.h"

#include <QDateTime>
#include <QElapsedTimer>
#include <QLabel>
#include <QLocale>
#include <QPushButton>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QtTest>

#include <atomic>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <future>
#include <memory>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

using namespace fieldsight;
using namespace fieldsight::test;
using namespace std::chrono_literals;
namespace fs = std::filesystem;

namespace {

/// Lets whatever waits on the FIFO `path` for a writer go on (it then reads nothing).
void release(const std::string& path)
{
    const int writer = ::open(path.c_str(), O_WRONLY | O_NONBLOCK);
    if (writer >= 0)
        ::close(writer);
}

bool isFifo(const std::string& path)
{
    struct stat st
    {
    };
    return ::lstat(path.c_str(), &st) == 0 && S_ISFIFO(st.st_mode);
}

} // namespace

class TestHostileWindow : public QObject
{
    Q_OBJECT

    QTemporaryDir m_dir;

private slots:
    void initTestCase()
    {
        QCOMPARE(test::startWindowSuite("test_hostile_window", m_dir), QString());
    }

    void aSettingsFileThatIsAFifoLeavesTheWindowItsDefaults()
    {
        // Reading it waited for a writer: the window never appeared.
        const QString folder =
            QStandardPaths::writableLocation(QStandardPaths::GenericConfigLocation) +
            "/FieldsightTest";
        QVERIFY(QDir().mkpath(folder));
        const std::string fifo = (folder + "/test_hostile_window.conf").toStdString();
        fs::remove(fifo);
        QCOMPARE(::mkfifo(fifo.c_str(), 0644), 0);
        auto loading = std::async(std::launch::async, [] { return ui::WindowSettings::load(); });
        if (loading.wait_for(5s) != std::future_status::ready) {
            release(fifo);
            loading.wait();
            fs::remove(fifo);
            QFAIL("reading the settings waited on the FIFO");
        }
        const ui::WindowSettings settings = loading.get();
        QVERIFY2(settings.problem.contains(QString::fromStdString(fifo)) &&
                     settings.problem.contains("a FIFO, not a regular file"),
                 qPrintable(settings.problem));
        QCOMPARE(settings.fps, 30); // the defaults
        {
            ui::MainWindow w;
            w.show();
            QVERIFY(QTest::qWaitForWindowExposed(&w));
            QVERIFY2(w.lastMessage().contains("settings file"), qPrintable(w.lastMessage()));
            w.close(); // saves its settings: not over the FIFO
        }
        QVERIFY(isFifo(fifo));
        fs::remove(fifo);
    }

    void quittingDoesNotWaitForAStuckOpen()
    {
        // An open stuck in the system (here: a FIFO opened to read, with no writer) kept the
        // quitting window's process alive for good.
        const std::string fifo = m_dir.filePath("stuck").toStdString();
        QCOMPARE(::mkfifo(fifo.c_str(), 0644), 0);
        // `returned` is set once the open comes back, which is only after release(): a session
        // deleted while it is still false did not wait for the open to end.
        auto entered = std::make_shared<std::atomic<bool>>(false);
        auto returned = std::make_shared<std::atomic<bool>>(false);
        const auto stuckOpener =
            [fifo, entered, returned](const QString&,
                                      const QString&) -> Result<std::shared_ptr<ui::OpenedStream>> {
            *entered = true;
            const int fd = ::open(fifo.c_str(), O_RDONLY);
            if (fd >= 0)
                ::close(fd);
            *returned = true;
            return Error{"released"};
        };
        auto* session = new ui::EditingSession;
        session->setSourceOpener(stuckOpener);
        QVERIFY(session->openStream("stuck"));
        QTRY_VERIFY(entered->load());
        QElapsedTimer clock;
        clock.start();
        delete session; // waits for the open at most kOpenWaitOnCloseMs, then leaves it
        const qint64 ms = clock.elapsed();
        QVERIFY(!returned->load());
        release(fifo);
        QTRY_VERIFY(returned->load());
        qInfo("the session closed in %lld ms with its open stuck", ms);

        // Cancelled first, it does not wait at all: not even the bounded wait above (an
        // unloaded machine takes a few ms here; the bound only tells "no wait" from "the wait").
        *entered = false;
        *returned = false;
        session = new ui::EditingSession;
        session->setSourceOpener(stuckOpener);
        QSignalSpy opened(session, &ui::EditingSession::opened);
        QVERIFY(session->openStream("stuck"));
        QTRY_VERIFY(entered->load());
        session->cancelOpening();
        QCOMPARE(opened.size(), 1);
        QCOMPARE(opened.front().at(1).toBool(), true); // cancelled
        clock.restart();
        delete session;
        QVERIFY(!returned->load());
        QVERIFY2(clock.elapsed() < ui::EditingSession::kOpenWaitOnCloseMs,
                 qPrintable(QString::number(clock.elapsed())));
        release(fifo);
        QTRY_VERIFY(returned->load());
    }

    void brokenFrameEntriesShowInTheMessageBar()
    {
        const std::string stream = m_dir.filePath("broken").toStdString();
        fs::create_directories(stream);
        for (const char* frame : {"frame_000000.png", "frame_000001.png"})
            fs::copy_file(sampleStreamsDir() + "/lab1/" + frame, stream + "/" + frame);
        fs::copy_file(sampleStreamsDir() + "/lab1/default.lut", stream + "/default.lut");
        fs::create_symlink(stream + "/gone.png", stream + "/frame_000002.png");
        ui::MainWindow w;
        w.show();
        QVERIFY(openAndWait(w, QString::fromStdString(stream)));
        QCOMPARE(w.session().stream().info().frame_count, std::size_t(2));
        QVERIFY(w.messageBar().isVisible());
        QCOMPARE(w.messageBar().text(),
                 QString::fromStdString(stream) +
                     "/frame_000002.png: skipped, a link to a file that does not exist");
    }

    void aLongRecoveryOfferKeepsItsButtonsInTheBar()
    {
        // A recovery file naming a 400-character path pushed Recover and Discard off the
        // window, and its time was shown as written (HTML in it shown as HTML).
        ui::MainWindow w;
        w.resize(1280, 800);
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        const QString folder = QStandardPaths::writableLocation(QStandardPaths::AppDataLocation);
        QVERIFY(QDir().mkpath(folder));
        QVERIFY(ColourLut().save((folder + "/lut-recovery.lut").toStdString()).ok());
        const QString table =
            "/home/robot/" + QString(190, 'a') + "/" + QString(190, 'b') + "/default.lut";
        QVERIFY(table.size() > 400);
        const QString stream = "/media/venue/" + QString(200, 'c');
        const auto offer = [&](const QString& saved_at) {
            std::ofstream((folder + "/lut-recovery.json").toStdString(), std::ios::trunc)
                << "{\"format\": \"fieldsight-lut-recovery/1\", \"path\": \"" << table.toStdString()
                << "\", \"stream\": \"" << stream.toStdString() << "\", \"saved_at\": \""
                << saved_at.toStdString() << "\"}";
            w.files().offerRecovery();
            QCoreApplication::processEvents();
        };
        offer("2024-06-01T10:20:30");
        ui::OfferBar& bar = w.recoveryBar();
        QVERIFY(bar.isVisible());
        // The long label used to raise the window's minimum width to 2,013 px: on a 1280-px
        // screen the buttons were off it.
        QCOMPARE(w.width(), 1280);
        QVERIFY(bar.width() <= 1280);
        for (const char* name : {"accept", "decline"}) {
            const auto* button = bar.findChild<QPushButton*>(name);
            QVERIFY(button && button->isVisible());
            const QRect in_window(button->mapTo(&w, QPoint(0, 0)), button->size());
            QVERIFY2(in_window.left() >= 0 && in_window.right() < 1280,
                     qPrintable(QString("%1 at x %2 to %3 in a window %4 wide")
                                    .arg(name)
                                    .arg(in_window.left())
                                    .arg(in_window.right())
                                    .arg(w.width())));
        }
        const QString when = QLocale().toString(QDateTime(QDate(2024, 6, 1), QTime(10, 20, 30)),
                                                QLocale::ShortFormat);
        QVERIFY2(bar.question().contains(when), qPrintable(bar.question()));
        QVERIFY2(!bar.question().contains('<'), qPrintable(bar.question()));
        const auto* label = bar.findChild<QLabel*>();
        QVERIFY(label && label->textFormat() == Qt::PlainText);
        QVERIFY(label->toolTip().contains(table) && label->toolTip().contains(stream));

        offer("<b>2024</b><img src=x>");
        QVERIFY2(!bar.question().contains('<'), qPrintable(bar.question()));
        QVERIFY(bar.question().contains("at a time not recorded"));
        w.session().lut().discardRecovery();
    }
};

FIELDSIGHT_TEST_SUITE(TestHostileWindow, Widgets)

#include "test_hostile_window.moc"
