// The colour table in the window, as a user works with it: a damaged table beside a stream, the
// no-table warning, New LUT, clearing a class and the class keys, the tolerance box, Save LUT As
// and the stream's table, the sample regions; and around it: the window's outputs never replace
// its inputs, the wheel scrolls the panel, a reopened stream comes back at its frame.
#include "support/test_files.h"
#include "support/test_suite.h"
#include "support/scripted_dialogs.h"
#include "support/synthetic_frames.h"
#include "support/window_waits.h"
#include "ui/adapters/image_adapter.h"
#include "ui/recording/frame_recorder.h"
#include "ui/panels/lut_panel.h"
#include "ui/panels/pipeline_panel.h"
#include "ui/tools/tool.h"
#include "visioncore/services/lut_building.h"
#include "ui/widgets/message_bar.h"

#include <QDockWidget>
#include <QPushButton>
#include <QSlider>
#include <QScrollArea>
#include <QScrollBar>
#include <QSpinBox>
#include <QWheelEvent>
#include <QToolButton>

#include <QSettings>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QtTest>

using namespace fieldsight;
using namespace fieldsight::test;
using fieldsight::ui::MainWindow;

namespace {

bool writeBytes(const QString& path, const QByteArray& bytes)
{
    QFile f(path);
    return f.open(QIODevice::WriteOnly) && f.write(bytes) == bytes.size();
}

std::size_t classifiedCells(MainWindow& w)
{
    const ColourLut& t = w.session().lut().table();
    return std::size_t(std::count_if(t.data(), t.data() + ColourLut::kCells,
                                     [](std::uint8_t c) { return c != 0; }));
}

} // namespace

class TestLutWorkflows : public QObject
{
    Q_OBJECT

    QTemporaryDir m_dir;

    /// A copy of the bundled stream's frames (and its table, with `lut`).
    QString copyStream(const QString& name, bool lut = true)
    {
        return copyFolderFiles(sampleStream(), m_dir.filePath(name),
                               lut ? isFrameOrTable : isFrameFile);
    }

private slots:
    void initTestCase()
    {
        QCOMPARE(test::startWindowSuite("test_lut_workflows", m_dir), QString());
        QSettings().clear();
    }

    void init() { QSettings().clear(); }

    /// A damaged default.lut no longer stops the stream opening: it opens with an empty table,
    /// the window says why, and no save writes over the damaged file without asking.
    void aDamagedTableOpensTheStreamWithAnEmptyOne()
    {
        const QString stream = copyStream("damaged");
        const QString lut = stream + "/default.lut";
        const QByteArray damaged = fileBytes(lut).left(1000) + QByteArray("not a table");
        QVERIFY(writeBytes(lut, damaged));

        MainWindow w;
        w.show();
        QVERIFY(openAndWait(w, stream));
        QVERIFY(w.session().stream().frameCount() > 1);
        QCOMPARE(classifiedCells(w), std::size_t(0));
        QVERIFY(w.session().lut().path().isEmpty());
        QVERIFY(w.messageBar().isVisible());
        QVERIFY2(w.messageBar().text().contains(lut), qPrintable(w.messageBar().text()));
        QVERIFY2(w.messageBar().text().contains("empty table"), qPrintable(w.messageBar().text()));

        // An edit, then Ctrl+S: the save asks where (starting in the stream's folder); cancelled,
        // nothing is written.
        ScriptedDialogs dialogs;
        std::vector<CellChange> one = {{100, Colour::Unclassified, Colour::Green}};
        QVERIFY(w.session().lut().edit("edit", one));
        QTest::keyClick(&w, Qt::Key_S, Qt::ControlModifier);
        QCOMPARE(dialogs.asked, QStringList{"Save LUT as"});
        QCOMPARE(QFileInfo(dialogs.suggested.front()).absolutePath(), stream);
        QCOMPARE(fileBytes(lut), damaged);
        QVERIFY(w.session().lut().modified());
    }

    /// "Every pixel is unclassified" goes away once the table has a class.
    void theNoTableWarningGoesWhenTheTableHasAClass()
    {
        const QString stream = copyStream("no_table", false);
        MainWindow w;
        w.show();
        QVERIFY(openAndWait(w, stream));
        QVERIFY(w.messageBar().isVisible());
        QVERIFY(w.messageBar().text().contains("unclassified"));
        std::vector<CellChange> none = {{7, Colour::Unclassified, Colour::Unclassified}};
        w.session().lut().edit("nothing", none);
        QVERIFY(w.messageBar().isVisible());
        std::vector<CellChange> one = {{100, Colour::Unclassified, Colour::White}};
        QVERIFY(w.session().lut().edit("edit", one));
        QVERIFY(!w.messageBar().isVisible());
        // An unrelated message later is not hidden by the next edit.
        w.showMessage("something else");
        std::vector<CellChange> two = {{101, Colour::Unclassified, Colour::White}};
        QVERIFY(w.session().lut().edit("edit", two));
        QVERIFY(w.messageBar().isVisible());
    }

    /// The window's own outputs follow the commands' rule: a snapshot never replaces a file of
    /// the stream or the table in use, and a recording goes only into a new or empty folder.
    void theWindowsOutputsNeverWriteOverInputs()
    {
        const QString stream = copyStream("outputs");
        MainWindow w;
        w.show();
        QVERIFY(openAndWait(w, stream));
        const QString frame = stream + "/frame_000000.png";
        const QByteArray frame_bytes = fileBytes(frame);
        QVERIFY(!w.files().saveSnapshot(frame));
        QCOMPARE(fileBytes(frame), frame_bytes);
        QVERIFY2(w.messageBar().text().contains(frame), qPrintable(w.messageBar().text()));
        const QString lut = stream + "/default.lut";
        const QByteArray lut_bytes = fileBytes(lut);
        QVERIFY(!w.files().saveSnapshot(lut));
        QCOMPARE(fileBytes(lut), lut_bytes);
        // A new file beside the frames is fine.
        QVERIFY(w.files().saveSnapshot(stream + "/view.png"));
        QVERIFY(QImage(stream + "/view.png").width() > 0);

        // Recording into the stream's folder would replace its table: refused.
        const auto into_stream = w.recorder().start(stream, w.session().lut().table());
        QVERIFY(!into_stream);
        QVERIFY(QString::fromStdString(into_stream.error().message).contains("not empty"));
        QCOMPARE(fileBytes(lut), lut_bytes);
        QVERIFY(!w.recorder().recording());
    }

    /// File > New LUT starts an empty untitled table (asking first about unsaved edits); one
    /// class can be cleared from the whole table as one undo step; every class has a key,
    /// shown on its button, and the buttons are in id order.
    void newTableClearAClassAndAKeyForEveryClass()
    {
        const QString stream = copyStream("new_lut");
        MainWindow w;
        w.show();
        QVERIFY(openAndWait(w, stream));
        const std::size_t had = classifiedCells(w);
        QVERIFY(had > 0);

        // Clear green: only green goes, one undo step brings it back.
        const ColourLut before = w.session().lut().table();
        const auto green = std::size_t(std::count(before.data(), before.data() + ColourLut::kCells,
                                                  std::uint8_t(Colour::Green)));
        QVERIFY(green > 0);
        QTest::keyClick(&w, Qt::Key_2);
        QCOMPARE(w.tools().settings().colour(), Colour::Green);
        w.findChild<QPushButton*>("clear_class")->click();
        QCOMPARE(classifiedCells(w), had - green);
        QVERIFY(w.messageBar().text().contains("green"));
        w.session().lut().undoStack().undo();
        QVERIFY(w.session().lut().table() == before);

        // Every class answers a key, in id order, and its button shows the key.
        QStringList buttons;
        for (int c = 0; c < kColourCount; ++c) {
            const QKeySequence key = c <= 9 ? QKeySequence(Qt::Key_0 + c) : QKeySequence("-");
            QTest::keyClick(&w, key[0].key());
            QCOMPARE(int(w.tools().settings().colour()), c);
            auto* button = w.findChild<QToolButton*>("colour_button." + ui::colourLabel(Colour(c)));
            QVERIFY(button);
            QVERIFY2(button->text().startsWith(key.toString(QKeySequence::NativeText)),
                     qPrintable(button->text()));
            buttons << button->text();
        }
        QCOMPARE(buttons.size(), 11);

        // New LUT with an edit pending: Cancel keeps it, Discard gives an empty untitled table.
        std::vector<CellChange> one = {{100, Colour::Unclassified, Colour::Green}};
        QVERIFY(w.session().lut().edit("edit", one));
        ScriptedDialogs dialogs;
        QAction* new_lut = w.findChild<QAction*>("file.new_lut");
        QVERIFY(new_lut);
        dialogs.answers = {QMessageBox::Cancel};
        new_lut->trigger();
        QVERIFY(w.session().lut().modified());
        QCOMPARE(w.session().lut().path(), stream + "/default.lut");
        dialogs.answers = {QMessageBox::Discard};
        new_lut->trigger();
        QCOMPARE(classifiedCells(w), std::size_t(0));
        QVERIFY(w.session().lut().path().isEmpty());
        QVERIFY(!w.session().lut().modified());
        QCOMPARE(fileBytes(stream + "/default.lut"),
                 fileBytes(sampleStream() + "/default.lut")); // the file is untouched
        // Its notice goes with the first class (the trial saw it stay through 28 edits).
        QVERIFY(w.messageBar().isVisible());
        QVERIFY(w.session().lut().edit("edit", one));
        QVERIFY(!w.messageBar().isVisible());
    }

    /// Return in a tolerance box gives the keys back: the next digit chooses a class instead of
    /// typing into the box.
    void returnInAToleranceBoxGivesTheKeysBack()
    {
        MainWindow w;
        w.resize(1280, 800);
        w.show();
        QVERIFY(QTest::qWaitForWindowActive(&w));
        QVERIFY(openAndWait(w, sampleStream()));
        w.findChild<QDockWidget*>("lut_dock")->raise();
        auto* box = w.findChild<QSpinBox*>("tolerance.y");
        QVERIFY(box);
        box->setFocus();
        QTRY_VERIFY(box->hasFocus());
        box->selectAll();
        QTest::keyClicks(box, "24");
        QTest::keyClick(box, Qt::Key_Return);
        QCOMPARE(w.tools().settings().tolerance().y, 24);
        QVERIFY(!box->hasFocus());
        QTest::keyClick(QApplication::focusWidget() ? QApplication::focusWidget() : &w, Qt::Key_2);
        QCOMPARE(w.tools().settings().colour(), Colour::Green);
        QCOMPARE(box->value(), 24);
    }

    /// The wheel over a parameter's spin box scrolls the panel unless the box has focus.
    void theWheelScrollsThePanelUnlessTheBoxHasFocus()
    {
        MainWindow w;
        w.resize(1280, 800);
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        QVERIFY(openAndWait(w, sampleStream()));
        QWidget* panel = &w.pipelinePanel();
        panel->parentWidget()->raise();
        auto* scroll = panel->findChild<QScrollArea*>();
        QVERIFY(scroll);
        QTRY_VERIFY(scroll->verticalScrollBar()->maximum() > 0);
        QSpinBox* box = nullptr;
        for (QSpinBox* b : panel->findChildren<QSpinBox*>())
            if (b->isVisible() && b->value() > b->minimum() && b->value() < b->maximum())
                box = b;
        QVERIFY(box);
        const auto wheel = [box] {
            const QPointF at(box->width() / 2.0, box->height() / 2.0);
            QWheelEvent e(at, box->mapToGlobal(at), {}, QPoint(0, -120), Qt::NoButton,
                          Qt::NoModifier, Qt::NoScrollPhase, false);
            QApplication::sendEvent(box, &e);
        };
        const int value = box->value();
        const int scrolled = scroll->verticalScrollBar()->value();
        wheel();
        QCOMPARE(box->value(), value);
        QVERIFY(scroll->verticalScrollBar()->value() != scrolled);
        box->setFocus();
        QTRY_VERIFY(box->hasFocus());
        wheel();
        QVERIFY(box->value() != value);
    }

    /// Save LUT As starts in the stream's folder and offers to make the table the stream's own
    /// (stream.json's "lut"), so the stream opens with it next time.
    void saveAsOffersToBecomeTheStreamsTable()
    {
        const QString stream = copyStream("save_as");
        const QByteArray own = fileBytes(stream + "/default.lut");
        {
            MainWindow w;
            w.show();
            QVERIFY(openAndWait(w, stream));
            std::vector<CellChange> one = {{100, Colour::Unclassified, Colour::Green}};
            QVERIFY(w.session().lut().edit("edit", one));
            ScriptedDialogs dialogs;
            dialogs.paths = {stream + "/venue.lut"};
            dialogs.answers = {QMessageBox::Yes};
            QTest::keyClick(&w, Qt::Key_S, Qt::ControlModifier | Qt::ShiftModifier);
            QCOMPARE(QFileInfo(dialogs.suggested.front()).absolutePath(), stream);
            QCOMPARE(dialogs.asked, (QStringList{"Save LUT as", "Use as this stream's table"}));
            QVERIFY(QFileInfo::exists(stream + "/venue.lut"));
            QCOMPARE(fileBytes(stream + "/default.lut"), own);
            QVERIFY(fileBytes(stream + "/stream.json").contains("\"lut\": \"venue.lut\""));
        }
        MainWindow again;
        again.show();
        QVERIFY(openAndWait(again, stream));
        QCOMPARE(again.session().lut().path(), stream + "/venue.lut");
        QCOMPARE(again.session().lut().table().data()[100], std::uint8_t(Colour::Green));
    }

    /// Sample regions are drawn while the Sample tool is active; a click selects one, a drag
    /// moves it, Delete removes it, and each is one undo step of the samples document.
    void sampleRegionsAreDrawnSelectedMovedAndDeleted()
    {
        const QString stream = copyStream("samples");
        MainWindow w;
        w.resize(1280, 800);
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        QVERIFY(openAndWait(w, stream));
        w.view().setZoom(1);
        w.view().setImageOrigin({0, 0});
        QTest::keyClick(&w, Qt::Key_S);
        QCOMPARE(w.tools().active().info().id, QStringLiteral("sample"));
        const auto drag = [&w](QPoint from, QPoint to) {
            QTest::mousePress(&w.view(), Qt::LeftButton, {}, from);
            QTest::mouseMove(&w.view(), (from + to) / 2);
            QTest::mouseMove(&w.view(), to);
            QTest::mouseRelease(&w.view(), Qt::LeftButton, {}, to);
        };
        QTest::keyClick(&w, Qt::Key_2);
        drag({40, 180}, {80, 220});
        QTest::keyClick(&w, Qt::Key_1);
        drag({200, 40}, {230, 60});
        ui::SamplesDocument& samples = w.session().samples();
        QCOMPARE(samples.samples().samples.size(), std::size_t(2));

        // Both drawn, in their class colours, over the image.
        ui::ToolOutline outline = w.tools().active().outline();
        QCOMPARE(outline.shapes.size(), std::size_t(2));
        QCOMPARE(outline.shapes[0].polygon.boundingRect(), QRectF(40, 180, 40, 40));
        QCOMPARE(outline.shapes[0].colour, ui::toQColor(colourDisplayRgb(Colour::Green)));
        const QImage shown = w.view().grab().toImage();
        QCOMPARE(QColor(shown.pixel(60, 180)), ui::toQColor(colourDisplayRgb(Colour::Green)));

        // A click inside the first selects it; a drag moves it by (10, -5), one undo step.
        const std::vector<cv::Point> first = samples.samples().samples[0].polygon;
        const int steps = samples.undoStack().count();
        drag({50, 200}, {60, 195});
        QVERIFY(w.tools().active().outline().shapes[0].selected);
        QCOMPARE(samples.samples().samples.size(), std::size_t(2));
        QCOMPARE(samples.undoStack().count(), steps + 1);
        for (std::size_t i = 0; i < first.size(); ++i)
            QCOMPARE(samples.samples().samples[0].polygon[i], first[i] + cv::Point(10, -5));
        QVERIFY(loadLutSamples(samples.path().toStdString()).value().samples[0].polygon[0] ==
                first[0] + cv::Point(10, -5));

        // Delete removes the selected one; undo brings it back where it was moved to.
        QTest::keyClick(&w, Qt::Key_Delete);
        QCOMPARE(samples.samples().samples.size(), std::size_t(1));
        QCOMPARE(samples.samples().samples[0].colour, Colour::White);
        QCOMPARE(w.tools().active().outline().shapes.size(), std::size_t(1));
        samples.undoStack().undo();
        QCOMPARE(samples.samples().samples.size(), std::size_t(2));
        QCOMPARE(samples.samples().samples[0].polygon[0], first[0] + cv::Point(10, -5));
        // Nothing selected: Delete does nothing.
        QTest::keyClick(&w, Qt::Key_Delete);
        QCOMPARE(samples.samples().samples.size(), std::size_t(2));
        // Another frame has none of them.
        QTest::keyClick(&w, Qt::Key_Right);
        QVERIFY(waitForFrame(w, 1));
        QCOMPARE(w.tools().active().outline().shapes.size(), std::size_t(0));
    }

    /// A stream opened again, in this window or the next one, comes back on the frame it was
    /// left on.
    void reopeningAStreamRemembersItsFrame()
    {
        const QString a = copyStream("frames_a");
        const QString b = copyStream("frames_b");
        {
            MainWindow w;
            w.show();
            QVERIFY(openAndWait(w, a));
            w.session().stream().setCurrentIndex(3);
            QVERIFY(waitForFrame(w, 3));
            QVERIFY(openAndWait(w, b));
            QCOMPARE(w.session().stream().currentIndex(), std::size_t(0));
            QSignalSpy opened(&w.files(), &ui::SessionFiles::streamOpened);
            w.files().openStream(a);
            QVERIFY(opened.wait(10000));
            QVERIFY(waitForFrame(w, 3));
            w.session().stream().setCurrentIndex(5);
            QVERIFY(waitForFrame(w, 5));
            w.close(); // saves the settings
        }
        MainWindow again;
        again.show();
        const ui::WindowSettings last = ui::WindowSettings::load();
        QCOMPARE(last.stream, a);
        QSignalSpy opened(&again.files(), &ui::SessionFiles::streamOpened);
        again.files().openLastSession(last.stream, last.lut);
        QVERIFY(opened.wait(10000));
        QVERIFY(waitForFrame(again, 5));
    }

    /// At 1280x800 on a first start, every control of the LUT editor is in sight: no horizontal
    /// scroll bar, nothing below the dock's visible part.
    void everyLutControlShowsAt1280x800()
    {
        MainWindow w;
        w.resize(1280, 800);
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        QVERIFY(openAndWait(w, sampleStream()));
        auto* dock = w.findChild<QDockWidget*>("lut_dock");
        QVERIFY(dock);
        dock->raise();
        QTRY_VERIFY(dock->isVisible() && w.lutPanel().isVisible());
        auto* scroll = qobject_cast<QScrollArea*>(dock->widget());
        QVERIFY(scroll);
        QTRY_VERIFY2(!scroll->horizontalScrollBar()->isVisible(),
                     qPrintable(QStringLiteral("panel needs %1, has %2")
                                    .arg(w.lutPanel().minimumSizeHint().width())
                                    .arg(scroll->viewport()->width())));
        const QRect seen = scroll->viewport()->rect();
        int controls = 0;
        for (QWidget* c : w.lutPanel().findChildren<QWidget*>()) {
            if (!qobject_cast<QAbstractButton*>(c) && !qobject_cast<QAbstractSpinBox*>(c) &&
                !qobject_cast<QSlider*>(c))
                continue;
            const QRect at(c->mapTo(scroll->viewport(), QPoint(0, 0)), c->size());
            QVERIFY2(seen.contains(at),
                     qPrintable(c->objectName() + " " + c->metaObject()->className()));
            ++controls;
        }
        QVERIFY(controls >= 25); // 11 classes, 6 tools, the settings, samples, table buttons
    }
};

FIELDSIGHT_TEST_SUITE(TestLutWorkflows, Widgets)

#include "test_lut_workflows.moc"
