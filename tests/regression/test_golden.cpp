// Golden regression: the pipeline's output on every bundled sample stream is compared with the
// stored output. Regenerate on purpose with FIELDSIGHT_REGENERATE_GOLDEN=1 (the run then fails, so
// regeneration can never pass CI silently).
#include "support/test_suite.h"
#include "support/synthetic_frames.h"
#include "visioncore/basics/atomic_file.h"
#include "visioncore/services/stream_runner.h"

#include <QtTest>
#include <nlohmann/json.hpp>

#include <cmath>
#include <filesystem>
#include <numeric>

using namespace fieldsight;
using nlohmann::json;

namespace {

/// Everything the pipeline decided for a frame, without timings: its percept lists as results
/// JSON (so a new kind of percept is covered without changing this test).
json frameJson(const FrameResult& f)
{
    nlohmann::ordered_json j = nlohmann::ordered_json::object();
    f.percepts.toJson(j, PerceptNames::Results);
    return json::parse(j.dump());
}

/// Compares two JSON trees, numbers within `tol`; returns the first difference's path.
std::string firstDifference(const json& a, const json& b, const std::string& path, double tol)
{
    if (a.is_number() && b.is_number())
        return std::abs(a.get<double>() - b.get<double>()) <= tol ? "" : path;
    if (a.type() != b.type())
        return path;
    if (a.is_array()) {
        if (a.size() != b.size())
            return path + " (size " + std::to_string(a.size()) + " vs " + std::to_string(b.size()) +
                   ")";
        for (std::size_t i = 0; i < a.size(); ++i)
            if (auto d = firstDifference(a[i], b[i], path + "[" + std::to_string(i) + "]", tol);
                !d.empty())
                return d;
        return "";
    }
    if (a.is_object()) {
        for (auto it = a.begin(); it != a.end(); ++it) {
            if (!b.contains(it.key()))
                return path + "." + it.key() + " (missing)";
            if (auto d = firstDifference(it.value(), b[it.key()], path + "." + it.key(), tol);
                !d.empty())
                return d;
        }
        return a.size() == b.size() ? "" : path + " (extra keys)";
    }
    return a == b ? "" : path;
}

} // namespace

class TestGolden : public QObject
{
    Q_OBJECT
private slots:
    void pipelineOutputMatchesGolden_data()
    {
        QTest::addColumn<QString>("stream");
        for (const char* name : {"lab1", "lab2", "difficult", "rc2012", "rc2013"})
            QTest::newRow(name) << QString(name);
    }

    void pipelineOutputMatchesGolden()
    {
        QFETCH(QString, stream);
        const std::string dir = test::sampleStreamsDir() + "/" + stream.toStdString();
        if (!std::filesystem::is_directory(dir))
            QFAIL(qPrintable("missing bundled stream " + QString::fromStdString(dir)));
        auto input = openStreamInput(dir, "");
        QVERIFY2(input.ok(), input.ok() ? "" : input.error().message.c_str());
        auto run = runStream(input.value(), firstFrames(input.value().info().frame_count), 2);
        QVERIFY2(run.ok(), run.ok() ? "" : run.error().message.c_str());
        json actual = json::object();
        for (const FrameResult& f : run.value().frames)
            actual[f.name] = frameJson(f);

        const std::string golden = std::string(FIELDSIGHT_SOURCE_DIR) +
                                   "/tests/regression/golden/" + stream.toStdString() + ".json";
        if (qEnvironmentVariableIsSet("FIELDSIGHT_REGENERATE_GOLDEN")) {
            QVERIFY(writeFileAtomically(golden, actual.dump(1) + "\n").ok());
            QFAIL(qPrintable("regenerated " + QString::fromStdString(golden) +
                             "; run again without FIELDSIGHT_REGENERATE_GOLDEN"));
        }
        auto text = readWholeFile(golden);
        QVERIFY2(text.ok(), text.ok() ? "" : text.error().message.c_str());
        const json expected = json::parse(text.value());
        const std::string diff = firstDifference(expected, actual, stream.toStdString(), 0.05);
        QVERIFY2(diff.empty(),
                 qPrintable("output differs from golden at " + QString::fromStdString(diff)));
    }
};

FIELDSIGHT_TEST_SUITE(TestGolden, None)

#include "test_golden.moc"
