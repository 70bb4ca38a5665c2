// Colour class names and display colours (SPEC §1).
#include "support/test_suite.h"
#include "visioncore/basics/colour.h"

#include <QtTest>

using namespace fieldsight;

class TestColour : public QObject
{
    Q_OBJECT

private slots:
    void snakeNamesRoundTripForEveryId()
    {
        const char* expected[] = {"unclassified", "white",       "green",      "shadow_object",
                                  "pink",         "pink_orange", "orange",     "yellow_orange",
                                  "yellow",       "blue",        "shadow_blue"};
        for (int id = 0; id < kColourCount; ++id) {
            QCOMPARE(std::string(colourName(Colour(id))), std::string(expected[id]));
            const auto back = colourFromName(expected[id]);
            QVERIFY(back.has_value());
            QCOMPARE(int(*back), id);
        }
    }

    void acceptsOriginalDisplayNamesIgnoringCase()
    {
        QCOMPARE(colourFromName("shadow object"), std::optional(Colour::ShadowObject));
        QCOMPARE(colourFromName("pink - orange"), std::optional(Colour::PinkOrange));
        QCOMPARE(colourFromName("yellow - orange"), std::optional(Colour::YellowOrange));
        QCOMPARE(colourFromName("shadow blue"), std::optional(Colour::ShadowBlue));
        QCOMPARE(colourFromName("Shadow_Object"), std::optional(Colour::ShadowObject));
        QCOMPARE(colourFromName("ORANGE"), std::optional(Colour::Orange));
        QCOMPARE(colourFromName("  green "), std::optional(Colour::Green));
    }

    void rejectsUnknownNames()
    {
        QVERIFY(!colourFromName("purple").has_value());
        QVERIFY(!colourFromName("").has_value());
        QVERIFY(!colourFromName("pink-orange").has_value());
    }

    void displayColoursMatchTheSpecTable()
    {
        QCOMPARE(colourDisplayRgb(Colour::Unclassified), (Rgb{0, 0, 0}));
        QCOMPARE(colourDisplayRgb(Colour::White), (Rgb{255, 255, 255}));
        QCOMPARE(colourDisplayRgb(Colour::Green), (Rgb{0, 255, 0}));
        QCOMPARE(colourDisplayRgb(Colour::ShadowObject), (Rgb{168, 168, 168}));
        QCOMPARE(colourDisplayRgb(Colour::Pink), (Rgb{255, 20, 127}));
        QCOMPARE(colourDisplayRgb(Colour::PinkOrange), (Rgb{255, 128, 128}));
        QCOMPARE(colourDisplayRgb(Colour::Orange), (Rgb{255, 165, 0}));
        QCOMPARE(colourDisplayRgb(Colour::YellowOrange), (Rgb{238, 219, 83}));
        QCOMPARE(colourDisplayRgb(Colour::Yellow), (Rgb{255, 255, 0}));
        QCOMPARE(colourDisplayRgb(Colour::Blue), (Rgb{0, 0, 255}));
        QCOMPARE(colourDisplayRgb(Colour::ShadowBlue), (Rgb{25, 25, 112}));
    }
};

FIELDSIGHT_TEST_SUITE(TestColour, None)

#include "test_colour.moc"
