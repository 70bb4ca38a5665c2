// The overlay painter and image adapters: which pixels a debug drawing colours, at zoom 1 and
// above.
#include "support/test_suite.h"
#include "ui/adapters/image_adapter.h"
#include "ui/adapters/overlay_painter.h"

#include <QPainter>
#include <QtTest>

#include <opencv2/core.hpp>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <numbers>
#include <set>
#include <utility>

using namespace fieldsight;
using namespace fieldsight::ui;

namespace {

using PixelSet = std::set<std::pair<int, int>>; // (x, y) in device px

constexpr Rgb kInk{255, 0, 255};   // not in the black test frame, so every such pixel was drawn
constexpr Rgb kOther{0, 200, 255}; // a second layer's colour
constexpr int kSide = 40;          // test frames are kSide x kSide image px

cv::Mat uniformFrame(int width, int height, uchar y, uchar cb, uchar cr)
{
    return cv::Mat(height, width, CV_8UC3, cv::Scalar(y, cb, cr));
}

/// Y 0, Cb = Cr = 128 is RGB (0, 0, 0).
cv::Mat blackFrame()
{
    return uniformFrame(kSide, kSide, 0, 128, 128);
}

QRgb rgbOf(Rgb c)
{
    return qRgb(c.r, c.g, c.b);
}

bool hasColour(const QImage& image, int x, int y, Rgb c)
{
    return image.valid(x, y) && (image.pixel(x, y) & 0xffffff) == (rgbOf(c) & 0xffffff);
}

PixelSet pixelsOf(const QImage& image, Rgb c)
{
    PixelSet set;
    for (int y = 0; y < image.height(); ++y) {
        for (int x = 0; x < image.width(); ++x) {
            if (hasColour(image, x, y, c))
                set.insert({x, y});
        }
    }
    return set;
}

/// `size` is the point side or circle radius (image px) for Points and Circle, and the pen width
/// (screen px) for Line, Polyline and Rect.
DebugShape shapeOf(ShapeKind kind, std::vector<PointF> points, double size, bool filled = false,
                   Rgb colour = kInk)
{
    DebugShape shape;
    shape.kind = kind;
    shape.points = std::move(points);
    const bool sized = kind == ShapeKind::Points || kind == ShapeKind::Circle;
    shape.size = sized ? size : 1;
    shape.width = sized ? 1 : size;
    shape.filled = filled;
    shape.colour = colour;
    return shape;
}

QImage renderShape(const DebugShape& shape, int scale)
{
    DebugDrawing drawing;
    drawing.layer = "test.layer";
    drawing.add(shape);
    return renderOverlay(blackFrame(), {&drawing}, scale);
}

/// Every pixel of the image block (x0..x1, y0..y1 inclusive) at `scale`, in device px.
PixelSet imageBlock(int x0, int y0, int x1, int y1, int scale)
{
    PixelSet set;
    for (int y = y0 * scale; y < (y1 + 1) * scale; ++y) {
        for (int x = x0 * scale; x < (x1 + 1) * scale; ++x)
            set.insert({x, y});
    }
    return set;
}

/// The device row (or column) of a 1 px line through an image pixel's centre, counted from the
/// pixel's first device row: the middle one, the upper of the two middle ones at even zoom.
int middle(int scale)
{
    return (scale - 1) / 2;
}

/// SPEC BT.601 full range, written out here rather than taken from the code under test.
Rgb bt601(double y, double cb, double cr)
{
    auto level = [](double v) { return uchar(std::clamp(std::lround(v), 0L, 255L)); };
    return {level(y + 1.402 * (cr - 128)), level(y - 0.344 * (cb - 128) - 0.714 * (cr - 128)),
            level(y + 1.772 * (cb - 128))};
}

bool withinOneLevel(QRgb got, Rgb want)
{
    return std::abs(qRed(got) - want.r) <= 1 && std::abs(qGreen(got) - want.g) <= 1 &&
           std::abs(qBlue(got) - want.b) <= 1;
}

QString describe(const PixelSet& set)
{
    QStringList parts;
    for (const auto& [x, y] : set)
        parts << QStringLiteral("(%1,%2)").arg(x).arg(y);
    return parts.join(' ');
}

/// The pixels that differ, empty when none do; a failure then shows where the painter went wrong.
QString pixelDifference(const PixelSet& got, const PixelSet& want)
{
    PixelSet extra, missing;
    std::set_difference(got.begin(), got.end(), want.begin(), want.end(),
                        std::inserter(extra, extra.end()));
    std::set_difference(want.begin(), want.end(), got.begin(), got.end(),
                        std::inserter(missing, missing.end()));
    if (extra.empty() && missing.empty())
        return {};
    return QStringLiteral("extra: %1\nmissing: %2").arg(describe(extra), describe(missing));
}

} // namespace

class TestOverlayPainter : public QObject
{
    Q_OBJECT

private slots:
    void ycbcrToQImageIsAnOwnedRgb888Copy()
    {
        cv::Mat frame = uniformFrame(5, 3, 128, 128, 128);
        const QImage image = ycbcrToQImage(frame);
        QCOMPARE(image.format(), QImage::Format_RGB888);
        QCOMPARE(image.size(), QSize(5, 3));
        frame.setTo(cv::Scalar(0, 128, 128)); // must not reach the QImage
        for (int y = 0; y < 3; ++y) {
            for (int x = 0; x < 5; ++x)
                QCOMPARE(image.pixel(x, y), qRgb(128, 128, 128));
        }
    }

    void bgrToQImageSwapsBlueAndRed()
    {
        // An odd width makes QImage pad its rows, which the conversion must respect.
        const cv::Mat bgr(2, 3, CV_8UC3, cv::Scalar(10, 20, 30));
        const QImage image = bgrToQImage(bgr);
        QCOMPARE(image.format(), QImage::Format_RGB888);
        for (int y = 0; y < 2; ++y) {
            for (int x = 0; x < 3; ++x)
                QCOMPARE(image.pixel(x, y), qRgb(30, 20, 10));
        }
    }

    void rejectsImagesThatAreNotThreeBytesPerPixel()
    {
        QVERIFY(ycbcrToQImage(cv::Mat()).isNull());
        QVERIFY(ycbcrToQImage(cv::Mat(4, 4, CV_8UC1, cv::Scalar(0))).isNull());
        QVERIFY(bgrToQImage(cv::Mat(4, 4, CV_8UC4, cv::Scalar(0))).isNull());
        QVERIFY(ycbcrToZoomedQImage(cv::Mat(4, 4, CV_16UC3, cv::Scalar(0)), 2).isNull());
        QVERIFY(renderOverlay(cv::Mat(), {}, 2).isNull());
    }

    void toQColorKeepsTheChannels() { QCOMPARE(toQColor(Rgb{1, 2, 3}), QColor(1, 2, 3)); }

    void backgroundIsBt601FullRange()
    {
        // Left half grey, right half a saturated colour whose blue channel clips at 0.
        cv::Mat frame = uniformFrame(4, 2, 128, 128, 128);
        frame(cv::Rect(2, 0, 2, 2)).setTo(cv::Scalar(100, 60, 200));
        const Rgb saturated = bt601(100, 60, 200);
        QCOMPARE(int(saturated.b), 0);
        QVERIFY(saturated.r > 190);

        const QImage image = renderOverlay(frame, {}, 1);
        for (int y = 0; y < 2; ++y) {
            QVERIFY(withinOneLevel(image.pixel(0, y), Rgb{128, 128, 128}));
            QVERIFY(withinOneLevel(image.pixel(1, y), Rgb{128, 128, 128}));
            QVERIFY2(withinOneLevel(image.pixel(3, y), saturated),
                     qPrintable(QColor(image.pixel(3, y)).name()));
        }
    }

    void backgroundIsScaledInBlocks_data()
    {
        QTest::addColumn<int>("scale");
        QTest::newRow("1") << 1;
        QTest::newRow("2") << 2;
        QTest::newRow("3") << 3;
        QTest::newRow("5") << 5;
    }

    void backgroundIsScaledInBlocks()
    {
        QFETCH(int, scale);
        // Every pixel differs from its neighbours, so a block taken from the wrong source pixel
        // shows. The size is a real frame's, where floating-point source mapping drifts.
        cv::Mat frame(240, 320, CV_8UC3);
        for (int y = 0; y < frame.rows; ++y) {
            for (int x = 0; x < frame.cols; ++x)
                frame.at<cv::Vec3b>(y, x) = cv::Vec3b(uchar(x * 7 + y * 13), uchar(x), uchar(y));
        }
        const QImage source = ycbcrToQImage(frame);
        const QImage image = renderOverlay(frame, {}, scale);
        QCOMPARE(image.size(), QSize(320 * scale, 240 * scale));
        QCOMPARE(image.format(), QImage::Format_RGB32);
        for (int y = 0; y < image.height(); ++y) {
            for (int x = 0; x < image.width(); ++x) {
                if (image.pixel(x, y) != source.pixel(x / scale, y / scale)) {
                    QFAIL(qPrintable(QStringLiteral("device pixel (%1,%2) is not image pixel "
                                                    "(%3,%4)")
                                         .arg(x)
                                         .arg(y)
                                         .arg(x / scale)
                                         .arg(y / scale)));
                }
            }
        }
    }

    void scaleBelowOneRendersAtImageSize()
    {
        DebugDrawing drawing;
        drawing.add(shapeOf(ShapeKind::Points, {{3, 4}}, 1));
        const QImage image = renderOverlay(blackFrame(), {&drawing}, 0);
        QCOMPARE(image.size(), QSize(kSide, kSide));
        const QString difference = pixelDifference(pixelsOf(image, kInk), {{3, 4}});
        QVERIFY2(difference.isEmpty(), qPrintable(difference));
    }

    void circleOutlineLandsOnItsPixels_data()
    {
        QTest::addColumn<int>("scale");
        QTest::newRow("scale 1") << 1;
        QTest::newRow("scale 3") << 3;
    }

    void circleOutlineLandsOnItsPixels()
    {
        QFETCH(int, scale);
        const double cx = 19, cy = 17, radius = 9;
        const double pen = scale == 1 ? 1 : 2;
        DebugShape circle = shapeOf(ShapeKind::Circle, {{cx, cy}}, radius);
        circle.width = pen;
        const QImage image = renderShape(circle, scale);
        const PixelSet ink = pixelsOf(image, kInk);
        QVERIFY(!ink.empty());

        // In device px: the centre of image pixel (cx, cy) and the radius.
        const double dcx = (cx + 0.5) * scale, dcy = (cy + 0.5) * scale, dr = radius * scale;
        // Every inked pixel is on the ring (its centre within half the pen and a pixel of it).
        for (const auto& [x, y] : ink) {
            const double d = std::hypot(x + 0.5 - dcx, y + 0.5 - dcy);
            QVERIFY2(std::abs(d - dr) <= pen / 2 + 1,
                     qPrintable(QStringLiteral("(%1,%2) is %3 px from the centre, radius %4")
                                    .arg(x)
                                    .arg(y)
                                    .arg(d)
                                    .arg(dr)));
        }
        // The ring is closed: every 5 degrees the ideal outline has an inked pixel next to it.
        for (int degrees = 0; degrees < 360; degrees += 5) {
            const double a = degrees * std::numbers::pi / 180;
            const int x = int(std::floor(dcx + dr * std::cos(a)));
            const int y = int(std::floor(dcy + dr * std::sin(a)));
            bool near = false;
            for (int dy = -1; dy <= 1; ++dy) {
                for (int dx = -1; dx <= 1; ++dx)
                    near = near || ink.count({x + dx, y + dy}) != 0;
            }
            QVERIFY2(near, qPrintable(QStringLiteral("nothing near %1 degrees").arg(degrees)));
        }
        // The outline's extremes on the axes are exactly the pixels `radius` away.
        const int ix = int(cx), iy = int(cy), r = int(radius);
        QVERIFY(
            hasColour(image, (ix + r) * scale + middle(scale), iy * scale + middle(scale), kInk));
        QVERIFY(
            hasColour(image, (ix - r) * scale + middle(scale), iy * scale + middle(scale), kInk));
        QVERIFY(
            hasColour(image, ix * scale + middle(scale), (iy + r) * scale + middle(scale), kInk));
        QVERIFY(
            hasColour(image, ix * scale + middle(scale), (iy - r) * scale + middle(scale), kInk));
        // Neither the centre, the inside nor the far outside is painted.
        const PixelSet centre = imageBlock(ix - 2, iy - 2, ix + 2, iy + 2, scale);
        for (const auto& p : centre)
            QVERIFY(!ink.count(p));
        QVERIFY(!hasColour(image, 0, 0, kInk));
        QVERIFY(!hasColour(image, (ix + r + 3) * scale, iy * scale, kInk));
        // The pen is cosmetic: `width` device px at any scale (2 at scale 3, not 6).
        int across = 0;
        const int row = int(dcy);
        for (int x = int(dcx); x < image.width(); ++x)
            across += hasColour(image, x, row, kInk) ? 1 : 0;
        QCOMPARE(across, int(pen));
    }

    void filledCircleCoversItsInside()
    {
        const QImage image = renderShape(shapeOf(ShapeKind::Circle, {{20, 20}}, 6, true), 2);
        const PixelSet ink = pixelsOf(image, kInk);
        for (const auto& p : imageBlock(16, 16, 24, 24, 2))
            QVERIFY(ink.count(p));
        QVERIFY(!hasColour(image, 2 * 27, 2 * 20, kInk));
    }

    void polylineColoursEachSegmentAndNothingElse()
    {
        // A horizontal, a vertical and a 45-degree segment, so the expected pixels are exact.
        const QImage image =
            renderShape(shapeOf(ShapeKind::Polyline, {{2, 3}, {20, 3}, {20, 14}, {9, 25}}, 1), 1);
        PixelSet want;
        for (int x = 2; x <= 20; ++x)
            want.insert({x, 3});
        for (int y = 3; y <= 14; ++y)
            want.insert({20, y});
        for (int k = 0; k <= 11; ++k)
            want.insert({20 - k, 14 + k});
        const QString difference = pixelDifference(pixelsOf(image, kInk), want);
        QVERIFY2(difference.isEmpty(), qPrintable(difference));
    }

    void polylineCornersStayOnImagePixelsWhenZoomed_data()
    {
        QTest::addColumn<int>("scale");
        QTest::newRow("scale 3") << 3;
        QTest::newRow("scale 4") << 4;
    }

    void polylineCornersStayOnImagePixelsWhenZoomed()
    {
        QFETCH(int, scale);
        const QImage image =
            renderShape(shapeOf(ShapeKind::Polyline, {{2, 3}, {20, 3}, {20, 14}}, 1), scale);
        PixelSet want;
        const int mid = middle(scale);
        for (int x = 2 * scale + mid; x <= 20 * scale + mid; ++x)
            want.insert({x, 3 * scale + mid});
        for (int y = 3 * scale + mid; y <= 14 * scale + mid; ++y)
            want.insert({20 * scale + mid, y});
        const QString difference = pixelDifference(pixelsOf(image, kInk), want);
        QVERIFY2(difference.isEmpty(), qPrintable(difference));
    }

    void lineWidthIsInDevicePixelsAtAnyZoom_data()
    {
        QTest::addColumn<double>("size");
        QTest::addColumn<int>("scale");
        QTest::newRow("size 1, scale 1") << 1.0 << 1;
        QTest::newRow("size 1, scale 4") << 1.0 << 4;
        QTest::newRow("size 3, scale 1") << 3.0 << 1;
        QTest::newRow("size 3, scale 4") << 3.0 << 4;
        QTest::newRow("size 0 draws 1 px") << 0.0 << 4;
    }

    void lineWidthIsInDevicePixelsAtAnyZoom()
    {
        QFETCH(double, size);
        QFETCH(int, scale);
        const QImage image =
            renderShape(shapeOf(ShapeKind::Line, {{5, 10}, {30, 10}}, size), scale);
        // The middle of the line, across it: exactly max(1, size) inked rows.
        const int x = 17 * scale;
        int rows = 0;
        for (int y = 0; y < image.height(); ++y)
            rows += hasColour(image, x, y, kInk) ? 1 : 0;
        QCOMPARE(rows, int(std::max(1.0, size)));
        QVERIFY(hasColour(image, x, 10 * scale + middle(scale), kInk));
    }

    void aOnePixelLineCoversItsPixel_data()
    {
        QTest::addColumn<int>("scale");
        QTest::newRow("scale 1") << 1;
        QTest::newRow("scale 4") << 4;
    }

    void aOnePixelLineCoversItsPixel()
    {
        // A colour segment one pixel long is a line from a pixel to itself: it must show.
        QFETCH(int, scale);
        const QImage image = renderShape(shapeOf(ShapeKind::Line, {{7, 9}, {7, 9}}, 1), scale);
        const int mid = middle(scale);
        const QString difference =
            pixelDifference(pixelsOf(image, kInk), {{7 * scale + mid, 9 * scale + mid}});
        QVERIFY2(difference.isEmpty(), qPrintable(difference));
    }

    void axisLinesCoverTheirEndPixelsAtAnyZoom_data()
    {
        QTest::addColumn<int>("scale");
        QTest::newRow("scale 1") << 1;
        QTest::newRow("scale 2") << 2;
        QTest::newRow("scale 3") << 3;
    }

    void axisLinesCoverTheirEndPixelsAtAnyZoom()
    {
        // Given right to left and bottom to top: the direction must not matter.
        QFETCH(int, scale);
        DebugDrawing drawing;
        drawing.add(shapeOf(ShapeKind::Line, {{30, 4}, {6, 4}}, 1));
        drawing.add(shapeOf(ShapeKind::Line, {{12, 33}, {12, 8}}, 1));
        const QImage image = renderOverlay(blackFrame(), {&drawing}, scale);
        const int mid = middle(scale);
        PixelSet want;
        for (int x = 6 * scale + mid; x <= 30 * scale + mid; ++x)
            want.insert({x, 4 * scale + mid});
        for (int y = 8 * scale + mid; y <= 33 * scale + mid; ++y)
            want.insert({12 * scale + mid, y});
        const QString difference = pixelDifference(pixelsOf(image, kInk), want);
        QVERIFY2(difference.isEmpty(), qPrintable(difference));
    }

    void pointsCoverExactlyTheirBlocks_data()
    {
        QTest::addColumn<double>("size");
        QTest::addColumn<int>("scale");
        QTest::newRow("size 1, scale 1") << 1.0 << 1;
        QTest::newRow("size 1, scale 3") << 1.0 << 3;
        QTest::newRow("size 3, scale 1") << 3.0 << 1;
        QTest::newRow("size 3, scale 2") << 3.0 << 2;
    }

    void pointsCoverExactlyTheirBlocks()
    {
        QFETCH(double, size);
        QFETCH(int, scale);
        const std::vector<PointF> points = {{5, 5}, {12, 30}, {33, 8}, {0, 39}};
        const QImage image = renderShape(shapeOf(ShapeKind::Points, points, size), scale);
        const int half = int(size) / 2;
        PixelSet want;
        for (const PointF& p : points) {
            const int x = int(p.x), y = int(p.y);
            for (const auto& [bx, by] : imageBlock(x - half, y - half, x + half, y + half, scale)) {
                if (bx >= 0 && by >= 0 && bx < image.width() && by < image.height())
                    want.insert({bx, by});
            }
        }
        const QString difference = pixelDifference(pixelsOf(image, kInk), want);
        QVERIFY2(difference.isEmpty(), qPrintable(difference));
    }

    void fractionalPointsRoundToTheNearestPixel()
    {
        const QImage image =
            renderShape(shapeOf(ShapeKind::Points, {{10.3, 20.2}, {10.7, 25.8}}, 1), 1);
        const QString difference = pixelDifference(pixelsOf(image, kInk), {{10, 20}, {11, 26}});
        QVERIFY2(difference.isEmpty(), qPrintable(difference));
    }

    void filledRectCoversBothCornersInclusive()
    {
        const int scale = 2;
        // Corners given bottom-right first: the order must not matter.
        const QImage image =
            renderShape(shapeOf(ShapeKind::Rect, {{20, 15}, {4, 6}}, 1, true), scale);
        const QString difference =
            pixelDifference(pixelsOf(image, kInk), imageBlock(4, 6, 20, 15, scale));
        QVERIFY2(difference.isEmpty(), qPrintable(difference));
    }

    void rectOutlineRunsThroughCornerPixels()
    {
        const QImage image = renderShape(shapeOf(ShapeKind::Rect, {{4, 6}, {20, 15}}, 1), 1);
        PixelSet want;
        for (int x = 4; x <= 20; ++x) {
            want.insert({x, 6});
            want.insert({x, 15});
        }
        for (int y = 6; y <= 15; ++y) {
            want.insert({4, y});
            want.insert({20, y});
        }
        const QString difference = pixelDifference(pixelsOf(image, kInk), want);
        QVERIFY2(difference.isEmpty(), qPrintable(difference));
    }

    void laterDrawingCoversEarlierOne()
    {
        DebugDrawing below, above;
        below.layer = "test.below";
        below.add(shapeOf(ShapeKind::Rect, {{5, 5}, {20, 20}}, 1, true, kInk));
        above.layer = "test.above";
        above.add(shapeOf(ShapeKind::Rect, {{15, 15}, {30, 30}}, 1, true, kOther));

        const QImage image = renderOverlay(blackFrame(), {&below, &above}, 2);
        QVERIFY(hasColour(image, 2 * 17, 2 * 17, kOther)); // the overlap
        QVERIFY(hasColour(image, 2 * 10, 2 * 10, kInk));
        QVERIFY(hasColour(image, 2 * 25, 2 * 25, kOther));

        const QImage swapped = renderOverlay(blackFrame(), {&above, &below}, 2);
        QVERIFY(hasColour(swapped, 2 * 17, 2 * 17, kInk));
    }

    void skipsNullDrawingsAndShapesWithoutEnoughPoints()
    {
        DebugDrawing drawing;
        drawing.add(shapeOf(ShapeKind::Line, {{3, 3}}, 1));
        drawing.add(shapeOf(ShapeKind::Polyline, {}, 1));
        drawing.add(shapeOf(ShapeKind::Rect, {{3, 3}}, 1, true));
        drawing.add(shapeOf(ShapeKind::Circle, {}, 4));
        const QImage image = renderOverlay(blackFrame(), {nullptr, &drawing}, 1);
        QVERIFY(pixelsOf(image, kInk).empty());
        QCOMPARE(image.pixel(3, 3), qRgb(0, 0, 0));
    }

    void paintDrawingLeavesThePainterAsItWas()
    {
        QImage image(8, 8, QImage::Format_RGB32);
        image.fill(Qt::black);
        QPainter painter(&image);
        painter.setPen(QPen(Qt::green, 5));
        painter.setBrush(Qt::red);
        DebugDrawing drawing;
        drawing.add(shapeOf(ShapeKind::Points, {{1, 1}}, 1));
        drawing.add(shapeOf(ShapeKind::Line, {{1, 2}, {6, 2}}, 2));
        paintDrawing(painter, drawing);
        QCOMPARE(painter.pen(), QPen(Qt::green, 5));
        QCOMPARE(painter.brush(), QBrush(Qt::red));
        painter.end();
        QVERIFY(hasColour(image, 1, 1, kInk));
    }
};

FIELDSIGHT_TEST_SUITE(TestOverlayPainter, None)

#include "test_overlay_painter.moc"
