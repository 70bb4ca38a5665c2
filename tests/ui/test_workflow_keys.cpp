// The window's keyboard workflows, offscreen, with real key events (a shortcut that is lost or
// taken by another item fails here): Ctrl+B bookmarks the frame and `[` / `]` go to the previous
// and next bookmark; Ctrl+E saves the view as PNG and Ctrl+Shift+C copies it; Alt+1..4 show the
// frame raw, classified, side by side and blended. Each checks what the user sees or what lands
// on disk.
#include "support/test_suite.h"
#include "support/test_files.h"
#include "support/scripted_dialogs.h"
#include "support/synthetic_frames.h"
#include "support/window_waits.h"
#include "ui/document/bookmarks.h"
#include "ui/panels/bookmarks_panel.h"
#include "ui/panels/layers_panel.h"

#include <QClipboard>
#include <QListWidget>
#include <QPainter>
#include <QSettings>
#include <QShortcut>
#include <QStandardPaths>
#include <QStatusBar>
#include <QTemporaryDir>
#include <QtTest>

using namespace fieldsight;
using namespace fieldsight::test;
using fieldsight::ui::MainWindow;

namespace {

/// The view's pixels in `area` (widget px).
QImage viewPixels(MainWindow& w, const QRect& area)
{
    return w.view().grab().toImage().copy(area).convertToFormat(QImage::Format_RGB32);
}

QImage rgb32(const QImage& image)
{
    return image.convertToFormat(QImage::Format_RGB32);
}

} // namespace

class TestWorkflowKeys : public QObject
{
    Q_OBJECT

    QTemporaryDir m_dir;

    /// The window shown and active (shortcuts need it) on a copy of the first `frames` frames.
    bool showOn(MainWindow& w, const QString& name, int frames)
    {
        const QString to = m_dir.filePath(name);
        QDir().mkpath(to);
        QFile::copy(sampleStream() + "/default.lut", to + "/default.lut");
        for (int i = 0; i < frames; ++i) {
            const QString frame = QStringLiteral("frame_%1.png").arg(i, 6, 10, QLatin1Char('0'));
            QFile::copy(sampleStream() + "/" + frame, to + "/" + frame);
        }
        w.show();
        return QTest::qWaitForWindowActive(&w) && openAndWait(w, to);
    }

    static bool key(MainWindow& w, Qt::Key k, Qt::KeyboardModifiers mods, std::size_t frame)
    {
        QTest::keyClick(&w, k, mods);
        return waitForFrame(w, frame);
    }

private slots:
    void initTestCase()
    {
        QCOMPARE(test::startWindowSuite("test_workflow_keys", m_dir), QString());
    }

    void init() { QSettings().clear(); }

    void noTwoActionsShareAKey()
    {
        // Qt fires neither of two window actions with one shortcut ("ambiguous"): every key the
        // menus, tools and panels bind must be bound once.
        MainWindow w;
        w.show();
        QVERIFY(QTest::qWaitForWindowActive(&w));
        std::map<QString, QStringList> owners;
        for (const QAction* action : w.findChildren<QAction*>()) {
            for (const QKeySequence& key : action->shortcuts())
                if (!key.isEmpty() && action->shortcutContext() != Qt::WidgetShortcut)
                    owners[key.toString()] << action->text();
        }
        for (const QShortcut* shortcut : w.findChildren<QShortcut*>())
            if (!shortcut->key().isEmpty() && shortcut->context() != Qt::WidgetShortcut)
                owners[shortcut->key().toString()] << shortcut->objectName();
        QVERIFY(owners.size() > 20);
        QStringList clashes;
        for (const auto& [key, names] : owners)
            if (names.size() > 1)
                clashes << key + ": " + names.join(" / ");
        QVERIFY2(clashes.isEmpty(), qPrintable(clashes.join("; ")));
    }

    void ctrlBMarksTheFrameAndBracketsGoBetweenMarks()
    {
        ScriptedDialogs dialogs;
        MainWindow w;
        QVERIFY(showOn(w, "marks", 10));
        const QString stream = w.session().stream().streamSpec();
        w.session().stream().setCurrentIndex(2);
        QVERIFY(waitForFrame(w, 2));
        dialogs.texts.push_back(QStringLiteral("post hidden"));
        QTest::keyClick(&w, Qt::Key_B, Qt::ControlModifier);
        QCOMPARE(dialogs.asked.last(), QStringLiteral("Bookmark frame 2"));
        w.session().stream().setCurrentIndex(7);
        QVERIFY(waitForFrame(w, 7));
        dialogs.texts.push_back(QStringLiteral("ball lost"));
        QTest::keyClick(&w, Qt::Key_B, Qt::ControlModifier);
        // Cancelling the note marks nothing.
        w.session().stream().setCurrentIndex(4);
        QVERIFY(waitForFrame(w, 4));
        QTest::keyClick(&w, Qt::Key_B, Qt::ControlModifier);
        QCOMPARE(dialogs.unanswered, QStringList{"Bookmark frame 4"});
        QVERIFY(!w.session().bookmarks().marks().find(4));

        // In the dock and in the file beside the stream.
        QListWidget& list = w.bookmarksPanel().list();
        QCOMPARE(list.count(), 2);
        QVERIFY2(list.item(0)->text().contains("post hidden"), qPrintable(list.item(0)->text()));
        QVERIFY2(list.item(1)->text().contains("ball lost"), qPrintable(list.item(1)->text()));
        QFile file(stream + "/bookmarks.json");
        QVERIFY(file.open(QIODevice::ReadOnly));
        QCOMPARE(file.readAll(),
                 QByteArray::fromStdString(w.session().bookmarks().marks().toJson()));
        const ui::Bookmark* mark = w.session().bookmarks().marks().find(7);
        QVERIFY(mark);
        QCOMPARE(QString::fromStdString(mark->note), QStringLiteral("ball lost"));
        QCOMPARE(QString::fromStdString(mark->name), QStringLiteral("frame_000007.png"));

        // `]` next, `[` previous, staying at the last or first mark.
        QVERIFY(key(w, Qt::Key_Home, {}, 0));
        QVERIFY(key(w, Qt::Key_BracketRight, {}, 2));
        QVERIFY(key(w, Qt::Key_BracketRight, {}, 7));
        QVERIFY(key(w, Qt::Key_BracketRight, {}, 7));
        QVERIFY(key(w, Qt::Key_BracketLeft, {}, 2));
        QVERIFY(key(w, Qt::Key_BracketLeft, {}, 2));
        QVERIFY(key(w, Qt::Key_End, {}, 9));
        QVERIFY(key(w, Qt::Key_BracketLeft, {}, 7));

        // Ctrl+B on a marked frame edits its note.
        dialogs.texts.push_back(QStringLiteral("ball behind the post"));
        QTest::keyClick(&w, Qt::Key_B, Qt::ControlModifier);
        QCOMPARE(w.session().bookmarks().marks().list().size(), std::size_t(2));
        QCOMPARE(QString::fromStdString(w.session().bookmarks().marks().find(7)->note),
                 QStringLiteral("ball behind the post"));
    }

    void ctrlESavesTheViewAsPngAndCtrlShiftCCopiesIt()
    {
        ScriptedDialogs dialogs;
        MainWindow w;
        QVERIFY(showOn(w, "snap", 5));
        QVERIFY(key(w, Qt::Key_Right, {}, 1));
        QVERIFY(key(w, Qt::Key_Right, {}, 2));
        const QImage shown = rgb32(w.view().grab().toImage());
        QVERIFY(shown.width() > 320 && shown.height() > 240);

        // Ctrl+E: the name suggested is the stream's and the frame's; the PNG is the view.
        const QString png = m_dir.filePath("view.png");
        dialogs.paths.push_back(png);
        QTest::keyClick(&w, Qt::Key_E, Qt::ControlModifier);
        QCOMPARE(dialogs.asked.last(), QStringLiteral("Save view as PNG"));
        QCOMPARE(dialogs.suggested.last(), QStringLiteral("snap_000002.png"));
        QCOMPARE(rgb32(QImage(png, "PNG")), shown);
        QCOMPARE(w.lastMessage(), "Saved the view to " + png);
        // No answer: nothing written. A folder that is not there: said, naming the file.
        QTest::keyClick(&w, Qt::Key_E, Qt::ControlModifier);
        QCOMPARE(dialogs.unanswered, QStringList{"Save view as PNG"});
        const QString nowhere = m_dir.filePath("missing/view.png");
        dialogs.paths.push_back(nowhere);
        QTest::keyClick(&w, Qt::Key_E, Qt::ControlModifier);
        QVERIFY(!QFileInfo::exists(nowhere));
        QVERIFY2(w.lastMessage().contains("missing/view.png"), qPrintable(w.lastMessage()));

        // Ctrl+Shift+C: the view as it is now (the message bar above it took some height).
        QApplication::clipboard()->clear();
        const QString tool = w.tools().active().info().id;
        const QImage now = rgb32(w.view().grab().toImage());
        QCOMPARE(now.width(), shown.width());
        QTest::keyClick(&w, Qt::Key_C, Qt::ControlModifier | Qt::ShiftModifier);
        QCOMPARE(rgb32(QApplication::clipboard()->image()), now);
        QCOMPARE(w.statusBar()->currentMessage(), QStringLiteral("The view is on the clipboard"));
        QCOMPARE(w.tools().active().info().id, tool); // not taken as C, the Click tool's key
    }

    void altOneToFourShowRawClassifiedSideBySideAndBlend()
    {
        ScriptedDialogs dialogs;
        MainWindow w;
        w.resize(1700, 1000); // side by side needs two frames' width
        QVERIFY(showOn(w, "modes", 3));
        w.layersPanel().setVisibleLayers({}); // the frame alone, no drawings
        w.view().setLabelsShown(false);
        w.view().setZoom(1);
        w.view().setImageOrigin({0, 0});
        const auto out = w.session().stream().current();
        const QImage raw = rgb32(out->raw), classified = rgb32(out->classified);
        QVERIFY(raw != classified);
        const QRect frame(QPoint(0, 0), raw.size());
        QVERIFY2(w.view().width() >= 2 * raw.width() + 20,
                 qPrintable(QString::number(w.view().width())));
        QImage blend = raw;
        {
            QPainter p(&blend);
            p.setOpacity(0.5);
            p.drawImage(0, 0, out->classified);
        }
        const auto checked = [&](ui::ViewMode mode) {
            auto* a = w.findChild<QAction*>(QStringLiteral("view.mode.%1").arg(int(mode)));
            return a && a->isChecked() && w.view().mode() == mode;
        };

        QTest::keyClick(&w, Qt::Key_2, Qt::AltModifier);
        QVERIFY(checked(ui::ViewMode::Classified));
        QCOMPARE(viewPixels(w, frame), classified);

        QTest::keyClick(&w, Qt::Key_3, Qt::AltModifier);
        QVERIFY(checked(ui::ViewMode::SideBySide));
        QCOMPARE(viewPixels(w, frame), raw);
        // The classified frame to the right of the raw one, past a gap of a few pixels.
        bool found = false;
        for (int gap = 0; gap <= 16 && !found; ++gap)
            found = viewPixels(w, frame.translated(raw.width() + gap, 0)) == classified;
        QVERIFY(found);

        QTest::keyClick(&w, Qt::Key_4, Qt::AltModifier);
        QVERIFY(checked(ui::ViewMode::Blend));
        QCOMPARE(viewPixels(w, frame), rgb32(blend));

        QTest::keyClick(&w, Qt::Key_1, Qt::AltModifier);
        QVERIFY(checked(ui::ViewMode::Raw));
        QCOMPARE(viewPixels(w, frame), raw);
        QVERIFY(dialogs.asked.isEmpty());
    }
};

FIELDSIGHT_TEST_SUITE(TestWorkflowKeys, Widgets)

#include "test_workflow_keys.moc"
