// The rasterising of LUT sample polygons (visioncore/src/services/polygon_fill): the same pixels
// as cv::fillPoly with cv::polylines, which it replaced (a sample polygon of 200k points took
// 50 s to many minutes), and the area a polygon stands for. Its speed: bench_polygon_fill.
#include "support/test_suite.h"
#include "services/polygon_fill.h"

#include <opencv2/imgproc.hpp>

#include <QtTest>

#include <cmath>
#include <numbers>
#include <vector>

using namespace fieldsight;

namespace {

/// What LutVotes::addFrame drew before: the inside, then the outline over it.
cv::Mat1b openCvFill(cv::Size size, const std::vector<cv::Point>& polygon)
{
    cv::Mat1b image(size, std::uint8_t(0));
    const std::vector<std::vector<cv::Point>> polygons{polygon};
    cv::fillPoly(image, polygons, cv::Scalar(7));
    cv::polylines(image, polygons, true, cv::Scalar(7));
    return image;
}

cv::Mat1b ourFill(cv::Size size, const std::vector<cv::Point>& polygon)
{
    cv::Mat image = cv::Mat1b(size, std::uint8_t(0));
    fillPolygon(image, polygon, 7);
    return image;
}

int differences(const cv::Mat1b& a, const cv::Mat1b& b)
{
    return cv::countNonZero(a != b);
}

std::vector<cv::Point> circle(int points, double cx, double cy, double radius)
{
    std::vector<cv::Point> polygon;
    for (int i = 0; i < points; ++i) {
        const double a = 2 * std::numbers::pi * i / points;
        polygon.emplace_back(int(std::lround(cx + radius * std::cos(a))),
                             int(std::lround(cy + radius * std::sin(a))));
    }
    return polygon;
}

} // namespace

class TestPolygonFill : public QObject
{
    Q_OBJECT

private slots:
    void randomPolygonsFillAsOpenCvFilledThem()
    {
        // Self-crossing polygons of 1 to 300 points, inside the image, across its border, and
        // mostly far outside it.
        cv::RNG rng(21);
        int compared = 0;
        for (const int spread : {1, 3, 41}) {
            for (int trial = 0; trial < 2000; ++trial) {
                const int w = rng.uniform(1, 60), h = rng.uniform(1, 60);
                const int n = rng.uniform(1, trial % 3 == 0 ? 300 : 9);
                std::vector<cv::Point> polygon;
                for (int i = 0; i < n; ++i)
                    polygon.emplace_back(rng.uniform(0, spread * w) - (spread - 1) / 2 * w,
                                         rng.uniform(0, spread * h) - (spread - 1) / 2 * h);
                const cv::Size size(w, h);
                QVERIFY2(differences(ourFill(size, polygon), openCvFill(size, polygon)) == 0,
                         qPrintable(QString("spread %1, trial %2, %3 points in %4x%5")
                                        .arg(spread)
                                        .arg(trial)
                                        .arg(n)
                                        .arg(w)
                                        .arg(h)));
                ++compared;
            }
        }
        QCOMPARE(compared, 6000);
    }

    void aPolygonOf200kPointsFillsAsOpenCvFilledIt()
    {
        // A circle drawn with 200,000 points (many repeated, as a lasso gives them) and a star
        // whose 200,000 points jump about its rim, on a small frame.
        const cv::Size size(64, 48);
        const std::vector<cv::Point> round = circle(200000, 31.5, 23.5, 20);
        const cv::Mat1b expected = openCvFill(size, round);
        QCOMPARE(differences(ourFill(size, round), expected), 0);
        QVERIFY(cv::countNonZero(expected) > 1200); // about pi 20^2, and not an empty frame
        std::vector<cv::Point> star;
        cv::RNG rng(5);
        for (int i = 0; i < 200000; ++i) {
            const double a = 2 * std::numbers::pi * i / 200000, r = rng.uniform(14.0, 20.0);
            star.emplace_back(int(std::lround(31.5 + r * std::cos(a))),
                              int(std::lround(23.5 + r * std::sin(a))));
        }
        QCOMPARE(differences(ourFill(size, star), openCvFill(size, star)), 0);
    }

    void aCircleOfManyPointsCoversItsArea()
    {
        // 10,000 points on a circle of radius 150: the pixels set are the circle's area within
        // 1% (its outline, drawn too, adds about a quarter pixel along the rim).
        const double r = 150;
        const cv::Mat1b filled = ourFill({400, 400}, circle(10000, 200, 200, r));
        const double area = std::numbers::pi * r * r;
        const int set = cv::countNonZero(filled);
        qInfo("%d pixels set for an area of %.0f (%.2f%%)", set, area, 100 * (set - area) / area);
        QVERIFY(std::abs(set - area) < 0.01 * area);
        // Half of it off the frame: the half inside, within 1% again.
        const int half = cv::countNonZero(ourFill({400, 200}, circle(10000, 200, 200, r)));
        QVERIFY(std::abs(half - area / 2) < 0.01 * area / 2);
    }
};

FIELDSIGHT_TEST_SUITE(TestPolygonFill, None)

#include "test_polygon_fill.moc"
