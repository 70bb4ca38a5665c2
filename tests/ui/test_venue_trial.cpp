// What the venue trial of issue 21 found in the window, each as the user met it: a damaged table
// beside a stream, a warning that outlived its cause, Save LUT As starting in the wrong folder,
// classes without keys, the wheel changing a parameter while the panel scrolls, stale previews.
#include "support/scripted_dialogs.h"
#include "support/synthetic_frames.h"
#include "support/window_waits.h"
#include "ui/widgets/message_bar.h"

#include <QSettings>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QtTest>

using namespace fieldsight;
using namespace fieldsight::test;
using fieldsight::ui::MainWindow;

namespace {

QString sampleStream()
{
    return QString::fromStdString(sampleStreamsDir() + "/lab1");
}

QByteArray fileBytes(const QString& path)
{
    QFile f(path);
    return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
}

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

class TestVenueTrial : public QObject
{
    Q_OBJECT

    QTemporaryDir m_dir;

    /// A copy of the bundled stream's frames (and its table, with `lut`).
    QString copyStream(const QString& name, bool lut = true)
    {
        const QString to = m_dir.filePath(name);
        QDir().mkpath(to);
        for (const QString& file : QDir(sampleStream()).entryList(QDir::Files))
            if (file.startsWith("frame_") || (lut && file == "default.lut"))
                QFile::copy(sampleStream() + "/" + file, to + "/" + file);
        return to;
    }

private slots:
    void initTestCase()
    {
        QStandardPaths::setTestModeEnabled(true);
        QCoreApplication::setOrganizationName("FieldsightTest");
        QCoreApplication::setApplicationName("test_venue_trial");
        QSettings().clear();
        QVERIFY(m_dir.isValid());
        if (!QFileInfo(sampleStream()).isDir())
            QSKIP("the bundled sample streams are missing");
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
};

QTEST_MAIN(TestVenueTrial)
#include "test_venue_trial.moc"
