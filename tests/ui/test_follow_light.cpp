// View > Follow the light in the real main window, offscreen: on a stream whose light drifts
// away from its table's, switching it on makes the worker classify the last frame through that
// frame's light (the carpet green again), the strip under the timeline plots how far the light
// moved, switching it off gives the table as it is again, and the window remembers the switch.
#include "support/test_suite.h"
#include "support/light_ramp.h"
#include "support/child_process.h"
#include "support/test_files.h"
#include "support/window_waits.h"
#include "ui/scans/edit_effect_scan.h"
#include "ui/scans/evaluation_scan.h"
#include "ui/scans/light_scan.h"
#include "ui/main_window.h"
#include "ui/settings/window_settings.h"
#include "ui/panels/evaluation_panel.h"
#include "ui/stream_navigator/effect_strip.h"
#include "ui/stream_navigator/light_strip.h"
#include "ui/stream_navigator/stream_navigator.h"

#include <QAction>
#include <QJsonDocument>
#include <QJsonObject>
#include <QLabel>
#include <QSettings>
#include <QStandardPaths>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QtTest>

#include <opencv2/core.hpp>

using namespace fieldsight;
using namespace fieldsight::test;
using fieldsight::ui::MainWindow;

namespace {

/// Pixels of the current frame's classes in `colour`, below row `from`.
int pixelsOf(MainWindow& w, Colour colour, int from)
{
    const auto& out = w.session().stream().current();
    if (!out || out->classes.empty())
        return -1;
    const cv::Mat below = out->classes.rowRange(from, out->classes.rows);
    return cv::countNonZero(below == int(colour));
}

/// Whether `scan` has finished a scan that covered frame `last`.
bool scanned(const ui::EditEffectScan& scan, std::size_t last)
{
    return !scan.running() && scan.effects().size() > last && scan.effects()[last].done;
}

} // namespace

class TestFollowLight : public QObject
{
    Q_OBJECT

private:
    QTemporaryDir m_dir;
    QString m_stream;

private slots:
    void initTestCase()
    {
        QCOMPARE(test::startWindowSuite("test_follow_light", m_dir), QString());
        // The bundled lab2 stream, its light going 30% warmer and 15% dimmer over its frames.
        m_stream = m_dir.filePath("drift");
        const QString made = writeLightRamp(QString::fromStdString(sampleStreamsDir() + "/lab2"),
                                            m_stream, {1.3 * 0.85, 0.85, 0.7 * 0.85});
        QVERIFY2(made.isEmpty(), qPrintable(made));
    }

    void init() { QSettings().clear(); } // no switch left on by a run before

    void followingTheLightReadsTheLastFrameInItsOwnLightAndPlotsIt()
    {
        MainWindow w;
        w.show();
        QVERIFY(openAndWait(w, m_stream));
        const std::size_t last = w.session().stream().frameCount() - 1;
        QVERIFY(last > 10);
        w.navigator().goToFrame(last);
        QVERIFY(waitForFrame(w, last));
        const int rows = w.session().stream().current()->classes.rows;
        const int static_green = pixelsOf(w, Colour::Green, rows / 2);
        const cv::Mat static_classes = w.session().stream().current()->classes.clone();
        QTRY_VERIFY_WITH_TIMEOUT(scanned(w.session().effectScan(), last), 30000);
        const std::uint32_t static_unclassified =
            w.session().effectScan().effects()[last].unclassified;
        QVERIFY(!w.timeline().lightStrip().isVisible());

        auto* follow = w.findChild<QAction*>(QStringLiteral("view.follow_light"));
        QVERIFY(follow && follow->isCheckable() && !follow->isChecked());
        follow->trigger();
        ui::LightScan& scan = w.session().lightScan();
        QVERIFY(scan.enabled());
        QTRY_VERIFY_WITH_TIMEOUT(scan.track() != nullptr, 30000);
        QVERIFY(w.session().stream().light() == scan.track());
        QVERIFY(waitForFrame(w, last));
        const int followed_green = pixelsOf(w, Colour::Green, rows / 2);
        // The carpet of the last frame, lost to the static table, is green again.
        QVERIFY2(followed_green > static_green + rows * 20,
                 qPrintable(QString("green %1 -> %2").arg(static_green).arg(followed_green)));

        // The strip plots every frame's distance from the table's light: none at the start,
        // growing to the end.
        QVERIFY(w.timeline().lightStrip().isVisible());
        const std::vector<double> d = w.timeline().lightStrip().distances();
        QCOMPARE(d.size(), last + 1);
        QCOMPARE(d.front(), 0.0);
        QVERIFY2(d.back() > 0.2 && d.back() > d[last / 2], qPrintable(QString::number(d.back())));
        QVERIFY(w.timeline().lightStrip().frameText(last).contains(QStringLiteral("R ×")));
        // The whole-stream scans read the frames in their light too: the last frame's carpet is
        // counted classified, and the strip's summary and the status bar say whose counts they
        // are.
        ui::EditEffectScan& effect = w.session().effectScan();
        QVERIFY(effect.followsLight() && w.session().evaluation().followsLight());
        QTRY_VERIFY_WITH_TIMEOUT(scanned(effect, last), 30000);
        const std::uint32_t followed_unclassified = effect.effects()[last].unclassified;
        QVERIFY2(followed_unclassified + std::uint32_t(rows) * 20 < static_unclassified,
                 qPrintable(QString("unclassified %1 -> %2")
                                .arg(static_unclassified)
                                .arg(followed_unclassified)));
        const QString switched_on = QStringLiteral("Follow the light switched on, over");
        QVERIFY2(w.timeline().effectStrip().summary().startsWith(switched_on),
                 qPrintable(w.timeline().effectStrip().summary()));
        auto* status = w.findChild<QLabel*>(QStringLiteral("effect_summary"));
        QVERIFY(status);
        QVERIFY2(status->text().contains(switched_on), qPrintable(status->text()));
        // The evaluation panel scores the frames in their light: its counts are eval --adapt's.
        QVERIFY(waitForEvaluation(w));
        const QString json = m_dir.filePath("adapt_eval.json");
        const Outcome o =
            runChild(FIELDSIGHT_EXE,
                     {"eval", m_stream.toStdString(), "--adapt", "--json", json.toStdString()},
                     m_dir.path().toStdString(), RLIM_INFINITY, false, 120);
        QVERIFY2(o.status == 0, o.err.c_str());
        const QJsonObject classes =
            QJsonDocument::fromJson(fileBytes(json)).object().value("classes").toObject();
        const QStringList names{"ball", "goalpost", "obstacle", "field_line"};
        const QTableWidget& scores = w.evaluationPanel().scores();
        QCOMPARE(scores.rowCount(), names.size());
        for (int r = 0; r < names.size(); ++r) {
            const QJsonObject c = classes.value(names[r]).toObject();
            QVERIFY2(!c.isEmpty(), qPrintable(names[r]));
            for (const auto& [column, key] : {std::pair{1, "tp"}, {2, "fp"}, {3, "fn"}})
                QCOMPARE(scores.item(r, column)->text(), QString::number(c.value(key).toInt()));
        }
        QVERIFY(classes.value("ball").toObject().value("tp").toInt() > 0);

        // Off: the table as it is again, the same classes as before.
        follow->trigger();
        QVERIFY(!scan.enabled() && !scan.track());
        QVERIFY(!w.session().stream().light());
        QVERIFY(waitForFrame(w, last));
        const cv::Mat again = w.session().stream().current()->classes;
        QCOMPARE(cv::countNonZero(again != static_classes), 0);
        QVERIFY(!w.timeline().lightStrip().isVisible());
        QVERIFY(!effect.followsLight() && !w.session().evaluation().followsLight());
        QTRY_VERIFY_WITH_TIMEOUT(scanned(effect, last), 30000);
        QCOMPARE(effect.effects()[last].unclassified, static_unclassified);
        QVERIFY2(w.timeline().effectStrip().summary().startsWith(
                     QStringLiteral("Follow the light switched off, over")),
                 qPrintable(w.timeline().effectStrip().summary()));
        QVERIFY(!status->text().contains(QStringLiteral("Following the light")));

        // Remembered: on at the close, on in the next window.
        follow->trigger();
        w.close();
        QVERIFY(ui::WindowSettings::load().follow_light);
        MainWindow next;
        auto* next_follow = next.findChild<QAction*>(QStringLiteral("view.follow_light"));
        QVERIFY(next_follow && next_follow->isChecked() && next.session().lightScan().enabled());
    }
};

FIELDSIGHT_TEST_SUITE(TestFollowLight, Widgets)

#include "test_follow_light.moc"
