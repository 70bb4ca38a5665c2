// The time to rasterise one LUT sample polygon of 200k and 2M points on a 640x480 frame, printed,
// not asserted (label bench): fillPolygon, and cv::fillPoly with cv::polylines (what
// LutVotes::addFrame used before) where that ends within a minute. Shapes: a circle (a lasso's
// many repeated points), points at random over the frame, and a zigzag whose every edge spans
// the frame's height (what made cv::fillPoly's active-edge list, sorted on every row, slowest).
#include "services/polygon_fill.h"

#include <opencv2/imgproc.hpp>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <functional>
#include <numbers>
#include <string>
#include <vector>

using namespace fieldsight;

namespace {

double seconds(const std::function<void()>& run)
{
    const auto start = std::chrono::steady_clock::now();
    run();
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

std::vector<cv::Point> shape(const std::string& name, int points)
{
    std::vector<cv::Point> polygon;
    cv::RNG rng(1);
    for (int i = 0; i < points; ++i) {
        if (name == "circle") {
            const double a = 2 * std::numbers::pi * i / points;
            polygon.emplace_back(int(std::lround(320 + 200 * std::cos(a))),
                                 int(std::lround(240 + 200 * std::sin(a))));
        } else if (name == "random") {
            polygon.emplace_back(rng.uniform(0, 640), rng.uniform(0, 480));
        } else {
            polygon.emplace_back((i / 2) % 640, i % 2 ? 479 : 0);
        }
    }
    return polygon;
}

} // namespace

int main()
{
    std::printf("%-8s %9s %14s %22s\n", "shape", "points", "fillPolygon s", "cv::fillPoly+lines s");
    for (const char* name : {"circle", "random", "zigzag"}) {
        for (const int points : {200000, 2000000}) {
            const std::vector<cv::Point> polygon = shape(name, points);
            cv::Mat ours = cv::Mat1b(480, 640, std::uint8_t(0));
            const double t_ours = seconds([&] { fillPolygon(ours, polygon, 7); });
            // cv::fillPoly took 183 s on the 200k zigzag here (50 s on a 320x240 frame) and
            // over 10 minutes on 200k random points (measured when it was replaced); only the
            // circle is timed again.
            std::string t_cv = "(minutes or more)";
            if (std::string(name) == "circle") {
                cv::Mat1b theirs(480, 640, std::uint8_t(0));
                const std::vector<std::vector<cv::Point>> polygons{polygon};
                char text[32];
                std::snprintf(text, sizeof text, "%.3f", seconds([&] {
                                  cv::fillPoly(theirs, polygons, cv::Scalar(7));
                                  cv::polylines(theirs, polygons, true, cv::Scalar(7));
                              }));
                t_cv = text;
            }
            std::printf("%-8s %9d %14.3f %22s\n", name, points, t_ours, t_cv.c_str());
        }
    }
    return 0;
}
