// A one-line label (the scores' change over the timeline) that ends in "…" where it is cut and
// keeps its whole text.
#include "support/test_suite.h"
#include "ui/widgets/elided_label.h"

#include <QtTest>

using namespace fieldsight::ui;

class TestElidedLabel : public QObject
{
    Q_OBJECT

private slots:
    void aLineLongerThanTheLabelEndsInAnEllipsisAndKeepsItsText()
    {
        QWidget window;
        window.resize(300, 60);
        auto* label = new ElidedLabel(&window);
        label->setGeometry(0, 0, 300, 30);
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        const QString line = QStringLiteral(
            "Scores after the last change: ball recall 0.00 → 1.00, goalpost recall 0.00 → 1.00, "
            "obstacle precision 0.00 → 0.12, field line recall 0.00 → 0.80");
        label->setText(line);
        QCOMPARE(label->text(), line);
        QVERIFY2(label->shownText().endsWith(QChar(0x2026)), qPrintable(label->shownText()));
        QVERIFY(label->shownText().size() < line.size());
        QVERIFY(line.startsWith(label->shownText().chopped(1)));

        // It draws the line itself: some of its pixels are the text's, not the background's.
        const QImage grab = label->grab().toImage();
        const QColor background = grab.pixelColor(0, 0);
        int inked = 0;
        for (int y = 0; y < grab.height(); ++y)
            for (int x = 0; x < grab.width(); ++x)
                inked += grab.pixelColor(x, y) != background;
        QVERIFY(inked > 50);

        // Wide enough, the whole line.
        window.resize(3000, 60);
        label->setGeometry(0, 0, 3000, 30);
        QCOMPARE(label->shownText(), line);
    }
};

FIELDSIGHT_TEST_SUITE(TestElidedLabel, Widgets)
#include "test_elided_label.moc"
