// Regression on real robot frames from reference_data: B-Human's 2009 Nao log with the colour
// table that shipped beside it, and NUbots lab frames with the NUbots lab LUT. The expected counts
// were measured once through the CLI; the margins leave room for tuning but not for a broken stage.
#include "support/test_suite.h"
#include "support/reference_streams.h"
#include "support/synthetic_frames.h"
#include "support/test_images.h"
#include "visioncore/percepts/ball.h"
#include "visioncore/percepts/field_boundary.h"
#include "visioncore/percepts/field_line.h"
#include "visioncore/percepts/goalpost.h"
#include "visioncore/services/stream_runner.h"
#include "visioncore/io/stream_reader.h"

#include <QtTest>

#include <QDir>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <string>
#include <vector>

using namespace fieldsight;

namespace {

constexpr int kBhumanFrames = 160;
constexpr int kBhumanWidth = 320;
constexpr int kBhumanHeight = 240;

QString refPath(const QString& relative)
{
    return QString::fromStdString(test::referenceDataDir()) + "/" + relative;
}

bool writeJson(const QString& path, const QJsonObject& object)
{
    QFile file(path);
    return file.open(QIODevice::WriteOnly) && file.write(QJsonDocument(object).toJson()) > 0;
}

/// Linear interpolation of the green horizon hull (x ascending) at `x`.
double hullYAt(const std::vector<PointF>& hull, double x)
{
    if (hull.empty())
        return 0;
    if (x <= hull.front().x)
        return hull.front().y;
    for (std::size_t i = 1; i < hull.size(); ++i) {
        if (x <= hull[i].x) {
            const PointF& a = hull[i - 1];
            const PointF& b = hull[i];
            return b.x > a.x ? a.y + (b.y - a.y) * (x - a.x) / (b.x - a.x) : b.y;
        }
    }
    return hull.back().y;
}

/// Runs the whole stream with `settings`; fails the calling test on any error.
std::vector<FrameResult> runWhole(const QString& stream, const std::vector<std::string>& settings)
{
    auto input = openStreamInput(stream.toStdString(), "");
    if (!input) {
        qWarning() << input.error().message.c_str();
        return {};
    }
    for (const std::string& setting : settings)
        if (Status s = input.value().params.parseSetting(setting); !s) {
            qWarning() << s.error().message.c_str();
            return {};
        }
    auto run = runStream(input.value(), firstFrames(input.value().info().frame_count), 2);
    if (!run) {
        qWarning() << run.error().message.c_str();
        return {};
    }
    return std::move(run).value().frames;
}

const FrameResult* findFrame(const std::vector<FrameResult>& frames, const std::string& name)
{
    for (const FrameResult& f : frames)
        if (f.name == name)
            return &f;
    return nullptr;
}

int countFrames(const std::vector<FrameResult>& frames, auto predicate)
{
    return int(std::count_if(frames.begin(), frames.end(), predicate));
}

} // namespace

class TestReferenceFrames : public QObject
{
    Q_OBJECT

private:
    QTemporaryDir m_dir;
    bool m_have_reference = false;
    QString m_bhuman;                       ///< stream folder over reference_data's B-Human frames
    QString m_nubots;                       ///< stream folder over the NUsight frames
    std::vector<FrameResult> m_bhuman_blue; ///< goal_colour = 9 (the 2009 goal is sky-blue)
    std::vector<FrameResult> m_bhuman_yellow; ///< goal_colour left at its default, yellow

    void makeBhumanStream()
    {
        const QString source = refPath("bhuman2009_log_coltable");
        m_bhuman = m_dir.filePath("bhuman2009");
        const auto rows = test::readBhumanFramesCsv(source + "/frames.csv");
        QVERIFY2(rows, "cannot read frames.csv");
        QCOMPARE(int(rows->size()), kBhumanFrames);

        QJsonArray frames;
        for (const test::BhumanFrameRow& row : *rows) {
            const auto horizon = row.horizon(kBhumanWidth);
            frames.append(
                QJsonObject{{"file", QString("f%1.png").arg(row.index, 3, 10, QChar('0'))},
                            {"timestamp_ms", row.timestamp_ms},
                            {"horizon", QJsonArray{horizon[0], horizon[1]}}});
        }
        const QString made = test::makeLinkedStream(
            m_bhuman, source + "/frames_ycbcr", frames,
            {{"format", "fieldsight-stream/1"}, {"pixel_format", "ycbcr"}, {"lut", "default.lut"}});
        QVERIFY2(made.isEmpty(), qPrintable(made));
        const QString lut = test::convertLut(source + "/coltable.c64", m_bhuman + "/default.lut");
        QVERIFY2(lut.isEmpty(), qPrintable(lut));
    }

    void makeNubotsStream()
    {
        const QString source = refPath("nubots_nusight_frames");
        m_nubots = m_dir.filePath("nusight");
        QVERIFY(QDir().mkpath(m_nubots));
        for (const char* name :
             {"test_image_2014-04.jpg", "test_image2_2014-05-03.jpg", "test_image2_2014-05-04.jpg"})
            QVERIFY(QFile::link(source + "/" + name, m_nubots + "/" + name));
        // The frames are stored upside down (see the README).
        QVERIFY(writeJson(m_nubots + "/stream.json",
                          {{"format", "fieldsight-stream/1"},
                           {"pixel_format", "rgb"},
                           {"flipped", true},
                           {"lut", refPath("nubots_robocup_2013_luts/default_lab.lut")}}));
    }

private slots:
    void initTestCase()
    {
        m_have_reference = !test::referenceDataDir().empty();
        if (!m_have_reference)
            return; // the manifest tests below still run
        QVERIFY(m_dir.isValid());
        makeBhumanStream();
        makeNubotsStream();
        m_bhuman_blue = runWhole(m_bhuman, {"transitions.goal_colour=9"});
        m_bhuman_yellow = runWhole(m_bhuman, {});
        QCOMPARE(int(m_bhuman_blue.size()), kBhumanFrames);
        QCOMPARE(int(m_bhuman_yellow.size()), kBhumanFrames);
    }

    void bhumanBallFoundInMostFrames()
    {
        if (!m_have_reference)
            QSKIP("reference_data is absent (FIELDSIGHT_SHARED_DIR)");
        // Measured: 116 of 160 (the ball leaves the view while the robot turns to the goal).
        const int with_ball = countFrames(
            m_bhuman_blue, [](const FrameResult& f) { return !f.percepts.list<Ball>().empty(); });
        QVERIFY2(with_ball >= 105 && with_ball <= 150, qPrintable(QString::number(with_ball)));
    }

    void bhumanBallLargeInViewAtF070()
    {
        if (!m_have_reference)
            QSKIP("reference_data is absent (FIELDSIGHT_SHARED_DIR)");
        const FrameResult* f = findFrame(m_bhuman_blue, "f070.png");
        QVERIFY(f);
        // The ball fills the middle of the frame, resting on a field line. Its orange pixels in
        // preview/f070_rgb.png (R > 150, R - G > 50, R - B > 80; rows 0-199, above the robot's
        // red foot) span x 128-205 and y 96-174: centre (166.5, 135), radius 39 px by the span,
        // 39.1 by the area (4797 px).
        QVERIFY2(f->percepts.list<Ball>().size() == 1,
                 qPrintable(QString("f070: %1 balls, expected the large one")
                                .arg(f->percepts.list<Ball>().size())));
        const Ball& ball = f->percepts.list<Ball>().front();
        const QString found =
            QString("ball at %1, %2, radius %3").arg(ball.x).arg(ball.y).arg(ball.radius);
        // Measured: (165.8, 134.4), radius 39.8.
        QVERIFY2(std::abs(ball.x - 166.5) <= 3 && std::abs(ball.y - 135) <= 3, qPrintable(found));
        QVERIFY2(std::abs(ball.radius - 39) <= 3, qPrintable(found));
    }

    void bhumanNoBallAboveTheGreenHorizon()
    {
        if (!m_have_reference)
            QSKIP("reference_data is absent (FIELDSIGHT_SHARED_DIR)");
        for (const FrameResult& f : m_bhuman_blue)
            for (const Ball& ball : f.percepts.list<Ball>()) {
                const double horizon = hullYAt(boundaryOf(f.percepts), ball.x);
                QVERIFY2(ball.y >= horizon,
                         qPrintable(QString("%1: ball at y %2 above the green horizon at y %3")
                                        .arg(QString::fromStdString(f.name))
                                        .arg(ball.y)
                                        .arg(horizon)));
            }
    }

    void bhumanBlueGoalpostsFound()
    {
        if (!m_have_reference)
            QSKIP("reference_data is absent (FIELDSIGHT_SHARED_DIR)");
        // Measured: 65 frames (the goal is in view from about frame 115 on, and briefly before).
        const int with_posts = countFrames(m_bhuman_blue, [](const FrameResult& f) {
            return !f.percepts.list<Goalpost>().empty();
        });
        QVERIFY2(with_posts >= 55 && with_posts <= 100, qPrintable(QString::number(with_posts)));
        for (const FrameResult& f : m_bhuman_blue)
            for (const Goalpost& post : f.percepts.list<Goalpost>()) {
                QVERIFY(post.left <= post.right && post.top <= post.bottom);
                QVERIFY(post.left >= 0 && post.right < kBhumanWidth);
            }
    }

    void bhumanYellowGoalColourFindsAlmostNoPosts()
    {
        if (!m_have_reference)
            QSKIP("reference_data is absent (FIELDSIGHT_SHARED_DIR)");
        // Only the sky-blue goal is in this log, so the parameter decides whether posts are seen.
        const int with_posts = countFrames(m_bhuman_yellow, [](const FrameResult& f) {
            return !f.percepts.list<Goalpost>().empty();
        });
        QVERIFY2(with_posts <= 5, qPrintable(QString::number(with_posts)));
    }

    void bhumanGreenHorizonInEveryFrameAndFieldLinesInNearlyAll()
    {
        if (!m_have_reference)
            QSKIP("reference_data is absent (FIELDSIGHT_SHARED_DIR)");
        // Field lines in nearly every frame. Frames that show only the centre circle have none
        // since the circle's chords are dropped (issue 34: f114 and f150, annotated without a
        // line); f113's one line is lost with them, RANSAC joining it to the circle's arc into
        // one bent line. 11 of 160 frames have none.
        int without_lines = 0;
        for (const FrameResult& f : m_bhuman_blue) {
            const QString name = QString::fromStdString(f.name);
            QVERIFY2(boundaryOf(f.percepts).size() >= 2, qPrintable(name));
            QCOMPARE(boundaryOf(f.percepts).front().x, 0.0);
            QCOMPARE(boundaryOf(f.percepts).back().x, double(kBhumanWidth - 1));
            const double top =
                std::min_element(boundaryOf(f.percepts).begin(), boundaryOf(f.percepts).end(),
                                 [](const PointF& a, const PointF& b) { return a.y < b.y; })
                    ->y;
            QVERIFY2(top < kBhumanHeight - 1, qPrintable(name + ": no green horizon"));
            without_lines += f.percepts.list<FieldLine>().empty() ? 1 : 0;
        }
        QVERIFY2(without_lines <= 12, qPrintable(QString::number(without_lines)));
    }

    void nubotsFrameHasBallAndBothPosts()
    {
        if (!m_have_reference)
            QSKIP("reference_data is absent (FIELDSIGHT_SHARED_DIR)");
        const std::vector<FrameResult> frames = runWhole(m_nubots, {});
        QCOMPARE(int(frames.size()), 3);
        const FrameResult* f = findFrame(frames, "test_image2_2014-05-03.jpg");
        QVERIFY(f);
        QCOMPARE(int(f->percepts.list<Ball>().size()), 1);
        const Ball& ball = f->percepts.list<Ball>().front();
        const QString where =
            QString("ball at (%1, %2) r %3").arg(ball.x).arg(ball.y).arg(ball.radius);
        QVERIFY2(std::hypot(ball.x - 134.5, ball.y - 188.8) <= 4.0, qPrintable(where));
        QVERIFY2(std::abs(ball.radius - 19.7) <= 3.0, qPrintable(where));

        QCOMPARE(int(f->percepts.list<Goalpost>().size()), 2);
        const int left_of_centre = int(
            std::count_if(f->percepts.list<Goalpost>().begin(), f->percepts.list<Goalpost>().end(),
                          [](const Goalpost& g) { return g.base_x < 160; }));
        QCOMPARE(left_of_centre, 1);
    }

    void flippedManifestRotatesTheImage()
    {
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        // 2x2, distinct colours (cv::imwrite takes BGR).
        cv::Mat bgr(2, 2, CV_8UC3);
        bgr.at<cv::Vec3b>(0, 0) = {0, 0, 255};
        bgr.at<cv::Vec3b>(0, 1) = {0, 255, 0};
        bgr.at<cv::Vec3b>(1, 0) = {255, 0, 0};
        bgr.at<cv::Vec3b>(1, 1) = {40, 200, 240};
        for (const char* folder : {"plain", "flipped"}) {
            QVERIFY(QDir(dir.path()).mkdir(folder));
            QVERIFY(fieldsight::test::imwrite(
                dir.filePath(QString(folder) + "/f0.png").toStdString(), bgr));
        }
        QVERIFY(writeJson(dir.filePath("flipped/stream.json"),
                          {{"format", "fieldsight-stream/1"}, {"flipped", true}}));

        auto plain = openStream(dir.filePath("plain").toStdString());
        auto flipped = openStream(dir.filePath("flipped").toStdString());
        QVERIFY(plain.ok() && flipped.ok());
        auto a = plain.value()->read(0);
        auto b = flipped.value()->read(0);
        QVERIFY(a.ok() && b.ok());
        const cv::Mat& original = a.value().ycbcr;
        const cv::Mat& rotated = b.value().ycbcr;
        QCOMPARE(rotated.size(), original.size());
        QVERIFY(original.at<cv::Vec3b>(0, 0) != original.at<cv::Vec3b>(1, 1));
        for (int y = 0; y < 2; ++y)
            for (int x = 0; x < 2; ++x)
                QVERIFY(rotated.at<cv::Vec3b>(y, x) == original.at<cv::Vec3b>(1 - y, 1 - x));
    }

    void flippedMustBeABoolean()
    {
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        QVERIFY(fieldsight::test::imwrite(dir.filePath("f0.png").toStdString(),
                                          cv::Mat::zeros(2, 2, CV_8UC3)));
        QVERIFY(writeJson(dir.filePath("stream.json"),
                          {{"format", "fieldsight-stream/1"}, {"flipped", "yes"}}));
        auto opened = openStream(dir.path().toStdString());
        QVERIFY(!opened.ok());
        const QString message = QString::fromStdString(opened.error().message);
        QVERIFY2(message.contains("stream.json") && message.contains("flipped"),
                 qPrintable(message));
    }
};

FIELDSIGHT_TEST_SUITE(TestReferenceFrames, Core)

#include "test_reference_frames.moc"
