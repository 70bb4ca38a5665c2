// The window's File workflows, offscreen, driven with keys and clicks and answered through the
// dialogs seam; each checks what the user sees and what lands on disk: the Save / Discard /
// Cancel question before another stream opens and before the window closes with an edited table,
// the recovery bar's Recover and Discard, Ctrl+S and Save As of a table imported from another
// team's format, opening a table (good, foreign, damaged), dropping a stream folder or a table on
// the window, and the recent streams menu.
#include "support/test_suite.h"
#include "support/test_files.h"
#include "support/scripted_dialogs.h"
#include "support/synthetic_frames.h"
#include "support/unsaved_ask.h"
#include "support/window_waits.h"
#include "ui/widgets/message_bar.h"
#include "visioncore/io/lut_import.h"

#include <QMenuBar>
#include <QMimeData>
#include <QPushButton>
#include <QSettings>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QtTest>

#include <cstring>
#include <unistd.h>

using namespace fieldsight;
using namespace fieldsight::test;
using fieldsight::ui::MainWindow;

namespace {

bool writeFile(const QString& path, const QByteArray& bytes)
{
    QFile f(path);
    return f.open(QIODevice::WriteOnly | QIODevice::Truncate) && f.write(bytes) == bytes.size();
}

ColourLut loadTable(const QString& path)
{
    auto t = ColourLut::load(path.toStdString());
    return t ? std::move(t).value() : ColourLut();
}

QString canonical(const QString& path)
{
    return QFileInfo(path).canonicalFilePath();
}

/// A B-Human ColorTable64 (run-length coded 64^3 cells): the lower half of Y orange (class 1),
/// the upper half green (class 5).
QByteArray bhumanTable()
{
    QByteArray rle;
    const auto run = [&](std::uint32_t length, char value) {
        char raw[4];
        std::memcpy(raw, &length, 4);
        rle.append(raw, 4);
        rle.append(value);
    };
    run(64 * 64 * 32, 1);
    run(64 * 64 * 32, 5);
    rle.append(4, '\0'); // the end
    return rle;
}

/// The leftover temporaries of an atomic write in `folder` (none after a finished save).
QStringList temporaries(const QString& folder)
{
    return QDir(folder).entryList({QStringLiteral("*.tmp-*")}, QDir::Files | QDir::Hidden);
}

} // namespace

class TestWorkflows : public QObject
{
    Q_OBJECT

    QTemporaryDir m_dir;

    /// A 5-frame copy of the sample stream lab1 as `name`; its table has `orange` cells of its
    /// own turned orange, so that each copy's table is told apart.
    QString copyStream(const QString& name, int orange = 0)
    {
        const QString from = QString::fromStdString(sampleStreamsDir() + "/lab1");
        const QString to = m_dir.filePath(name);
        QDir().mkpath(to);
        for (int i = 0; i < 5; ++i) {
            const QString frame = QStringLiteral("frame_%1.png").arg(i, 6, 10, QLatin1Char('0'));
            QFile::copy(from + "/" + frame, to + "/" + frame);
        }
        ColourLut table = loadTable(from + "/default.lut");
        for (int i = 0; i < orange; ++i)
            table.setCell(std::uint32_t(1000 + 7 * i), Colour::Orange);
        if (!table.save((to + "/default.lut").toStdString()))
            return {};
        return to;
    }

    /// A user's edit: a click with the Click tool and class `colour` on a field pixel; the
    /// frame is shown again.
    static bool clickEdit(MainWindow& w, Colour colour = Colour::Pink)
    {
        QTest::keyClick(&w, Qt::Key_C);
        w.tools().settings().setColour(colour);
        w.view().setZoom(1);
        w.view().setImageOrigin({0, 0});
        const QByteArray before = tableBytes(w.session().lut().table());
        QTest::mouseClick(&w.view(), Qt::LeftButton, {}, QPoint(60, 200));
        return tableBytes(w.session().lut().table()) != before && w.session().lut().modified() &&
               waitForFrame(w, w.session().stream().currentIndex());
    }

    static QByteArray tableBytes(const ColourLut& t)
    {
        return QByteArray(reinterpret_cast<const char*>(t.data()), qsizetype(ColourLut::kCells));
    }

    /// A shown window on `stream` with one edit, autosaved to the recovery file.
    static bool openAndEdit(MainWindow& w, const QString& stream)
    {
        w.show();
        if (!QTest::qWaitForWindowActive(&w) || !openAndWait(w, stream))
            return false;
        w.session().lut().setAutosaveDelay(50);
        return clickEdit(w) &&
               QTest::qWaitFor([&] { return w.session().lut().findRecovery().has_value(); });
    }

    /// The File > Recent streams menu.
    static QMenu* recentMenu(MainWindow& w)
    {
        for (QMenu* m : w.menuBar()->findChildren<QMenu*>())
            if (m->title() == QStringLiteral("Recent streams"))
                return m;
        return nullptr;
    }

    static bool drop(MainWindow& w, const QUrl& url)
    {
        QMimeData data;
        data.setUrls({url});
        QDragEnterEvent enter(QPoint(300, 300), Qt::CopyAction, &data, Qt::LeftButton, {});
        QCoreApplication::sendEvent(&w, &enter);
        if (!enter.isAccepted())
            return false;
        QDropEvent event(QPointF(300, 300), Qt::CopyAction, &data, Qt::LeftButton, {});
        QCoreApplication::sendEvent(&w, &event);
        return event.isAccepted();
    }

private slots:
    void initTestCase() { QCOMPARE(test::startWindowSuite("test_workflows", m_dir), QString()); }

    void init()
    {
        QSettings().clear();
        const QDir app(QStandardPaths::writableLocation(QStandardPaths::AppDataLocation));
        for (const char* name : {"lut-recovery.lut", "lut-recovery.json"})
            QFile::remove(app.filePath(QString::fromLatin1(name)));
    }

    void unsavedEditsAskSaveDiscardOrCancel_data() { addUnsavedAskRows(); }

    void unsavedEditsAskSaveDiscardOrCancel()
    {
        QFETCH(QMessageBox::StandardButton, answer);
        QFETCH(bool, close);
        const QString tag = unsavedAskTag();
        const QString a = copyStream("ask_a_" + tag), b = copyStream("ask_b_" + tag, 50);
        const QString file = a + "/default.lut";
        // A second name for the file as it is: an atomic save replaces the name's file and
        // leaves this one as it was; a write in place would change both.
        QCOMPARE(::link(QFile::encodeName(file), QFile::encodeName(a + "/held.lut")), 0);
        const QByteArray on_disk = fileBytes(file);
        ScriptedDialogs dialogs;
        MainWindow w;
        QVERIFY(openAndEdit(w, a));
        const ColourLut edited = w.session().lut().table();
        QVERIFY(w.isWindowModified());

        UnsavedDocument lut;
        lut.question = QStringLiteral("Unsaved LUT edits");
        lut.holds_edit = [&] { return w.session().lut().table() == edited; };
        // Written by replacing the file whole.
        lut.file_has_edit = [&] { return loadTable(file) == edited; };
        lut.file_as_before = [&] { return fileBytes(file) == on_disk; };
        lut.has_recovery = [&] { return w.session().lut().findRecovery().has_value(); };
        lut.shows_other = [&] {
            return w.session().lut().table() == loadTable(b + "/default.lut");
        };
        answerUnsavedAsk(w, dialogs, lut, answer, close, a, b);
        if (QTest::currentTestFailed())
            return;
        QVERIFY(temporaries(a).isEmpty());
        QCOMPARE(fileBytes(a + "/held.lut"), on_disk);
    }

    void theRecoveryBarRecoversOrDiscards_data()
    {
        QTest::addColumn<QString>("button");
        QTest::newRow("Recover") << QStringLiteral("accept");
        QTest::newRow("Discard") << QStringLiteral("decline");
    }

    void theRecoveryBarRecoversOrDiscards()
    {
        QFETCH(QString, button);
        const QString a = copyStream("bar_" + button);
        const QByteArray on_disk = fileBytes(a + "/default.lut");
        ScriptedDialogs dialogs;
        ColourLut edited;
        {
            MainWindow crashed;
            QVERIFY(openAndEdit(crashed, a));
            edited = crashed.session().lut().table();
        } // gone without closing: only the recovery file keeps the edit

        auto w = std::make_unique<MainWindow>();
        w->show();
        QVERIFY(openAndWait(*w, a));
        QVERIFY(w->recoveryBar().isVisible());
        const QString question = w->recoveryBar().question();
        QVERIFY2(question.contains(a) && question.contains("default.lut"), qPrintable(question));
        QVERIFY(!(w->session().lut().table() == edited));
        QTest::mouseClick(w->recoveryBar().findChild<QPushButton*>(button), Qt::LeftButton);
        QVERIFY(!w->recoveryBar().isVisible());
        QCOMPARE(fileBytes(a + "/default.lut"), on_disk); // nothing written before Ctrl+S
        if (button == "accept") {
            QVERIFY(w->session().lut().table() == edited);
            QVERIFY(w->isWindowModified());
            QVERIFY2(w->lastMessage().startsWith("Recovered"), qPrintable(w->lastMessage()));
            QTest::keyClick(w.get(), Qt::Key_S, Qt::ControlModifier);
            QVERIFY(loadTable(a + "/default.lut") == edited);
            QVERIFY(!w->isWindowModified());
        } else {
            QVERIFY(w->session().lut().table() == loadTable(a + "/default.lut"));
            QVERIFY(!w->isWindowModified());
        }
        // Either way the edits are not offered again at the next start.
        QVERIFY(!w->session().lut().findRecovery());
        w.reset();
        MainWindow next;
        next.show();
        QVERIFY(openAndWait(next, a));
        QVERIFY(!next.recoveryBar().isVisible());
        QVERIFY(dialogs.unanswered.isEmpty());
    }

    void anImportedTableIsSavedAsLutNeverOverTheForeignFile()
    {
        const QString a = copyStream("imported");
        const QString foreign = m_dir.filePath("team.c64");
        QVERIFY(writeFile(foreign, bhumanTable()));
        ScriptedDialogs dialogs;
        MainWindow w;
        w.show();
        QVERIFY(QTest::qWaitForWindowActive(&w));
        QVERIFY(openAndWait(w, a));
        dialogs.paths.push_back(foreign);
        QTest::keyClick(&w, Qt::Key_L, Qt::ControlModifier); // File > Open LUT
        QVERIFY(w.session().lut().table() == importLut(foreign.toStdString()).value());
        QVERIFY2(w.windowTitle().contains("team.c64"), qPrintable(w.windowTitle()));
        QVERIFY(clickEdit(w));
        const ColourLut edited = w.session().lut().table();

        // Ctrl+S asks where the .lut goes; no answer writes nothing and keeps the edit.
        const int asked = int(dialogs.asked.size());
        QTest::keyClick(&w, Qt::Key_S, Qt::ControlModifier);
        QCOMPARE(dialogs.asked.mid(asked), QStringList{"Save LUT as"});
        QVERIFY(w.isWindowModified());
        QCOMPARE(fileBytes(foreign), bhumanTable());
        // Answered with a name without its suffix: written as .lut beside it.
        dialogs.unanswered.clear();
        dialogs.paths.push_back(a + "/venue");
        dialogs.answers.push_back(QMessageBox::No); // not as the stream's own table
        QTest::keyClick(&w, Qt::Key_S, Qt::ControlModifier);
        QCOMPARE(dialogs.asked.last(), QStringLiteral("Use as this stream's table"));
        QVERIFY(loadTable(a + "/venue.lut") == edited);
        QCOMPARE(fileBytes(foreign), bhumanTable());
        QCOMPARE(w.session().lut().path(), a + "/venue.lut");
        QVERIFY(!w.isWindowModified());
        QVERIFY2(w.windowTitle().contains("venue.lut"), qPrintable(w.windowTitle()));

        // The next Ctrl+S writes venue.lut without asking; Save As writes a new .lut and the
        // table is that file from then on.
        QVERIFY(clickEdit(w, Colour::Yellow));
        const ColourLut edited_again = w.session().lut().table();
        const int asked_before = int(dialogs.asked.size());
        QTest::keyClick(&w, Qt::Key_S, Qt::ControlModifier);
        QCOMPARE(int(dialogs.asked.size()), asked_before);
        QVERIFY(loadTable(a + "/venue.lut") == edited_again);
        QVERIFY(clickEdit(w, Colour::Blue));
        dialogs.paths.push_back(a + "/copy.lut");
        dialogs.answers.push_back(QMessageBox::No);
        QTest::keyClick(&w, Qt::Key_S, Qt::ControlModifier | Qt::ShiftModifier);
        QCOMPARE(dialogs.asked.mid(dialogs.asked.size() - 2),
                 (QStringList{"Save LUT as", "Use as this stream's table"}));
        QVERIFY(loadTable(a + "/copy.lut") == w.session().lut().table());
        QVERIFY(loadTable(a + "/venue.lut") == edited_again);
        QCOMPARE(w.session().lut().path(), a + "/copy.lut");
        QCOMPARE(fileBytes(foreign), bhumanTable());
        QVERIFY(dialogs.unanswered.isEmpty());
    }

    void openingATableShowsItOrSaysWhyNot()
    {
        const QString a = copyStream("open_lut");
        const QString good = copyStream("open_lut_other", 300) + "/default.lut";
        const QString foreign = m_dir.filePath("open.c64");
        QVERIFY(writeFile(foreign, bhumanTable()));
        const QString damaged = m_dir.filePath("damaged.lut");
        QVERIFY(writeFile(damaged, fileBytes(good).left(1000)));
        ScriptedDialogs dialogs;
        MainWindow w;
        w.show();
        QVERIFY(QTest::qWaitForWindowActive(&w));
        QVERIFY(openAndWait(w, a));
        const auto openLut = [&](const QString& path) {
            dialogs.paths.push_back(path);
            QTest::keyClick(&w, Qt::Key_L, Qt::ControlModifier);
        };
        // The frame as shown is classified with the table opened.
        const auto shownWith = [&](const ColourLut& table) {
            return QTest::qWaitFor([&] {
                const auto& out = w.session().stream().current();
                cv::Mat classes;
                return !w.session().stream().waiting() && out &&
                       out->classified == ui::classifyFrame(out->frame.ycbcr, table, classes);
            });
        };

        openLut(good);
        QVERIFY(w.session().lut().table() == loadTable(good));
        QVERIFY(!(w.session().lut().table() == loadTable(a + "/default.lut")));
        QCOMPARE(w.session().lut().path(), good);
        QVERIFY(!w.isWindowModified());
        QVERIFY(shownWith(loadTable(good)));

        openLut(foreign);
        const ColourLut imported = importLut(foreign.toStdString()).value();
        QVERIFY(w.session().lut().table() == imported);
        QVERIFY2(w.windowTitle().contains("open.c64"), qPrintable(w.windowTitle()));
        QVERIFY(shownWith(imported));

        // A damaged table: said in the window (the file and the problem); nothing changes.
        const QString title = w.windowTitle();
        openLut(damaged);
        QVERIFY(w.messageBar().isVisible());
        QVERIFY2(w.messageBar().text().contains(damaged) &&
                     w.messageBar().text().contains("wrong size: 1000 bytes"),
                 qPrintable(w.messageBar().text()));
        QVERIFY(w.session().lut().table() == imported);
        QCOMPARE(w.session().lut().path(), foreign);
        QCOMPARE(w.windowTitle(), title);
        QVERIFY(!w.isWindowModified());
        QVERIFY(dialogs.unanswered.isEmpty());
    }

    void droppingAStreamFolderOrATableOpensIt()
    {
        const QString a = copyStream("drop_a"), b = copyStream("drop_b", 80);
        const QString table = copyStream("drop_table", 300) + "/default.lut";
        ScriptedDialogs dialogs;
        MainWindow w;
        w.show();
        QVERIFY(openAndWait(w, a));
        // Only local files are taken.
        QVERIFY(!drop(w, QUrl("https://example.org/stream")));
        QCOMPARE(canonical(w.session().stream().streamSpec()), canonical(a));

        QSignalSpy opened(&w.files(), &ui::SessionFiles::streamOpened);
        QVERIFY(drop(w, QUrl::fromLocalFile(b)));
        QVERIFY(opened.wait(10000));
        QVERIFY(opened.front().front().toBool());
        QCOMPARE(canonical(w.session().stream().streamSpec()), canonical(b));
        QVERIFY(waitForFrame(w, 0));
        QVERIFY(w.session().lut().table() == loadTable(b + "/default.lut"));

        QVERIFY(drop(w, QUrl::fromLocalFile(table)));
        QVERIFY(w.session().lut().table() == loadTable(table));
        QCOMPARE(w.session().lut().path(), table);
        QCOMPARE(canonical(w.session().stream().streamSpec()), canonical(b));

        // A drop over unsaved edits asks first, like the menu; Cancel keeps them.
        QVERIFY(clickEdit(w));
        const ColourLut edited = w.session().lut().table();
        dialogs.answers.push_back(QMessageBox::Cancel);
        drop(w, QUrl::fromLocalFile(a));
        QCOMPARE(dialogs.asked.last(), QStringLiteral("Unsaved LUT edits"));
        QVERIFY(!opened.wait(300));
        QCOMPARE(canonical(w.session().stream().streamSpec()), canonical(b));
        QVERIFY(w.session().lut().table() == edited);
        QVERIFY(dialogs.unanswered.isEmpty());
    }

    void theRecentStreamsMenuListsNewestFirstAndOpensOne()
    {
        const QString a = copyStream("recent_a"), b = copyStream("recent_b", 80);
        const auto listed = [](MainWindow& w) {
            QStringList texts;
            for (QAction* action : recentMenu(w)->actions())
                texts << action->text();
            return texts;
        };
        ScriptedDialogs dialogs;
        {
            MainWindow w;
            w.show();
            QVERIFY(recentMenu(w));
            QVERIFY(!recentMenu(w)->isEnabled()); // nothing opened yet
            QVERIFY(openAndWait(w, a));
            QVERIFY(openAndWait(w, b));
            QCOMPARE(listed(w), (QStringList{b, a}));
            QSignalSpy opened(&w.files(), &ui::SessionFiles::streamOpened);
            recentMenu(w)->actions().at(1)->trigger();
            QVERIFY(opened.wait(10000));
            QCOMPARE(canonical(w.session().stream().streamSpec()), canonical(a));
            QVERIFY(w.session().lut().table() == loadTable(a + "/default.lut"));
            QCOMPARE(listed(w), (QStringList{a, b}));
            QVERIFY(w.close());
        }
        // Remembered for the next start.
        MainWindow next;
        QCOMPARE(listed(next), (QStringList{a, b}));
        QVERIFY(recentMenu(next)->isEnabled());
        QVERIFY(dialogs.unanswered.isEmpty());
    }
};

FIELDSIGHT_TEST_SUITE(TestWorkflows, Widgets)

#include "test_workflows.moc"
