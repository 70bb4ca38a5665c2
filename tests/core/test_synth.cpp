// The scene generator: determinism, camera geometry, ground truth against the rendered pixels,
// the ideal LUT, and the files it writes.
#include "support/child_process.h"
#include "support/test_suite.h"
#include "support/test_images.h"
#include "synth/camera_model.h"
#include "synth/ground_truth.h"
#include "synth/ideal_lut.h"
#include "synth/renderer.h"
#include "synth/scenario_script.h"
#include "synth/stream_frame.h"
#include "synth/synth.h"

#include "visioncore/percepts/obstacle.h"

#include <QTemporaryDir>
#include <QtTest>

#include <nlohmann/json.hpp>
#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <memory>
#include <string>
#include <vector>

using namespace fieldsight;
using namespace fieldsight::synth;
namespace fs = std::filesystem;

namespace {

constexpr int kFrames = 8;

std::vector<char> readBytes(const fs::path& path)
{
    const std::string bytes = test::readAll(path.string());
    return {bytes.begin(), bytes.end()};
}

nlohmann::json readJson(const fs::path& path)
{
    std::ifstream in(path);
    return nlohmann::json::parse(in);
}

/// Every file of a folder, by name.
std::map<std::string, std::vector<char>> folderBytes(const fs::path& dir)
{
    std::map<std::string, std::vector<char>> files;
    for (const auto& entry : fs::directory_iterator(dir))
        files[entry.path().filename().string()] = readBytes(entry.path());
    return files;
}

/// The first file one folder has and the other lacks or holds other bytes in; empty: the same.
std::string firstDifference(const std::map<std::string, std::vector<char>>& a,
                            const std::map<std::string, std::vector<char>>& b)
{
    for (const auto& [name, bytes] : a)
        if (!b.count(name) || b.at(name) != bytes)
            return name;
    for (const auto& [name, bytes] : b)
        if (!a.count(name))
            return name;
    return {};
}

/// Lab 2 of `frames` frames from `seed`, to be written into `out`.
fieldsight::synth::SynthOptions lab2Into(const std::string& out, int frames, std::uint64_t seed)
{
    fieldsight::synth::SynthOptions options;
    options.scenario = fieldsight::synth::Scenario::Lab2;
    options.frames = frames;
    options.seed = seed;
    options.out_dir = out;
    return options;
}

bool orangeish(const cv::Vec3b& bgr)
{
    return bgr[2] > 120 && bgr[2] > bgr[1] + 50 && bgr[1] >= bgr[0];
}

double polylineY(const nlohmann::json& polyline, double x)
{
    for (std::size_t i = 1; i < polyline.size(); ++i) {
        const double x0 = polyline[i - 1][0];
        const double x1 = polyline[i][0];
        if (x >= x0 && x <= x1) {
            const double y0 = polyline[i - 1][1];
            const double y1 = polyline[i][1];
            return x1 > x0 ? y0 + (y1 - y0) * (x - x0) / (x1 - x0) : y0;
        }
    }
    return polyline.back()[1];
}

} // namespace

class TestSynth : public QObject
{
    Q_OBJECT

private:
    /// A generated stream per scenario (seed 1, kFrames frames, with image.strm), made once.
    const fs::path& stream(Scenario scenario)
    {
        auto& dir = m_streams[scenario];
        if (!dir) {
            dir = std::make_unique<QTemporaryDir>();
            SynthOptions options;
            options.scenario = scenario;
            options.frames = kFrames;
            options.seed = 1;
            options.out_dir = dir->path().toStdString();
            options.write_strm = true;
            const Status status = generateStream(options);
            if (!status)
                qFatal("generateStream failed: %s", status.error().message.c_str());
            m_paths[scenario] = options.out_dir;
        }
        return m_paths[scenario];
    }

    std::map<Scenario, std::unique_ptr<QTemporaryDir>> m_streams;
    std::map<Scenario, fs::path> m_paths;

private slots:
    void scenarioNamesRoundTrip()
    {
        const std::vector<std::string> names = scenarioNames();
        QCOMPARE(names.size(), std::size_t(6));
        for (const std::string& name : names) {
            const auto scenario = scenarioFromName(name);
            QVERIFY(scenario.ok());
            QCOMPARE(scenarioName(scenario.value()), name);
        }
        QCOMPARE(paperFrameCount(Scenario::Lab1), 5090);
        QCOMPARE(paperFrameCount(Scenario::RC2012), 2640);
        const auto bad = scenarioFromName("lab3");
        QVERIFY(!bad.ok());
        QVERIFY(bad.error().message.find("lab3") != std::string::npos);
    }

    void rejectsBadOptions()
    {
        SynthOptions options;
        QVERIFY(!generateStream(options).ok()); // no folder
        QTemporaryDir dir;
        options.out_dir = (fs::path(dir.path().toStdString()) / "out").string();
        options.frames = 0;
        const Status status = generateStream(options);
        QVERIFY(!status.ok());
        QVERIFY(status.error().message.find(options.out_dir) != std::string::npos);
    }

    void ballOnOpticalAxisProjectsToImageCentre()
    {
        CameraModel camera(320, 240);
        QVERIFY(std::abs(camera.fx() - 262.1) < 0.05); // design note §2.9
        CameraPose pose;
        pose.position = Eigen::Vector3d(0.3, -0.2, 0.45);
        pose.yaw = 0.7;
        pose.pitch = 0.35;
        pose.roll = 0.1;
        camera.setPose(pose);
        const Eigen::Vector3d forward = camera.directionToWorld(Eigen::Vector3d(0, 0, 1));
        const Eigen::Vector3d right = camera.directionToWorld(Eigen::Vector3d(1, 0, 0));
        const double d = 1.7;
        const Eigen::Vector3d ball = pose.position + d * forward;
        const auto centre = camera.project(ball);
        QVERIFY(centre.has_value());
        QVERIFY(std::abs(centre->x - 160.0) < 1e-9);
        QVERIFY(std::abs(centre->y - 120.0) < 1e-9);
        QVERIFY(std::abs(camera.apparentRadius(ball, 0.07) - camera.fx() * 0.07 / d) < 1e-12);
        // The annotated ball: the outline's centroid and equal-area radius.
        const auto image = ballImage(camera, ball, 0.07);
        QVERIFY(image.has_value());
        QVERIFY(std::abs(image->centre.x - 160.0) < 1e-6);
        QVERIFY(std::abs(image->centre.y - 120.0) < 1e-6);
        const double exact = std::sqrt(camera.fx() * camera.fy()) * std::tan(std::asin(0.07 / d));
        QVERIFY(std::abs(image->radius - exact) < 1e-3 * exact);
        QVERIFY(std::abs(image->radius - camera.fx() * 0.07 / d) < 0.01 * image->radius);
        // Off the axis the outline stretches outwards and its centre moves out a little.
        const Eigen::Vector3d aside = pose.position + 1.2 * forward + 0.6 * right;
        const auto stretched = ballImage(camera, aside, 0.07);
        QVERIFY(stretched->radius > camera.apparentRadius(aside, 0.07));
        QVERIFY(stretched->centre.x > camera.project(aside)->x);
        const auto beside = camera.project(ball + 0.1 * right);
        QVERIFY(std::abs(beside->x - (160.0 + camera.fx() * 0.1 / d)) < 1e-9);
        QVERIFY(std::abs(beside->y - 120.0) < 1e-9);
        QVERIFY(!camera.project(pose.position - forward).has_value()); // behind the camera
        // The ray through the image centre is the optical axis.
        QVERIFY((camera.rayDirection(160, 120) - forward).norm() < 1e-12);
    }

    void horizonIsWhereGroundAtInfinityProjects()
    {
        CameraModel camera(320, 240);
        CameraPose pose;
        pose.pitch = 0.3;
        camera.setPose(pose);
        const double expected = 120.0 - camera.fy() * std::tan(0.3);
        QVERIFY(std::abs(camera.horizon().y_left - expected) < 1e-9);
        QVERIFY(std::abs(camera.horizon().y_right - expected) < 1e-9);

        pose.yaw = 1.1;
        pose.roll = 0.08;
        pose.position = Eigen::Vector3d(1, 1, 0.46);
        camera.setPose(pose);
        const Horizon h = camera.horizon();
        QVERIFY(h.y_left > h.y_right + 5); // positive roll lowers the image's right side
        for (const double a : {-0.3, 0.0, 0.4}) {
            const Eigen::Vector3d far =
                pose.position + 1e7 * Eigen::Vector3d(std::cos(1.1 + a), std::sin(1.1 + a), 0);
            const auto p = camera.project(far);
            QVERIFY(p.has_value());
            QVERIFY(std::abs(p->y - h.yAt(p->x, 320)) < 1e-3);
        }
    }

    void sameSeedGivesIdenticalBytes()
    {
        const fs::path& first = stream(Scenario::Lab2);
        QTemporaryDir dir;
        SynthOptions options = lab2Into(dir.path().toStdString(), kFrames, 1);
        options.write_strm = true;
        QVERIFY(generateStream(options).ok());
        const auto a = folderBytes(first);
        const auto b = folderBytes(options.out_dir);
        // frames, json x 2, lut, strm, synth-output.json
        QCOMPARE(a.size(), std::size_t(kFrames + 5));
        QCOMPARE(b.size(), a.size());
        const std::string differs = firstDifference(a, b);
        QVERIFY2(differs.empty(), differs.c_str());
    }

    void theBundledStreamIsWhatSynthWritesNow()
    {
        // The sample streams' README promises the same options give the same bytes.
        QTemporaryDir dir;
        QVERIFY(generateStream(lab2Into(dir.path().toStdString(), 30, 1)).ok());
        const auto bundled = folderBytes(FIELDSIGHT_SAMPLE_STREAMS_DIR "/lab2");
        const auto now = folderBytes(dir.path().toStdString());
        QCOMPARE(now.size(), bundled.size());
        const std::string differs = firstDifference(now, bundled);
        QVERIFY2(differs.empty(), differs.c_str());
    }

    void differentSeedGivesDifferentFrames()
    {
        const fs::path& first = stream(Scenario::Lab2);
        QTemporaryDir dir;
        QVERIFY(generateStream(lab2Into(dir.path().toStdString(), 2, 2)).ok());
        const fs::path other(dir.path().toStdString());
        QVERIFY(readBytes(first / "frame_000000.png") != readBytes(other / "frame_000000.png"));
        const auto truth_a = readJson(first / "annotations.json")["frames"]["frame_000000.png"];
        const auto truth_b = readJson(other / "annotations.json")["frames"]["frame_000000.png"];
        QVERIFY(truth_a != truth_b);
    }

    void manifestAndAnnotationsMatchFrames()
    {
        const fs::path& dir = stream(Scenario::Lab1);
        const nlohmann::json manifest = readJson(dir / "stream.json");
        QCOMPARE(manifest["format"].get<std::string>(), std::string("fieldsight-stream/1"));
        QCOMPARE(manifest["pixel_format"].get<std::string>(), std::string("rgb"));
        QCOMPARE(manifest["lut"].get<std::string>(), std::string("default.lut"));
        QCOMPARE(manifest["camera"]["fov_deg"][0].get<double>(), 62.8);
        QCOMPARE(manifest["camera"]["fov_deg"][1].get<double>(), 48.8);
        const nlohmann::json& frames = manifest["frames"];
        QCOMPARE(int(frames.size()), kFrames);
        ScenarioScript script(Scenario::Lab1, 1, 320, 240);
        for (int i = 0; i < kFrames; ++i) {
            const nlohmann::json& f = frames[std::size_t(i)];
            char name[32];
            std::snprintf(name, sizeof name, "frame_%06d.png", i);
            QCOMPARE(f["file"].get<std::string>(), std::string(name));
            QVERIFY(fs::is_regular_file(dir / name));
            QVERIFY(std::abs(f["timestamp_ms"].get<double>() - i * 1000.0 / 30.0) < 0.001);
            CameraModel camera(320, 240);
            camera.setPose(script.sceneAt(i).camera);
            QVERIFY(std::abs(f["horizon"][0].get<double>() - camera.horizon().y_left) < 0.01);
            QVERIFY(std::abs(f["horizon"][1].get<double>() - camera.horizon().y_right) < 0.01);
        }
        QCOMPARE(fs::file_size(dir / "default.lut"), std::uintmax_t(128 * 128 * 128));

        const nlohmann::json truth = readJson(dir / "annotations.json");
        QCOMPARE(truth["format"].get<std::string>(), std::string("fieldsight-annotations/1"));
        QCOMPARE(int(truth["frames"].size()), kFrames);
        for (const auto& [name, frame] : truth["frames"].items()) {
            QVERIFY2(frame["done"].get<bool>(), name.c_str());
            const nlohmann::json& boundary = frame["field_boundary"];
            QVERIFY(boundary.size() >= 2);
            QCOMPARE(boundary.front()[0].get<double>(), 0.0);
            QCOMPARE(boundary.back()[0].get<double>(), 319.0);
            for (std::size_t i = 0; i < boundary.size(); ++i) {
                const double y = boundary[i][1];
                QVERIFY(y >= 0 && y <= 239);
                if (i > 0)
                    QVERIFY(boundary[i][0].get<double>() > boundary[i - 1][0].get<double>());
            }
            QVERIFY(!frame["field_lines"].empty()); // the camera always sees some of the field
        }
    }

    void cameraMovesBetweenFrames()
    {
        // Lab 2 has no sensor noise, so any difference is the camera or the scene moving.
        const fs::path& dir = stream(Scenario::Lab2);
        const cv::Mat first = fieldsight::test::imread((dir / "frame_000000.png").string());
        const cv::Mat last = fieldsight::test::imread((dir / "frame_000007.png").string());
        QCOMPARE(first.size(), last.size());
        cv::Mat diff;
        cv::absdiff(first, last, diff);
        const cv::Scalar mean = cv::mean(diff);
        QVERIFY2(mean[0] + mean[1] + mean[2] > 3.0, std::to_string(mean[0]).c_str());
        const nlohmann::json frames = readJson(dir / "stream.json")["frames"];
        QVERIFY(frames[0]["horizon"] != frames[7]["horizon"]);
    }

    void annotatedBallIsOrangeInTheImage()
    {
        const fs::path& dir = stream(Scenario::Lab2);
        const nlohmann::json truth = readJson(dir / "annotations.json");
        int with_ball = 0;
        for (const auto& [name, frame] : truth["frames"].items()) {
            if (frame["balls"].empty() || frame["balls"][0].value("concealed", false))
                continue;
            ++with_ball;
            QCOMPARE(int(frame["balls"].size()), 1);
            const cv::Mat image = fieldsight::test::imread((dir / name).string());
            QCOMPARE(image.cols, 320);
            const double x = frame["balls"][0]["x"];
            const double y = frame["balls"][0]["y"];
            const double r = frame["balls"][0]["radius"];
            QVERIFY(r >= 3);
            QVERIFY2(orangeish(image.at<cv::Vec3b>(int(std::lround(y)), int(std::lround(x)))),
                     name.c_str());
            for (const double side : {-1.5, 1.5}) {
                const int px = int(std::lround(x + side * r));
                if (px >= 0 && px < image.cols)
                    QVERIFY2(!orangeish(image.at<cv::Vec3b>(int(std::lround(y)), px)),
                             name.c_str());
            }
        }
        // Lab 2 follows the ball: it is in most frames.
        QVERIFY(with_ball >= kFrames * 3 / 4);
    }

    /// A ball in view but mostly hidden (Lab 1's first frames: behind a robot; Difficult's
    /// frames 23-25) is listed as concealed, a ball in full view is not; a concealed robot is cut
    /// by the frame's side or stands behind another one.
    void partlySeenObjectsAreListedConcealed()
    {
        int concealed_balls = 0;
        int plain_balls = 0;
        int concealed_robots = 0;
        for (const auto& [scenario, frames] :
             {std::pair{Scenario::Lab1, std::vector{0, 1, 2, 10}},
              std::pair{Scenario::Difficult, std::vector{1, 12, 23, 24, 25}}}) {
            const ScenarioScript script(scenario, 1, 320, 240);
            for (const int i : frames) {
                const StreamFrame frame = renderStreamFrame(script, i);
                const cv::Mat& labels = frame.image.labels;
                const auto& balls = frame.truth.truth.list<Ball>();
                for (std::size_t b = 0; b < balls.size(); ++b) {
                    // The share of the disc's pixels that show ball colour and nothing else.
                    int disc = 0;
                    int orange = 0;
                    const Ball& ball = balls[b];
                    for (int y = int(ball.y - ball.radius); y <= int(ball.y + ball.radius); ++y)
                        for (int x = int(ball.x - ball.radius); x <= int(ball.x + ball.radius);
                             ++x) {
                            if (std::hypot(x - ball.x, y - ball.y) > ball.radius - 1)
                                continue;
                            ++disc;
                            orange += x >= 0 && y >= 0 && x < 320 && y < 240 &&
                                      labels.at<std::uint8_t>(y, x) == int(Colour::Orange);
                        }
                    const double share = double(orange) / disc;
                    const bool concealed = frame.truth.flagsOf("balls", b).concealed;
                    ++(concealed ? concealed_balls : plain_balls);
                    const std::string what = std::to_string(i) + ": " + std::to_string(share);
                    QVERIFY2(concealed ? share > 0.05 && share < 0.6 : share > 0.8, what.c_str());
                }
                const auto& robots = frame.truth.truth.list<Obstacle>();
                for (std::size_t o = 0; o < robots.size(); ++o) {
                    if (!frame.truth.flagsOf("obstacles", o).concealed)
                        continue;
                    ++concealed_robots;
                    const Obstacle& r = robots[o];
                    const bool cut = r.left == 0 || r.right == 319;
                    const bool behind =
                        std::any_of(robots.begin(), robots.end(), [&r](const Obstacle& other) {
                            return &other != &r && other.left <= r.right && r.left <= other.right;
                        });
                    QVERIFY2(cut || behind, std::to_string(i).c_str());
                }
            }
        }
        QCOMPARE(concealed_balls, 6);
        QVERIFY(plain_balls >= 1);
        QVERIFY(concealed_robots >= 2);
    }

    /// A field line is seen where it is at least half a pixel wide across itself and nothing
    /// stands in front of it: a line across the view 4 m away (about 0.37 px tall) is not seen, the
    /// same line 1 m away is (about 6 px), a line running away from the camera is seen to where
    /// it grows thin, and a robot in front hides what it covers.
    void aFieldLineIsSeenWhereItIsWideAndInFront()
    {
        CameraModel camera(320, 240);
        CameraPose pose; // at the origin, 0.45 m high, looking along +x
        pose.pitch = 0.2;
        camera.setPose(pose);
        cv::Mat nothing(240, 320, CV_32S, cv::Scalar(-1));
        const auto across = [](double x) {
            return LineSegment{Eigen::Vector2d(x, -0.5), Eigen::Vector2d(x, 0.5)};
        };
        // f_y 262 px: a 5 cm line d m ahead is 262 * 0.05 * 0.45 / d^2 px tall (d >> 0.45 m).
        QCOMPARE(seenLineShare(across(4.0), camera, nothing), 0.0);
        QCOMPARE(seenLineShare(across(1.0), camera, nothing), 1.0);
        // Running away from the camera its width across itself is f * 0.05 / d: half a pixel at
        // about 26 m, so all of it from 1 to 6 m ahead is seen.
        const LineSegment away{Eigen::Vector2d(1.0, 0.3), Eigen::Vector2d(6.0, 0.3)};
        QCOMPARE(seenLineShare(away, camera, nothing), 1.0);

        // Something in front of the middle third of the near line's image.
        const auto a = camera.project(Eigen::Vector3d(1.0, 0.5, 0));
        const auto b = camera.project(Eigen::Vector3d(1.0, -0.5, 0));
        QVERIFY(a && b);
        cv::Mat robot = nothing.clone();
        const int third = int((b->x - a->x) / 3);
        robot(cv::Rect(int(a->x) + third, 0, third, 240)).setTo(0);
        const double share = seenLineShare(across(1.0), camera, robot);
        QVERIFY2(std::abs(share - 2.0 / 3.0) < 0.03, std::to_string(share).c_str());
    }

    /// A post whose foot is in the frame but behind a robot (Lab 1's frames 2 and 14) is listed
    /// as concealed: its box ends at the robot, not at its base. A post standing in view is not.
    void aPostWithItsFootHiddenIsConcealed()
    {
        const ScenarioScript script(Scenario::Lab1, 1, 320, 240);
        int hidden = 0;
        int standing = 0;
        for (const int i : {2, 10, 14}) {
            const StreamFrame frame = renderStreamFrame(script, i);
            const auto& posts = frame.truth.truth.list<Goalpost>();
            for (std::size_t p = 0; p < posts.size(); ++p) {
                // The post's object: the one whose foot projects into this box's columns.
                std::optional<PointF> foot;
                for (const SceneObject& o : frame.scene.objects)
                    if (const auto at = frame.camera.project(o.position);
                        o.kind == ObjectKind::Post && at && at->x >= posts[p].left - 1 &&
                        at->x <= posts[p].right + 1)
                        foot = at;
                if (!foot || foot->y >= 239 || posts[p].bottom - posts[p].top < 8)
                    continue;
                // Post colour on the foot's row or just above it, in the box's columns.
                bool yellow = false;
                for (int y = std::max(0, int(std::lround(foot->y)) - 2);
                     y <= int(std::lround(foot->y)); ++y)
                    for (int x = posts[p].left; x <= posts[p].right; ++x)
                        yellow = yellow ||
                                 frame.image.labels.at<std::uint8_t>(y, x) == int(Colour::Yellow);
                const bool concealed = frame.truth.flagsOf("goalposts", p).concealed;
                QVERIFY2(concealed != yellow, std::to_string(i).c_str());
                ++(concealed ? hidden : standing);
            }
        }
        QVERIFY(hidden >= 2);
        QVERIFY(standing >= 2);
    }

    void fieldBoundaryIsTopOfTheGreen()
    {
        ScenarioScript script(Scenario::RC2012, 1, 320, 240);
        const fs::path& dir = stream(Scenario::RC2012);
        const nlohmann::json truth = readJson(dir / "annotations.json");
        int checked = 0;
        int agree = 0;
        for (int i = 0; i < kFrames; i += 3) {
            const StreamFrame frame = renderStreamFrame(script, i);
            const nlohmann::json& boundary = truth["frames"][frame.name]["field_boundary"];
            for (int x = 0; x < 320; ++x) {
                const double yb = polylineY(boundary, x);
                if (yb < 3 || yb > 236)
                    continue;
                const int below = int(std::ceil(yb)) + 2;
                const int above = int(std::floor(yb)) - 2;
                const auto label = [&](int y) {
                    return Colour(frame.image.labels.at<uchar>(y, x));
                };
                // Just below: carpet (green, a line, or an edge between them) or something on it.
                const bool field_below = label(below) == Colour::Green ||
                                         label(below) == Colour::White ||
                                         frame.image.labels.at<uchar>(below, x) == kMixedLabel ||
                                         frame.image.primitive.at<int>(below, x) >= 0;
                const bool green_above =
                    label(above) == Colour::Green || label(above) == Colour::White;
                ++checked;
                agree += field_below && !green_above;
            }
        }
        QVERIFY(checked > 300);
        QVERIFY2(agree >= checked * 97 / 100,
                 (std::to_string(agree) + " of " + std::to_string(checked)).c_str());
    }

    void idealLutClassifiesLabelledPixels_data()
    {
        QTest::addColumn<int>("scenario");
        for (const std::string& name : scenarioNames())
            QTest::newRow(name.c_str()) << int(scenarioFromName(name).value());
    }

    void idealLutClassifiesLabelledPixels()
    {
        QFETCH(int, scenario);
        const fs::path& dir = stream(Scenario(scenario));
        const std::vector<char> bytes = readBytes(dir / "default.lut");
        QCOMPARE(bytes.size(), std::size_t(128 * 128 * 128));
        ScenarioScript script(Scenario(scenario), 1, 320, 240);
        long total[kColourCount] = {};
        long right[kColourCount] = {};
        long background_as_field_class = 0;
        for (int i = 0; i < kFrames; ++i) {
            const StreamFrame frame = renderStreamFrame(script, i);
            // The PNG on disk is what a user gets: classify that, not the in-memory copy.
            cv::Mat ycrcb;
            cv::cvtColor(fieldsight::test::imread((dir / frame.name).string()), ycrcb,
                         cv::COLOR_BGR2YCrCb);
            const cv::Mat core = IdealLutBuilder::coreMask(frame.image.labels);
            for (int y = 0; y < ycrcb.rows; ++y) {
                for (int x = 0; x < ycrcb.cols; ++x) {
                    if (!core.at<uchar>(y, x))
                        continue;
                    const cv::Vec3b p = ycrcb.at<cv::Vec3b>(y, x); // Y, Cr, Cb
                    const int label = frame.image.labels.at<uchar>(y, x);
                    const auto got =
                        Colour(std::uint8_t(bytes[ColourLut::index(p[0], p[2], p[1])]));
                    ++total[label];
                    right[label] += int(got) == label;
                    if (label == 0 &&
                        (got == Colour::Green || got == Colour::Orange || got == Colour::Yellow))
                        ++background_as_field_class;
                }
            }
        }
        QVERIFY(total[int(Colour::Green)] > 10000);
        for (int c = 0; c < kColourCount; ++c) {
            if (total[c] < 200)
                continue; // too few core pixels in these frames to measure
            const double accuracy = double(right[c]) / double(total[c]);
            QVERIFY2(
                accuracy >= 0.95,
                (std::string(colourName(Colour(c))) + ": " + std::to_string(accuracy)).c_str());
        }
        QVERIFY2(background_as_field_class <= total[0] / 100,
                 std::to_string(background_as_field_class).c_str());
    }

    void strmHoldsTheSameFrames()
    {
        const fs::path& dir = stream(Scenario::Lab2);
        const std::vector<char> strm = readBytes(dir / "image.strm");
        const std::size_t record = 25 + 320 * 240 * 4;
        QCOMPARE(strm.size(), record * kFrames);
        QCOMPARE(std::string(strm.data(), 4), std::string("IMAG"));
        QCOMPARE(int(strm[24]), 0); // not flipped
        for (const int i : {0, kFrames - 1}) {
            char name[32];
            std::snprintf(name, sizeof name, "frame_%06d.png", i);
            cv::Mat ycrcb;
            cv::cvtColor(fieldsight::test::imread((dir / name).string()), ycrcb,
                         cv::COLOR_BGR2YCrCb);
            const auto* pixels =
                reinterpret_cast<const unsigned char*>(strm.data() + record * std::size_t(i) + 25);
            int mismatches = 0;
            for (int y = 0; y < 240; ++y) {
                for (int x = 0; x < 320; ++x) {
                    const unsigned char* q = pixels + 4 * (std::size_t(y) * 320 + std::size_t(x));
                    const cv::Vec3b p = ycrcb.at<cv::Vec3b>(y, x);
                    mismatches += q[2] != p[0] || q[1] != p[2] || q[3] != p[1];
                }
            }
            QCOMPARE(mismatches, 0);
        }
    }

    void crowdedScenarioShowsSeveralRobots()
    {
        const nlohmann::json truth = readJson(stream(Scenario::RC2013) / "annotations.json");
        int obstacles = 0;
        for (const auto& [name, frame] : truth["frames"].items()) {
            QVERIFY2(frame["obstacles"].size() >= 2, name.c_str());
            obstacles += int(frame["obstacles"].size());
            for (const auto& o : frame["obstacles"]) {
                QVERIFY(o["right"].get<int>() - o["left"].get<int>() + 1 >= 6);
                QVERIFY(o["bottom"].get<int>() > o["top"].get<int>());
            }
        }
        const double mean = double(obstacles) / kFrames;
        QVERIFY2(mean >= 3.5 && mean <= 8.5, std::to_string(mean).c_str());
    }

    /// The crowded test scene: five robots, and now and then one close enough to the camera to
    /// fill over half of the frame's width.
    void crowdedSceneHasARobotFillingTheFrame()
    {
        const ScenarioScript script(Scenario::Crowded, 1, 320, 240);
        int widest = 0;
        for (int i = 0; i < 120; i += 4) {
            const Scene scene = script.sceneAt(i);
            QCOMPARE(
                std::count_if(scene.objects.begin(), scene.objects.end(),
                              [](const SceneObject& o) { return o.kind == ObjectKind::Robot; }),
                std::ptrdiff_t(5));
            if (i % 12 != 0)
                continue;
            const StreamFrame frame = renderStreamFrame(script, i);
            for (const Obstacle& o : frame.truth.truth.list<Obstacle>())
                widest = std::max(widest, o.right - o.left + 1);
        }
        QVERIFY2(widest > 160, std::to_string(widest).c_str());
    }

    /// --camera-height moves the camera and nothing else of the scene; 0.45 is the default.
    void cameraHeightMovesOnlyTheCamera()
    {
        const ScenarioScript usual(Scenario::RC2012, 3, 320, 240);
        ScenarioScript low = usual;
        low.setCameraHeight(0.35);
        for (int i : {0, 17, 40}) {
            const Scene a = usual.sceneAt(i);
            const Scene b = low.sceneAt(i);
            QVERIFY(std::abs(a.camera.position.z() - 0.45) < 0.01);
            QVERIFY(std::abs(a.camera.position.z() - b.camera.position.z() - 0.1) < 1e-9);
            QCOMPARE(a.objects.size(), b.objects.size());
            for (std::size_t k = 0; k < a.objects.size(); ++k)
                QVERIFY(a.objects[k].position == b.objects[k].position);
        }
    }

    void goalpostBoxesShowYellow()
    {
        const fs::path& dir = stream(Scenario::RC2012);
        const nlohmann::json truth = readJson(dir / "annotations.json");
        int posts = 0;
        for (const auto& [name, frame] : truth["frames"].items()) {
            const cv::Mat image = fieldsight::test::imread((dir / name).string());
            for (const auto& post : frame["goalposts"]) {
                ++posts;
                const int left = post["left"];
                const int right = post["right"];
                const int top = post["top"];
                const int bottom = post["bottom"];
                QVERIFY(bottom - top + 1 >= 8 && right - left + 1 >= 2);
                // The middle column of the box, half way up, is the post's yellow.
                const cv::Vec3b p = image.at<cv::Vec3b>((top + bottom) / 2, (left + right) / 2);
                QVERIFY2(p[2] > p[0] + 60 && p[1] > p[0] + 50, name.c_str());
            }
        }
        QVERIFY(posts > 0);
    }
};

FIELDSIGHT_TEST_SUITE(TestSynth, None)

#include "test_synth.moc"
