// Compare A/B and the COCO export in the main window, offscreen: Pipeline > Compare A/B with a
// table B that erases one colour lists the frames it broke for the class that colour finds (the
// same frames `compare` gives), choosing one shows that frame, a comparison can be cancelled, and
// File > Export annotations as COCO writes the annotations document's truth (unsaved edits too),
// never over an input.
#include "support/test_suite.h"
#include "support/scripted_dialogs.h"
#include "support/test_files.h"
#include "support/window_waits.h"
#include "ui/dialogs/ab_compare_dialog.h"
#include "visioncore/io/annotations.h"
#include "visioncore/services/stream_runner.h"

#include <nlohmann/json.hpp>

#include <QAction>
#include <QLabel>
#include <QPushButton>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTreeWidget>
#include <QtTest>

using namespace fieldsight;
using fieldsight::ui::MainWindow;

namespace {

QString lab2()
{
    return QString::fromStdString(test::sampleStreamsDir() + "/lab2");
}

QAction* actionNamed(MainWindow& w, const QString& name)
{
    return w.findChild<QAction*>(name);
}

bool waitForEnd(ui::AbCompareDialog& dialog)
{
    QSignalSpy ended(&dialog, &ui::AbCompareDialog::comparisonEnded);
    return !dialog.running() || ended.wait(120000);
}

} // namespace

class TestAbCompareWindow : public QObject
{
    Q_OBJECT

private:
    QTemporaryDir m_dir;
    /// lab2's table without the colour of one class (every cell of that colour unclassified);
    /// the colour is picked by its id here, so this file names no class.
    QString m_erased;

private slots:
    void initTestCase()
    {
        QCOMPARE(test::startWindowSuite("test_ab_compare_window", m_dir), QString());
        // The bundled streams are part of the project: a wrong path must fail, not skip.
        QVERIFY2(QFileInfo(lab2()).isDir(),
                 qPrintable("the bundled sample stream is missing: " + lab2()));
        auto lut = ColourLut::load((lab2() + "/default.lut").toStdString());
        QVERIFY(lut.ok());
        ColourLut table = std::move(lut).value();
        const auto erased = std::uint8_t(6); // SPEC §1's class 6
        for (std::size_t i = 0; i < ColourLut::kCells; ++i)
            if (table.data()[i] == erased)
                table.setCell(i, Colour::Unclassified);
        m_erased = m_dir.filePath("erased.lut");
        QVERIFY(table.save(m_erased.toStdString()).ok());
    }

    void compareListsTheBrokenFramesAndShowsOne()
    {
        MainWindow w;
        w.show();
        QVERIFY(QTest::qWaitForWindowActive(&w));
        QVERIFY(test::openAndWait(w, lab2()));
        test::ScriptedDialogs dialogs;
        QAction* compare = actionNamed(w, "pipeline.compare_ab");
        QVERIFY(compare);
        compare->trigger();
        auto* dialog = w.findChild<ui::AbCompareDialog*>("ab_compare");
        QVERIFY(dialog);
        auto* start = dialog->findChild<QPushButton*>("ab.start");
        QVERIFY(!start->isEnabled()); // no side B yet

        // Table B through the dialogs seam, then Compare.
        dialogs.paths.push_back(m_erased);
        QTest::mouseClick(dialog->findChild<QPushButton*>("ab.table"), Qt::LeftButton);
        QVERIFY(start->isEnabled());
        QVERIFY(dialog->findChild<QLabel*>("ab.sides")->text().contains("erased.lut"));
        QTest::mouseClick(start, Qt::LeftButton);
        QVERIFY(dialog->running());
        QVERIFY(waitForEnd(*dialog));
        QVERIFY2(dialog->result().has_value(), qPrintable(dialog->status()));

        // The class the erased colour finds: every frame it got right is broken; the window's
        // frames are the command's (the same service over the same table and frames).
        const AbComparison& c = *dialog->result();
        QCOMPARE(c.frames, std::size_t(30));
        // (Its pixels unclassified, the same frames also gain a false detection of another
        // class; the one that lost every true positive is the colour's.)
        const AbClass* hit = nullptr;
        for (const AbClass& k : c.classes)
            if (k.a.tp > 0 && k.b.tp == 0)
                hit = &k;
        QVERIFY(hit);
        QCOMPARE(hit->b.tp, 0);
        QCOMPARE(hit->broken.size() + hit->wrong_both, std::size_t(30));
        QVERIFY(hit->fixed.empty());

        auto input = openStreamInput((lab2()).toStdString(), "");
        QVERIFY(input.ok());
        auto truth = Annotations::load((lab2() + "/annotations.json").toStdString(),
                                       w.session().pipeline().perceptKinds());
        QVERIFY(truth.ok());
        AbSide b;
        b.lut = std::make_shared<const ColourLut>(ColourLut::load(m_erased.toStdString()).value());
        auto direct = compareAb(input.value(), b, truth.value(), "truth", 1);
        QVERIFY(direct.ok());
        for (std::size_t k = 0; k < c.classes.size(); ++k) {
            QCOMPARE(c.classes[k].a, direct.value().classes[k].a);
            QCOMPARE(c.classes[k].b, direct.value().classes[k].b);
            QCOMPARE(c.classes[k].broken.size(), direct.value().classes[k].broken.size());
        }

        // The list: one row per class, its broken frames under it; choosing one shows it.
        QTreeWidget& list = dialog->frameList();
        QCOMPARE(list.topLevelItemCount(), int(c.classes.size()));
        QTreeWidgetItem* row = nullptr;
        for (int i = 0; i < list.topLevelItemCount(); ++i)
            if (list.topLevelItem(i)->text(0).startsWith(QString::fromStdString(hit->name) + ":"))
                row = list.topLevelItem(i);
        QVERIFY(row);
        QCOMPARE(row->childCount(), int(hit->broken.size()));
        const AbFrame& target = hit->broken.back();
        QTreeWidgetItem* last = row->child(row->childCount() - 1);
        QVERIFY(last->text(0).contains(QString::fromStdString(target.name)));
        QVERIFY(target.index != w.session().stream().currentIndex());
        list.setCurrentItem(last);
        QCOMPARE(w.session().stream().currentIndex(), target.index);
        QVERIFY(test::waitForFrame(w, target.index));

        // Cancelled at once: no result, and it says so.
        QTest::mouseClick(start, Qt::LeftButton);
        QVERIFY(dialog->running());
        QTest::mouseClick(dialog->findChild<QPushButton*>("ab.cancel"), Qt::LeftButton);
        QVERIFY(waitForEnd(*dialog));
        QVERIFY(!dialog->result());
        QVERIFY2(dialog->status().contains("Cancelled"), qPrintable(dialog->status()));
        QCOMPARE(list.topLevelItemCount(), 0);
    }

    void fileExportWritesCocoNeverOverAnInput()
    {
        MainWindow w;
        w.show();
        QVERIFY(QTest::qWaitForWindowActive(&w));
        QVERIFY(test::openAndWait(w, lab2()));
        test::ScriptedDialogs dialogs;
        QAction* exporting = actionNamed(w, "file.export_coco");
        QVERIFY(exporting);

        const QString out = m_dir.filePath("window_coco.json");
        dialogs.paths.push_back(out);
        exporting->trigger();
        QVERIFY2(QFileInfo::exists(out), qPrintable(w.lastMessage()));
        QVERIFY(w.lastMessage().contains("window_coco.json"));
        QVERIFY(dialogs.suggested.back().startsWith(lab2()));
        const auto coco = nlohmann::json::parse(test::fileBytes(out).toStdString(), nullptr, false);
        QCOMPARE(coco.at("images").size(), std::size_t(30));
        QCOMPARE(coco.at("images").at(0).at("width").get<int>(), 320);

        // What the annotations document holds is exported, unsaved edits too.
        QVERIFY(
            w.session().annotations().edit("drop frame 0", {{"frame_000000.png", std::nullopt}}));
        QVERIFY(w.session().annotations().modified());
        const QString edited = m_dir.filePath("edited_coco.json");
        dialogs.paths.push_back(edited);
        exporting->trigger();
        const auto fewer =
            nlohmann::json::parse(test::fileBytes(edited).toStdString(), nullptr, false);
        QCOMPARE(fewer.at("images").size(), std::size_t(29));
        QCOMPARE(fewer.at("images").at(0).at("file_name").get<std::string>(),
                 std::string("frame_000001.png"));

        // Over the stream's own annotations: refused, the file as it was.
        const QString truth = lab2() + "/annotations.json";
        const QByteArray before = test::fileBytes(truth);
        dialogs.paths.push_back(truth);
        exporting->trigger();
        QVERIFY(w.lastMessage().contains("nothing was written"));
        QCOMPARE(test::fileBytes(truth), before);
    }
};

FIELDSIGHT_TEST_SUITE(TestAbCompareWindow, Widgets)

#include "test_ab_compare_window.moc"
