// `fieldsight tune` as a user runs it: the file it writes gives `eval` the scores it reported,
// its JSON report is complete, and Ctrl+C ends the search with the best so far written.
#include "support/test_suite.h"
#include "support/synthetic_frames.h"

#include "visioncore/framework/param_set.h"

#include <QtTest>

#include <QDir>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QTemporaryDir>

#include <csignal>

using namespace fieldsight;

namespace {

QJsonObject readJson(const QString& path)
{
    QFile f(path);
    if (!f.open(QIODevice::ReadOnly))
        qFatal("cannot read %s", qPrintable(path));
    return QJsonDocument::fromJson(f.readAll()).object();
}

} // namespace

class TestTuneCommand : public QObject
{
    Q_OBJECT

    QTemporaryDir m_dir;

    QString stream(const char* name) const
    {
        return QString::fromStdString(test::sampleStreamsDir()) + "/" + name;
    }

    QProcess* start(const QStringList& args)
    {
        auto* p = new QProcess(this);
        p->start(FIELDSIGHT_EXE, args);
        if (!p->waitForStarted())
            qFatal("fieldsight did not start");
        return p;
    }

private slots:
    void theWrittenFileGivesEvalTheTunedScores()
    {
        const QString params = m_dir.filePath("lab2.json");
        const QString report = m_dir.filePath("lab2.tune.json");
        QProcess* tune = start({"tune", stream("lab2"), "--holdout", "0", "--stages",
                                "transitions,ball", "--budget", "40", "--set",
                                "transitions.goal_colour=9", "--out", params, "--json", report});
        QVERIFY(tune->waitForFinished(120000));
        QCOMPARE(tune->exitCode(), 0);
        const QString text = QString::fromUtf8(tune->readAllStandardOutput());
        QVERIFY2(text.contains("transitions.goal_colour"), qPrintable(text));
        const QJsonObject r = readJson(report);
        QCOMPARE(r["format"].toString(), QString("fieldsight-tune/1"));
        QCOMPARE(r["evaluations"].toInt() <= 40 + 10, true);
        QVERIFY(!r["history"].toArray().isEmpty());
        QVERIFY(r["holdout_frames"].toArray().isEmpty());
        const QJsonObject tuned = r["tuned"].toObject()["fit"].toObject();

        // eval with the file (on top of the stream's own settings) scores what tune reported.
        const QString eval_json = m_dir.filePath("lab2.eval.json");
        QProcess* eval = start({"eval", stream("lab2"), "--params", params, "--json", eval_json});
        QVERIFY(eval->waitForFinished(120000));
        QCOMPARE(eval->exitCode(), 0);
        const QJsonObject scores = readJson(eval_json)["classes"].toObject();
        for (const char* name : {"ball", "goalpost", "obstacle", "field_line"}) {
            const QJsonObject want = tuned["classes"].toObject()[name].toObject();
            const QJsonObject got = scores[name].toObject();
            for (const char* count : {"tp", "fp", "fn"})
                QCOMPARE(got[count].toInt(), want[count].toInt());
        }
        auto saved = ParamSet::load(params.toStdString());
        QVERIFY(saved.ok());
        QCOMPARE(saved.value().values.at("transitions").at("goal_colour"), 8.0); // yellow
    }

    void aValidationStreamIsScoredAsEvalScoresIt()
    {
        const QString params = m_dir.filePath("lab2v.json");
        const QString report = m_dir.filePath("lab2v.tune.json");
        QProcess* tune =
            start({"tune", stream("lab2"), "--validate", stream("lab1"), "--stages",
                   "transitions,field_lines", "--budget", "30", "--out", params, "--json", report});
        QVERIFY(tune->waitForFinished(120000));
        QCOMPARE(tune->exitCode(), 0);
        const QString text = QString::fromUtf8(tune->readAllStandardOutput());
        QVERIFY2(text.contains("validation streams"), qPrintable(text));
        const QJsonObject r = readJson(report);
        QCOMPARE(r["validation_streams"].toArray().size(), 1);
        const QJsonArray frames = r["validation_frames"].toArray();
        QVERIFY(!frames.isEmpty());
        QVERIFY(frames[0].toString().startsWith(stream("lab1") + "/"));
        // The result on lab1 is what eval scores there with the file written.
        const QString eval_json = m_dir.filePath("lab1v.eval.json");
        QProcess* eval = start({"eval", stream("lab1"), "--params", params, "--json", eval_json});
        QVERIFY(eval->waitForFinished(120000));
        QCOMPARE(eval->exitCode(), 0);
        const QJsonObject scores = readJson(eval_json)["classes"].toObject();
        const QJsonObject tuned = r["tuned"].toObject()["validation"].toObject();
        for (const char* name : {"ball", "goalpost", "obstacle", "field_line"}) {
            const QJsonObject want = tuned["classes"].toObject()[name].toObject();
            const QJsonObject got = scores[name].toObject();
            for (const char* count : {"tp", "fp", "fn"})
                QCOMPARE(got[count].toInt(), want[count].toInt());
        }

        // A stream cannot be fitted and kept aside at once.
        QProcess* both = start({"tune", stream("lab2"), "--validate", stream("lab2"), "--out",
                                m_dir.filePath("both.json")});
        QVERIFY(both->waitForFinished(120000));
        QVERIFY(both->exitCode() != 0);
        const QString error = QString::fromUtf8(both->readAllStandardError());
        QVERIFY2(error.contains("both fitted and a --validate stream"), qPrintable(error));
        QVERIFY(!QFile::exists(m_dir.filePath("both.json")));
    }

    void ctrlCKeepsTheBestSoFar()
    {
        const QString params = m_dir.filePath("interrupted.json");
        QProcess* tune = start({"tune", stream("lab1"), "--budget", "1000000", "--out", params});
        // Long enough for the frames to be read and the search to run a while (the whole budget
        // would take hours).
        QTest::qWait(4000);
        QCOMPARE(tune->state(), QProcess::Running);
        ::kill(pid_t(tune->processId()), SIGINT);
        QVERIFY(tune->waitForFinished(60000));
        QCOMPARE(tune->exitStatus(), QProcess::NormalExit);
        QCOMPARE(tune->exitCode(), 0);
        const QString text = QString::fromUtf8(tune->readAllStandardOutput());
        QVERIFY2(text.contains("interrupted: the best so far"), qPrintable(text));
        QVERIFY(QFile::exists(params));
        QVERIFY(ParamSet::load(params.toStdString()).ok());
    }
};

FIELDSIGHT_TEST_SUITE(TestTuneCommand, Core)

#include "test_tune_command.moc"
