// A stage in one place: an eighth stage, with a parameter, a debug layer and a percept kind of its
// own, is added to the pipeline by this test alone, and the command line (run's results, --set,
// --skip, --render, the usage text) knows it without any other change.
//
// What adding it took: the Stage subclass and its percept type with PerceptTraits (below), and
// one Pipeline::add call (the line stage_list.cpp would get).
#include "support/in_process_command.h"
#include "support/test_suite.h"
#include "commands/commands.h"
#include "support/fake_stage.h"
#include "support/synthetic_frames.h"
#include "visioncore/framework/blackboard.h"
#include "visioncore/basics/atomic_file.h"
#include "visioncore/services/results_json.h"

#include <QImage>
#include <QTemporaryDir>
#include <QtTest>
#include <nlohmann/json.hpp>

#include <sstream>

using namespace fieldsight;
using namespace fieldsight::test;

class TestFakeStage : public QObject
{
    Q_OBJECT

    Pipeline m_pipeline = withFakeStage();
    QTemporaryDir m_dir;
    std::string m_stream;

    CommandOutcome run(const QStringList& args) { return runInProcess(m_pipeline, args); }

    nlohmann::json runJson(const QStringList& extra)
    {
        const QString out = m_dir.filePath("results.json");
        const CommandOutcome o =
            run(QStringList{"run", QString::fromStdString(m_stream), "--out", out} + extra);
        if (o.status != 0)
            qWarning() << o.err.c_str();
        auto text = readWholeFile(out.toStdString());
        return text ? nlohmann::json::parse(text.value()) : nlohmann::json();
    }

private slots:
    void initTestCase()
    {
        QVERIFY(m_dir.isValid());
        m_stream = test::sampleStreamsDir() + "/lab1";
        QCOMPARE(m_pipeline.size(), std::size_t(8));
        QVERIFY(m_pipeline.validate().ok());
    }

    void runResultsHaveTheStagesTimeAndPercepts()
    {
        const nlohmann::json doc = runJson({"--limit", "2"});
        QCOMPARE(doc["frames"].size(), std::size_t(2));
        const auto& frame = doc["frames"][0];
        QVERIFY(frame["time_ms"].contains("fake"));
        QCOMPARE(frame["fake_marks"].size(), std::size_t(1));
        QCOMPARE(frame["fake_marks"][0]["value"].get<double>(), 1.5);
        QVERIFY(doc["summary"]["stage_mean_ms"].contains("fake"));
        // The standard stages are still all there.
        QVERIFY(frame.contains("balls"));
        QVERIFY(frame["time_ms"].contains("obstacles"));
    }

    void setReachesTheFakeStage()
    {
        const nlohmann::json doc = runJson({"--limit", "1", "--set", "fake.level=3"});
        QCOMPARE(doc["frames"][0]["fake_marks"][0]["value"].get<double>(), 3.0);

        const CommandOutcome bad = run({"run", QString::fromStdString(m_stream), "--set",
                                        "fake.level=11", "--out", m_dir.filePath("x.json")});
        QCOMPARE(bad.status, 2);
        QVERIFY2(QString::fromStdString(bad.err).contains("fake.level"), bad.err.c_str());
        const CommandOutcome unknown = run({"run", QString::fromStdString(m_stream), "--set",
                                            "fake.nope=1", "--out", m_dir.filePath("x.json")});
        QCOMPARE(unknown.status, 2);
        QVERIFY2(QString::fromStdString(unknown.err).contains("nope"), unknown.err.c_str());
    }

    void skipSwitchesTheFakeStageOff()
    {
        const nlohmann::json doc = runJson({"--limit", "1", "--skip", "fake"});
        const auto& frame = doc["frames"][0];
        QVERIFY(!frame.contains("fake_marks")); // absent, not empty
        QVERIFY(!frame["time_ms"].contains("fake"));
        QCOMPARE(doc["skipped_stages"][0].get<std::string>(), std::string("fake"));
    }

    void renderDrawsTheFakeLayerAndPercept()
    {
        const QString dir = m_dir.filePath("render");
        const CommandOutcome o = run({"run", QString::fromStdString(m_stream), "--limit", "1",
                                      "--out", m_dir.filePath("r.json"), "--render", dir,
                                      "--layers", "fake,percepts.fake_marks", "--scale", "1"});
        QCOMPARE(o.status, 0);
        const QImage image(dir + "/frame_000000.png");
        QVERIFY(!image.isNull());
        QCOMPARE(image.size(), QSize(320, 240));
        const QRgb box = qRgb(kFakeLayerColour.r, kFakeLayerColour.g, kFakeLayerColour.b);
        QCOMPARE(image.pixel(10, 10), box);
        QCOMPARE(image.pixel(15, 15), box);
        QCOMPARE(image.pixel(19, 19), box);
        QVERIFY(image.pixel(21, 21) != box);
        const Rgb mark = PerceptTraits<FakeMark>::colour;
        QCOMPARE(image.pixel(40, 30), qRgb(mark.r, mark.g, mark.b));
        QCOMPARE(image.pixel(42, 32), qRgb(mark.r, mark.g, mark.b)); // 5 px square
        QVERIFY(image.pixel(44, 30) != qRgb(mark.r, mark.g, mark.b));

        const CommandOutcome bad = run({"run", QString::fromStdString(m_stream), "--limit", "1",
                                        "--render", dir, "--layers", "fake.nothing"});
        QCOMPARE(bad.status, 2);
        QVERIFY2(QString::fromStdString(bad.err).contains("fake.nothing"), bad.err.c_str());
    }

    void aFaultyStageIsADiagnosticOfItsFrames_data()
    {
        QTest::addColumn<int>("fault");
        QTest::addColumn<QString>("message");
        QTest::newRow("throws") << int(FakeStage::kThrows) << "failed on purpose";
        QTest::newRow("NaN") << int(FakeStage::kNotANumber)
                             << "returned fake_marks with the point (nan, 30) for a 320x240 image";
        QTest::newRow("far outside") << int(FakeStage::kFarOutside) << "(10000000, 30)";
    }

    void aFaultyStageIsADiagnosticOfItsFrames()
    {
        QFETCH(int, fault);
        QFETCH(QString, message);
        // The fault strikes frames 2 and 5 of 6; the run goes on and says so per frame.
        const nlohmann::json doc =
            runJson({"--limit", "6", "--set", QString("fake.fault=%1").arg(fault), "--set",
                     "fake.every=3"});
        QCOMPARE(doc["frames"].size(), std::size_t(6));
        for (std::size_t i = 0; i < 6; ++i) {
            const auto& frame = doc["frames"][i];
            const bool struck = i % 3 == 2;
            QCOMPARE(frame.contains("diagnostics"), struck);
            QCOMPARE(frame["fake_marks"].size(), struck ? std::size_t(0) : std::size_t(1));
            QVERIFY(frame.contains("balls")); // the other stages ran
            if (struck) {
                QCOMPARE(frame["diagnostics"].size(), std::size_t(1));
                QCOMPARE(frame["diagnostics"][0]["stage"].get<std::string>(), std::string("fake"));
                const auto text = frame["diagnostics"][0]["message"].get<std::string>();
                QVERIFY2(QString::fromStdString(text).contains(message), text.c_str());
            }
        }
        // No NaN or absurd number reached the file: it reads back with the checks of every reader.
        auto text = readWholeFile(m_dir.filePath("results.json").toStdString());
        QVERIFY(text.ok());
        const auto back = readResults(text.value(), "results.json", m_pipeline);
        QVERIFY2(back.ok(), back ? "" : back.error().message.c_str());
    }

    void usageListsTheFakeStage()
    {
        const CommandOutcome o = run({"help"});
        QCOMPARE(o.status, 0);
        QVERIFY2(QString::fromStdString(o.out).contains("obstacles, fake."), o.out.c_str());
    }
};

FIELDSIGHT_TEST_SUITE(TestFakeStage, Core)

#include "test_fake_stage.moc"
