// The message bar over the frame's top: a report of what was done goes by itself, a problem stays.
#include "support/test_suite.h"
#include "ui/widgets/message_bar.h"

#include <QLabel>
#include <QTimer>
#include <QtTest>

using namespace fieldsight::ui;

class TestMessageBar : public QObject
{
    Q_OBJECT

private slots:
    void aReportGoesByItselfAndAProblemStays()
    {
        QWidget window;
        window.resize(400, 300);
        auto* bar = new MessageBar(&window);
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        auto* fade = bar->findChild<QTimer*>();
        QVERIFY(fade);
        QCOMPARE(fade->interval(), MessageBar::kInfoShownMs);
        fade->setInterval(30); // the test's own pace: what is tested is that it goes, not when
        bar->setGeometry(0, 0, 400, 40);
        QTest::mouseMove(&window, QPoint(200, 250)); // not on the bar: it would stay, being read

        bar->show(QStringLiteral("Saved the table"), false);
        QVERIFY(bar->isVisible());
        QTRY_VERIFY_WITH_TIMEOUT(!bar->isVisible(), 2000);

        // With the mouse on it, a report stays until the mouse leaves.
        QTest::mouseMove(&window, QPoint(200, 20));
        bar->show(QStringLiteral("Saved the annotations"), false);
        QTest::qWait(200);
        QVERIFY(bar->isVisible());
        QTest::mouseMove(&window, QPoint(200, 250));
        QTRY_VERIFY_WITH_TIMEOUT(!bar->isVisible(), 2000);

        bar->show(QStringLiteral("Cannot read frame_000007.png"), true);
        QTest::qWait(200);
        QVERIFY(bar->isVisible());
        QCOMPARE(bar->text(), QStringLiteral("Cannot read frame_000007.png"));

        // A problem that follows a report is not taken away by the report's timer.
        bar->show(QStringLiteral("Saved the table"), false);
        bar->show(QStringLiteral("The disk is full"), true);
        QTest::qWait(200);
        QVERIFY(bar->isVisible());
    }
};

FIELDSIGHT_TEST_SUITE(TestMessageBar, Widgets)
#include "test_message_bar.moc"
