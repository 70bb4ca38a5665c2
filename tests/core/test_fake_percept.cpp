// A percept kind in one place: a fake kind with its matching rule (support/fake_percept.h), added
// to the pipeline by this test alone, is scored by matchFrame and by `eval` (its table row and
// its JSON class, the standard classes' bytes unchanged) and exported to COCO, with no change
// anywhere else.
#include "support/in_process_command.h"
#include "support/test_suite.h"
#include "commands/commands.h"
#include "support/fake_percept.h"
#include "support/synthetic_frames.h"
#include "visioncore/basics/atomic_file.h"
#include "visioncore/services/evaluation.h"

#include <QDir>
#include <QFile>
#include <QTemporaryDir>
#include <QtTest>
#include <nlohmann/json.hpp>

#include <sstream>

using namespace fieldsight;
using namespace fieldsight::test;

namespace {

nlohmann::json jsonOfFile(const QString& path)
{
    auto text = readWholeFile(path.toStdString());
    return text ? nlohmann::json::parse(text.value()) : nlohmann::json();
}

} // namespace

class TestFakePercept : public QObject
{
    Q_OBJECT

    Pipeline m_pipeline = withFakePercept();
    QTemporaryDir m_dir;
    QString m_stream;

private slots:
    void initTestCase()
    {
        QVERIFY(m_dir.isValid());
        QVERIFY(m_pipeline.validate().ok());
        // lab1 (30 done frames) with true fake spots on two frames: one where the stage sees
        // its spot, one far from it.
        m_stream = m_dir.filePath("lab1");
        const QDir from(QString::fromStdString(test::sampleStreamsDir() + "/lab1"));
        QVERIFY(QDir().mkpath(m_stream));
        for (const QString& name : from.entryList(QDir::Files))
            QVERIFY(QFile::copy(from.filePath(name), m_stream + "/" + name));
        const QString truth = m_stream + "/annotations.json";
        nlohmann::ordered_json doc =
            nlohmann::ordered_json::parse(readWholeFile(truth.toStdString()).value());
        auto& frames = doc["frames"];
        QVERIFY(frames.size() == 30 && frames.contains("frame_000001.png"));
        frames["frame_000000.png"]["fake_spots"] = {{{"x", 42}, {"y", 31}, {"radius", 4}}};
        frames["frame_000001.png"]["fake_spots"] = {{{"x", 200}, {"y", 200}, {"radius", 4}}};
        QFile::remove(truth);
        QVERIFY(writeFileAtomically(truth.toStdString(), doc.dump(1)).ok());
    }

    void theKindCarriesItsRuleAndName()
    {
        const PerceptKind& kind = perceptKind<FakeSpot>();
        QCOMPARE(scoredClassName(kind), std::string("fake_spot"));
        QCOMPARE(scoredClassText(kind), std::string("fake spot"));
        // Listed after the standard classes, which keep their order.
        std::vector<const PerceptKind*> expected = scoredKinds();
        expected.push_back(&kind);
        QVERIFY(scoredKinds(m_pipeline.perceptKinds()) == expected);
        QCOMPARE(scoredKinds().size(), std::size_t(4));
    }

    void matchFrameScoresTheKindByItsRule()
    {
        PerceptSet detected;
        detected.output<FakeSpot>() = {kFakeSpotSeen, {100, 100, 3}};
        FrameAnnotation truth;
        truth.done = true;
        truth.truth.output<FakeSpot>() = {{43, 33, 4}, {300, 10, 4}}; // 4.2 px away; far
        const std::vector<const PerceptKind*> kinds = scoredKinds(m_pipeline.perceptKinds());
        const FrameMatch match = matchFrame(detected, truth, 320, 240, kinds);
        QCOMPARE(match.kinds.size(), std::size_t(5));
        const KindMatch& fake = match.kinds.back();
        QCOMPARE(fake.kind, &perceptKind<FakeSpot>());
        QCOMPARE(fake.pairs, (std::vector<MatchPair>{{0, 0}}));
        QCOMPARE(fake.score, (ClassScore{1, 1, 1}));
        QCOMPARE(fake.false_detections, std::vector<std::size_t>{1});
        QCOMPARE(fake.missed, std::vector<std::size_t>{1});
        // Without it among the kinds (the standard pipeline), it is not scored.
        QCOMPARE(matchFrame(detected, truth, 320, 240).kinds.size(), std::size_t(4));

        EvaluationScores scores(kinds);
        scores.add(match);
        QCOMPARE(scores.of<FakeSpot>(), (ClassScore{1, 1, 1}));
        QCOMPARE(scores.classes().back().first, &perceptKind<FakeSpot>());
    }

    void evalScoresTheKind()
    {
        const QString fake_json = m_dir.filePath("fake_eval.json");
        const CommandOutcome fake =
            runInProcess(m_pipeline, {"eval", m_stream, "--json", fake_json, "--threads", "1"});
        QVERIFY2(fake.status == 0, fake.err.c_str());
        const QString standard_json = m_dir.filePath("standard_eval.json");
        const CommandOutcome standard = runInProcess(
            Pipeline::standard(), {"eval", m_stream, "--json", standard_json, "--threads", "1"});
        QVERIFY2(standard.status == 0, standard.err.c_str());

        // The table: the standard rows as they were, and a row of its own after them. The
        // stage sees a spot on each of the 30 frames; one of the two true spots is near it.
        const std::string row = "fake spot        1      29       1      0.033    0.500\n";
        const std::size_t at = fake.out.find(row);
        QVERIFY2(at != std::string::npos, fake.out.c_str());
        QVERIFY(fake.out.find("field line") < at);
        QCOMPARE(fake.out.substr(0, at) + fake.out.substr(at + row.size()), standard.out);

        // The JSON: its class after the standard ones, which are unchanged.
        const nlohmann::json f = jsonOfFile(fake_json);
        const nlohmann::json s = jsonOfFile(standard_json);
        const nlohmann::json& spot = f["classes"]["fake_spot"];
        QCOMPARE(spot["tp"].get<int>(), 1);
        QCOMPARE(spot["fp"].get<int>(), 29);
        QCOMPARE(spot["fn"].get<int>(), 1);
        QCOMPARE(spot["recall"].get<double>(), 0.5);
        nlohmann::json without = f;
        without["classes"].erase("fake_spot");
        QCOMPARE(without["classes"].dump(), s["classes"].dump());
        QCOMPARE(f["field_boundary"].dump(), s["field_boundary"].dump());
        std::size_t fake_disagreements = 0;
        for (const auto& d : f["disagreements"])
            fake_disagreements += d["class"] == "fake_spot";
        QCOMPARE(fake_disagreements, std::size_t(29)); // frame 1's miss with its false spot
        QCOMPARE(f["disagreements"].size(), s["disagreements"].size() + fake_disagreements);
    }

    void cocoExportHasTheKind()
    {
        const QString coco = m_dir.filePath("coco.json");
        const CommandOutcome o =
            runInProcess(m_pipeline, {"annotations", "export", m_stream, "--coco", coco});
        QVERIFY2(o.status == 0, o.err.c_str());
        const nlohmann::json doc = jsonOfFile(coco);
        int category = -1;
        for (const auto& c : doc["categories"])
            if (c["name"] == "fake_spots")
                category = c["id"].get<int>();
        QVERIFY2(category >= 0, doc["categories"].dump().c_str());
        std::vector<std::vector<double>> circles;
        for (const auto& a : doc["annotations"])
            if (a["category_id"] == category)
                circles.push_back(a["circle"].get<std::vector<double>>());
        QCOMPARE(circles, (std::vector<std::vector<double>>{{42, 31, 4}, {200, 200, 4}}));
    }
};

FIELDSIGHT_TEST_SUITE(TestFakePercept, Core)

#include "test_fake_percept.moc"
