// The fieldsight executable's headless commands as a user meets them: exit statuses, one-line
// errors naming the file, and the JSON of run, bench and eval on a tiny stream.
#include "support/test_suite.h"
#include "support/synthetic_frames.h"
#include "visioncore/basics/colour_lut.h"
#include "visioncore/percepts/percept_set.h"
#include "visioncore/services/stream_runner.h"

#include <QtTest>

#include <QDataStream>
#include <QFile>
#include <QImage>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QRegularExpression>
#include <QSet>

#include <filesystem>
#include <QTemporaryDir>

#include <set>
#include <vector>

namespace {

constexpr int kCliWidth = 64;
constexpr int kCliHeight = 48;
constexpr int kCliFrames = 3;

struct CliOutcome
{
    int status = -1;
    QByteArray out;
    QByteArray err;
};

QString frameName(int i)
{
    return QString("frame_%1.png").arg(i, 6, 10, QChar('0'));
}

/// A LUT that calls every colour green.
fieldsight::ColourLut allGreenLut()
{
    fieldsight::ColourLut lut;
    for (std::size_t i = 0; i < fieldsight::ColourLut::kCells; ++i)
        lut.setCell(i, fieldsight::Colour::Green);
    return lut;
}

QJsonObject parseObject(const QByteArray& bytes)
{
    QJsonParseError error;
    const QJsonDocument doc = QJsonDocument::fromJson(bytes, &error);
    if (error.error != QJsonParseError::NoError)
        qWarning() << "JSON parse error:" << error.errorString() << bytes.left(400);
    return doc.object();
}

QJsonObject readObject(const QString& path)
{
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly))
        return {};
    return parseObject(file.readAll());
}

} // namespace

class TestCli : public QObject
{
    Q_OBJECT

private:
    QTemporaryDir m_dir;
    QString m_stream; ///< kCliFrames solid-green PNGs and default.lut

    /// Runs the executable; `without_display` removes DISPLAY, WAYLAND_DISPLAY and
    /// QT_QPA_PLATFORM from its environment.
    CliOutcome fieldsight(const QStringList& args, bool without_display = false)
    {
        QProcess process;
        if (without_display) {
            QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
            for (const char* name : {"DISPLAY", "WAYLAND_DISPLAY", "QT_QPA_PLATFORM"})
                env.remove(name);
            process.setProcessEnvironment(env);
        }
        process.setWorkingDirectory(m_dir.path());
        process.start(QStringLiteral(FIELDSIGHT_EXE), args);
        CliOutcome o;
        if (!process.waitForFinished(120000)) {
            process.kill();
            process.waitForFinished();
            return o;
        }
        o.status = process.exitStatus() == QProcess::NormalExit ? process.exitCode() : -1;
        o.out = process.readAllStandardOutput();
        o.err = process.readAllStandardError();
        return o;
    }

    QString path(const QString& name) const { return m_dir.filePath(name); }

    void makeStream(const QString& folder, bool with_lut, int frames = kCliFrames)
    {
        QVERIFY(QDir().mkpath(folder));
        for (int i = 0; i < frames; ++i) {
            QImage image(kCliWidth, kCliHeight, QImage::Format_RGB888);
            image.fill(QColor(40, 150 + 10 * i, 40));
            QVERIFY(image.save(folder + "/" + frameName(i), "PNG"));
        }
        if (with_lut)
            QVERIFY(allGreenLut().save((folder + "/default.lut").toStdString()).ok());
    }

    /// Checks the one-line error contract: non-empty, one line, "fieldsight: " prefix.
    static void verifyOneLineError(const CliOutcome& o, const QString& must_contain)
    {
        const QString err = QString::fromLocal8Bit(o.err).trimmed();
        QVERIFY2(!err.isEmpty(), "no message on stderr");
        QVERIFY2(!err.contains('\n'), qPrintable("more than one line: " + err));
        QVERIFY2(err.startsWith("fieldsight: "), qPrintable(err));
        QVERIFY2(err.contains(must_contain), qPrintable(err + " does not name " + must_contain));
    }

    /// A frame with its timings removed, to compare runs.
    static QJsonObject withoutTimes(QJsonObject frame)
    {
        frame.remove("time_ms");
        return frame;
    }

private slots:
    void initTestCase()
    {
        QVERIFY(m_dir.isValid());
        QVERIFY2(QFileInfo::exists(QStringLiteral(FIELDSIGHT_EXE)), FIELDSIGHT_EXE);
        m_stream = path("stream");
        makeStream(m_stream, true);
    }

    void missingStreamExitsTwoNamingIt()
    {
        const QString missing = path("no_such_stream");
        const CliOutcome o = fieldsight({"run", missing});
        QCOMPARE(o.status, 2);
        verifyOneLineError(o, missing);
        QVERIFY(!QFileInfo::exists(path("fieldsight-results.json")));
    }

    void wrongSizeLutExitsTwoNamingIt()
    {
        const QString lut = path("short.lut");
        QFile file(lut);
        QVERIFY(file.open(QIODevice::WriteOnly));
        file.write(QByteArray(1000, '\x02'));
        file.close();
        const CliOutcome o = fieldsight({"run", m_stream, "--lut", lut, "--out", path("x.json")});
        QCOMPARE(o.status, 2);
        verifyOneLineError(o, lut);
        QVERIFY(!QFileInfo::exists(path("x.json")));
    }

    void noCommandWritesOverWhatItReads()
    {
        // The venue trial's cases (issue 21): each refused with exit 2 naming both paths, every
        // input byte for byte as it was, through a link and `..` too.
        const QString s = path("kept");
        makeStream(s, true);
        QFile truth(s + "/annotations.json");
        QVERIFY(truth.open(QIODevice::WriteOnly));
        truth.write("{\"format\": \"fieldsight-annotations/1\", \"frames\": {}}\n");
        truth.close();
        QVERIFY(QFile::link(s, path("kept_link")));
        const auto bytes = [](const QString& file) {
            QFile f(file);
            return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
        };
        QStringList files = QDir(s).entryList(QDir::Files);
        std::map<QString, QByteArray> before;
        for (const QString& f : files)
            before[f] = bytes(s + "/" + f);
        const QList<QStringList> cases{
            {"run", s, "--render", s},
            {"run", s, "--render", path("kept_link")},
            {"run", s, "--out", s + "/annotations.json"},
            {"run", s, "--out", s + "/../kept/default.lut"},
            {"eval", s, "--json", s + "/annotations.json"},
            {"lut", "convert", s + "/default.lut", path("kept_link") + "/default.lut"},
            {"lut", "build", s, "--out", s + "/frame_000000.png"},
        };
        for (const QStringList& args : cases) {
            const CliOutcome o = fieldsight(args);
            QVERIFY2(o.status == 2, qPrintable(args.join(' ') + ": exit " +
                                               QString::number(o.status) + " " + o.err));
            verifyOneLineError(o, "nothing was written");
            QCOMPARE(QDir(s).entryList(QDir::Files), files);
            for (const QString& f : files)
                QVERIFY2(bytes(s + "/" + f) == before[f], qPrintable(args.join(' ') + ": " + f));
        }
        // synth writes only into a new, empty or its own earlier folder, and replaces that whole.
        const CliOutcome onto = fieldsight({"synth", "--frames", "2", "--out", s});
        QCOMPARE(onto.status, 2);
        verifyOneLineError(onto, "not an earlier synth output");
        for (const QString& f : files)
            QVERIFY2(bytes(s + "/" + f) == before[f], qPrintable(f));
        const QString own = path("own_synth");
        // Small frames: the rule is tested, not the renderer (slow under the sanitizers).
        const QStringList small{"--width", "64", "--height", "48"};
        QCOMPARE(fieldsight(QStringList{"synth", "--frames", "3", "--out", own} + small).status, 0);
        QCOMPARE(fieldsight(QStringList{"synth", "--frames", "2", "--out", own} + small).status, 0);
        QCOMPARE(QDir(own).entryList({"frame_*.png"}, QDir::Files).size(), 2); // nothing mixed

        // A new file beside the frames is still fine.
        const CliOutcome ok = fieldsight({"run", s, "--out", s + "/results.json"});
        QCOMPARE(ok.status, 0);
        QVERIFY(QFileInfo::exists(s + "/results.json"));
    }

    void streamWithoutLutExitsTwo()
    {
        const QString bare = path("bare");
        makeStream(bare, false);
        const CliOutcome o = fieldsight({"run", bare, "--out", path("bare.json")});
        QCOMPARE(o.status, 2);
        verifyOneLineError(o, "no LUT");
    }

    void unknownSkipStageExitsTwo()
    {
        const CliOutcome o = fieldsight({"run", m_stream, "--skip", "ball,wormholes"});
        QCOMPARE(o.status, 2);
        verifyOneLineError(o, "wormholes");
    }

    void badNumberExitsTwo()
    {
        CliOutcome o = fieldsight({"run", m_stream, "--threads", "many"});
        QCOMPARE(o.status, 2);
        verifyOneLineError(o, "--threads");
        o = fieldsight({"bench", m_stream, "--repeat", "0"});
        QCOMPARE(o.status, 2);
        verifyOneLineError(o, "--repeat");
    }

    void unknownCommandAndMissingArgumentExitTwo()
    {
        CliOutcome o = fieldsight({"frobnicate"});
        QCOMPARE(o.status, 2);
        verifyOneLineError(o, "frobnicate");
        o = fieldsight({"run"});
        QCOMPARE(o.status, 2);
        verifyOneLineError(o, "run");
        o = fieldsight({"help"});
        QCOMPARE(o.status, 0);
        QVERIFY(o.out.contains("fieldsight run"));
    }

    /// The options `--help` of the command `words` lists, and checks its usage line names it.
    QSet<QString> helpOptions(const QStringList& words)
    {
        const CliOutcome o = fieldsight(words + QStringList{"--help"});
        const QString help = QString::fromUtf8(o.out);
        const QString command = words.join(' ');
        [&] {
            QCOMPARE(o.status, 0);
            QVERIFY2(help.startsWith("Usage: fieldsight " + command + " [options]"),
                     qPrintable(help.section('\n', 0, 0)));
            QVERIFY2(!help.contains("The command."), qPrintable(command));
        }();
        QSet<QString> options;
        static const QRegularExpression option(R"(^\s+(?:-\w, )?--([a-z][a-z-]*))",
                                               QRegularExpression::MultilineOption);
        for (auto it = option.globalMatch(help); it.hasNext();)
            options.insert(it.next().captured(1));
        options.remove("help");
        return options;
    }

    void theOverviewAndTheReadmeNameEveryOptionAsEachCommandsHelpDoes()
    {
        // The overview's block of each command: its line and the indented lines after it.
        const QString usage = QString::fromUtf8(fieldsight({"help"}).out);
        std::map<QString, QString> blocks;
        QString current;
        for (const QString& line : usage.split('\n')) {
            if (line.startsWith("  fieldsight ")) {
                QStringList words;
                for (const QString& w : line.mid(13).split(' ', Qt::SkipEmptyParts)) {
                    if (!w.at(0).isLower())
                        break;
                    words << w;
                }
                current = words.join(' ');
                if (current == "help")
                    current.clear();
            } else if (!line.startsWith("     ")) {
                current.clear();
            }
            if (!current.isEmpty())
                blocks[current] += line + "\n";
        }
        QVERIFY2(blocks.size() >= 11, qPrintable(usage));
        static const QRegularExpression flag(R"(--([a-z][a-z-]*))");
        std::map<QString, QSet<QString>> options;
        for (const auto& [command, block] : blocks) {
            options[command] = helpOptions(command.split(' '));
            QSet<QString> named;
            for (auto it = flag.globalMatch(block); it.hasNext();)
                named.insert(it.next().captured(1));
            QVERIFY2(named == options[command],
                     qPrintable(command + ": the overview names " +
                                QStringList(named.values()).join(',') + ", --help " +
                                QStringList(options[command].values()).join(',')));
        }
        // `lut --help` and `annotations --help` are the overview's lines.
        for (const QString group : {"lut", "annotations"}) {
            const QString help = QString::fromUtf8(fieldsight({group, "--help"}).out);
            for (const auto& [command, block] : blocks)
                if (command.startsWith(group + " "))
                    QVERIFY2(help.contains(block), qPrintable(group + ": " + help));
        }
        // Every option the README gives a command is one the command has.
        QFile readme(QStringLiteral(FIELDSIGHT_SOURCE_DIR "/README.md"));
        QVERIFY(readme.open(QIODevice::ReadOnly));
        std::size_t checked = 0;
        for (const QString& line : QString::fromUtf8(readme.readAll()).split('\n'))
            for (const QString& span : line.split('`')) {
                const qsizetype at = span.indexOf("fieldsight ");
                if (at < 0)
                    continue;
                const QString rest = span.mid(at + 11);
                QString command;
                for (const auto& [c, o] : options)
                    if ((rest == c || rest.startsWith(c + " ")) && c.size() > command.size())
                        command = c;
                if (command.isEmpty())
                    continue;
                for (auto it = flag.globalMatch(rest); it.hasNext(); ++checked) {
                    const QString f = it.next().captured(1);
                    QVERIFY2(f == "help" || options[command].contains(f),
                             qPrintable("README: '" + span + "': " + command + " has no --" + f));
                }
            }
        QVERIFY2(checked >= 12, qPrintable(QString::number(checked)));
    }

    void truncatedStrmExitsTwo()
    {
        // One record: header, then only half of the 4-byte pixels (SPEC §4).
        const QString strm = path("cut.strm");
        QFile file(strm);
        QVERIFY(file.open(QIODevice::WriteOnly));
        QDataStream s(&file);
        s.setByteOrder(QDataStream::LittleEndian);
        s.setFloatingPointPrecision(QDataStream::DoublePrecision);
        s.writeRawData("IMAG", 4);
        s << qint32(1) << qint32(kCliWidth) << qint32(kCliHeight) << double(0.0) << quint8(0);
        const QByteArray pixels(kCliWidth * kCliHeight * 4 / 2, '\x80');
        s.writeRawData(pixels.constData(), int(pixels.size()));
        file.close();
        const CliOutcome o = fieldsight(
            {"run", strm, "--lut", m_stream + "/default.lut", "--out", path("cut.json")});
        QCOMPARE(o.status, 2);
        verifyOneLineError(o, strm);
    }

    void unreadableImageExitsTwoNamingIt()
    {
        const QString broken = path("broken");
        makeStream(broken, true);
        QFile file(broken + "/" + frameName(1));
        QVERIFY(file.open(QIODevice::WriteOnly | QIODevice::Truncate));
        file.write("this is not a PNG");
        file.close();
        const CliOutcome o = fieldsight({"run", broken, "--out", path("broken.json")});
        QCOMPARE(o.status, 2);
        verifyOneLineError(o, frameName(1));
    }

    void emptyFolderExitsTwo()
    {
        const QString empty = path("empty");
        QVERIFY(QDir().mkpath(empty));
        const CliOutcome o = fieldsight({"run", empty, "--lut", m_stream + "/default.lut"});
        QCOMPARE(o.status, 2);
        verifyOneLineError(o, empty);
    }

    void runWritesResultsJson()
    {
        const QString out = path("results.json");
        const CliOutcome o = fieldsight({"run", m_stream, "--out", out});
        QCOMPARE(o.status, 0);
        QVERIFY2(o.err.isEmpty(), o.err.constData());

        const QJsonObject doc = readObject(out);
        QCOMPARE(doc.value("format").toString(), QString("fieldsight-results/1"));
        QCOMPARE(doc.value("stream").toString(), m_stream);
        QVERIFY(doc.value("lut").toString().endsWith("default.lut"));
        QCOMPARE(doc.value("width").toInt(), kCliWidth);
        QCOMPARE(doc.value("height").toInt(), kCliHeight);

        const QJsonArray frames = doc.value("frames").toArray();
        QCOMPARE(frames.size(), kCliFrames);
        double total_sum = 0;
        for (int i = 0; i < kCliFrames; ++i) {
            const QJsonObject f = frames[i].toObject();
            QCOMPARE(f.value("index").toInt(-1), i);
            QCOMPARE(f.value("name").toString(), frameName(i));
            const QJsonObject time = f.value("time_ms").toObject();
            QVERIFY(time.value("total").isDouble());
            QVERIFY(time.value("total").toDouble() >= 0);
            for (const char* stage : {"green_horizon", "scanlines", "transitions", "goalposts",
                                      "field_lines", "ball", "obstacles"})
                QVERIFY2(time.value(stage).isDouble(), stage);
            total_sum += time.value("total").toDouble();
            for (const char* list : {"balls", "goalposts", "obstacles", "field_lines"})
                QVERIFY2(f.value(list).isArray(), list);
            // The hull runs from x = 0 to x = width-1 (SPEC §5.1).
            const QJsonArray hull = f.value("green_horizon").toArray();
            QVERIFY(!hull.isEmpty());
            QCOMPARE(hull.first().toArray().at(0).toDouble(), 0.0);
            QCOMPARE(hull.last().toArray().at(0).toDouble(), double(kCliWidth - 1));
            // An all-green frame has no ball, goal or obstacle.
            QCOMPARE(f.value("balls").toArray().size(), 0);
            QCOMPARE(f.value("goalposts").toArray().size(), 0);
        }
        const QJsonObject summary = doc.value("summary").toObject();
        QCOMPARE(summary.value("frames").toInt(), kCliFrames);
        QVERIFY(qAbs(summary.value("mean_ms").toDouble() - total_sum / kCliFrames) < 1e-3);
        QVERIFY(summary.value("std_ms").toDouble() >= 0);
        QCOMPARE(summary.value("stage_mean_ms").toObject().size(), 7);
        // The one-line summary names the output.
        QVERIFY(o.out.contains(out.toLocal8Bit()));
    }

    void unwritableOutputIsAFailureWhileRunning()
    {
        const QString out = path("no_such_folder/results.json");
        const CliOutcome o = fieldsight({"run", m_stream, "--out", out});
        QCOMPARE(o.status, 1);
        verifyOneLineError(o, out);
    }

    void runWritesToStandardOutputWithDash()
    {
        const CliOutcome o = fieldsight({"run", m_stream, "--out", "-", "--limit", "2"});
        QCOMPARE(o.status, 0);
        const QJsonObject doc = parseObject(o.out);
        QCOMPARE(doc.value("format").toString(), QString("fieldsight-results/1"));
        QCOMPARE(doc.value("frames").toArray().size(), 2);
        QCOMPARE(doc.value("summary").toObject().value("frames").toInt(), 2);
        QVERIFY(!QFileInfo::exists(path("fieldsight-results.json")));
    }

    void skippedStageListIsAbsent()
    {
        const QString out = path("skip.json");
        const CliOutcome o = fieldsight({"run", m_stream, "--skip", "ball", "--out", out});
        QCOMPARE(o.status, 0);
        const QJsonObject doc = readObject(out);
        const QJsonArray frames = doc.value("frames").toArray();
        QCOMPARE(frames.size(), kCliFrames);
        for (const QJsonValue& v : frames) {
            const QJsonObject f = v.toObject();
            QVERIFY(!f.contains("balls"));
            QVERIFY(!f.value("time_ms").toObject().contains("ball"));
            QVERIFY(f.value("goalposts").isArray());
            QVERIFY(f.value("obstacles").isArray());
        }
        QVERIFY(
            !doc.value("summary").toObject().value("stage_mean_ms").toObject().contains("ball"));
    }

    void threadsGiveTheSameFramesInOrder()
    {
        QCOMPARE(fieldsight({"run", m_stream, "--out", path("t1.json")}).status, 0);
        QCOMPARE(fieldsight({"run", m_stream, "--threads", "3", "--out", path("t3.json")}).status,
                 0);
        const QJsonArray one = readObject(path("t1.json")).value("frames").toArray();
        const QJsonArray three = readObject(path("t3.json")).value("frames").toArray();
        QCOMPARE(one.size(), kCliFrames);
        QCOMPARE(three.size(), kCliFrames);
        for (int i = 0; i < kCliFrames; ++i)
            QCOMPARE(withoutTimes(three[i].toObject()), withoutTimes(one[i].toObject()));
    }

    void benchPrintsTableAndJson()
    {
        const QString json = path("bench.json");
        const CliOutcome o = fieldsight({"bench", m_stream, "--repeat", "2", "--json", json});
        QCOMPARE(o.status, 0);
        QVERIFY(o.out.contains("pipeline / floor"));
        QVERIFY(o.out.contains("pipeline / baseline"));
        const QJsonObject doc = readObject(json);
        QCOMPARE(doc.value("format").toString(), QString("fieldsight-bench/1"));
        QCOMPARE(doc.value("frames").toInt(), kCliFrames);
        QCOMPARE(doc.value("repeat").toInt(), 2);
        const QJsonObject pipeline = doc.value("pipeline").toObject();
        QCOMPARE(pipeline.value("samples").toInt(), 2 * kCliFrames);
        QVERIFY(pipeline.value("mean_ms").toDouble() > 0);
        QCOMPARE(pipeline.value("stages").toObject().size(), 7);
        QCOMPARE(doc.value("floor").toObject().value("samples").toInt(), 2 * kCliFrames);
        QCOMPARE(doc.value("baseline").toObject().value("samples").toInt(), 2 * kCliFrames);
        QVERIFY(doc.value("baseline").toObject().value("mean_ms").toDouble() > 0);
        QVERIFY(doc.value("ratios").toObject().value("pipeline_over_floor").toDouble() > 0);
        QVERIFY(doc.value("ratios").toObject().value("pipeline_over_baseline").toDouble() > 0);
    }

    void benchOverSeveralStreamsPrintsTableOne()
    {
        const QString lab_a = path("lab_a");
        const QString lab_b = path("lab_b");
        makeStream(lab_a, true, 3);
        makeStream(lab_b, true, 2);
        const QString json = path("bench_two.json");
        const CliOutcome o = fieldsight({"bench", lab_a, lab_b, "--repeat", "2", "--json", json});
        QCOMPARE(o.status, 0);
        QVERIFY2(o.err.isEmpty(), o.err.constData());

        // Table 1: a row per stream named by its folder, then "combined" over all frames.
        const QStringList lines = QString::fromLocal8Bit(o.out).split('\n');
        auto row = [&](const QString& name) {
            for (const QString& line : lines)
                if (line.startsWith(name + ' '))
                    return line.split(' ', Qt::SkipEmptyParts);
            return QStringList();
        };
        QCOMPARE(row("lab_a").value(1), QString("3"));
        QCOMPARE(row("lab_b").value(1), QString("2"));
        QCOMPARE(row("combined").value(1), QString("5"));
        // The per-stage table: one column per stream and one for all of them.
        QVERIFY(o.out.contains("by stage"));
        for (const char* stage : {"green_horizon", "scanlines", "transitions", "goalposts",
                                  "field_lines", "ball", "obstacles", "pipeline"}) {
            const QStringList cells = row(stage);
            QVERIFY2(cells.size() == 4, qPrintable(QString(stage) + ": " + cells.join(' ')));
            for (int c = 1; c < 4; ++c) {
                bool ok = false;
                QVERIFY2(cells[c].toDouble(&ok) >= 0 && ok, qPrintable(cells.join(' ')));
            }
        }

        const QJsonObject doc = readObject(json);
        QCOMPARE(doc.value("format").toString(), QString("fieldsight-bench/1"));
        const QJsonArray streams = doc.value("streams").toArray();
        QCOMPARE(streams.size(), 2);
        const QJsonObject a = streams[0].toObject();
        const QJsonObject b = streams[1].toObject();
        QCOMPARE(a.value("name").toString(), QString("lab_a"));
        QCOMPARE(a.value("stream").toString(), lab_a);
        QCOMPARE(a.value("frames").toInt(), 3);
        QCOMPARE(a.value("pipeline").toObject().value("samples").toInt(), 6);
        QCOMPARE(b.value("name").toString(), QString("lab_b"));
        QCOMPARE(b.value("frames").toInt(), 2);
        QVERIFY(b.value("lut").toString().startsWith(lab_b)); // each stream's own LUT

        const QJsonObject combined = doc.value("combined").toObject();
        QCOMPARE(combined.value("frames").toInt(), 5);
        const QJsonObject pipeline = combined.value("pipeline").toObject();
        QCOMPARE(pipeline.value("samples").toInt(), 10);
        QCOMPARE(pipeline.value("stages").toObject().size(), 7);
        // Pooled over frames: the mean weights each stream by its runs (6 and 4).
        const double mean_a = a.value("pipeline").toObject().value("mean_ms").toDouble();
        const double mean_b = b.value("pipeline").toObject().value("mean_ms").toDouble();
        QVERIFY(qAbs(pipeline.value("mean_ms").toDouble() - (6 * mean_a + 4 * mean_b) / 10) < 2e-5);
        QCOMPARE(combined.value("floor").toObject().value("samples").toInt(), 10);
        QCOMPARE(combined.value("baseline").toObject().value("samples").toInt(), 10);
        QVERIFY(combined.value("ratios").toObject().value("pipeline_over_floor").toDouble() > 0);
    }

    void benchNamesABadSecondStream()
    {
        const QString good = path("bench_good");
        makeStream(good, true, 2);
        const QString missing = path("bench_missing");
        CliOutcome o = fieldsight({"bench", good, missing});
        QCOMPARE(o.status, 2);
        verifyOneLineError(o, missing);
        QVERIFY2(o.out.isEmpty(), o.out.constData()); // checked before anything is timed

        // A second stream without a LUT is named too.
        const QString bare = path("bench_bare");
        makeStream(bare, false, 1);
        o = fieldsight({"bench", good, bare});
        QCOMPARE(o.status, 2);
        verifyOneLineError(o, bare);
    }

    void pooledTimingsEqualTheConcatenatedSamples()
    {
        using fieldsight::TimingStats;
        const std::vector<double> a = {1.0, 2.0, 4.0};
        const std::vector<double> b = {10.0, 12.0};
        std::vector<double> all = a;
        all.insert(all.end(), b.begin(), b.end());
        const TimingStats pooled = TimingStats::pooled({TimingStats::of(a), TimingStats::of(b)});
        const TimingStats direct = TimingStats::of(all);
        QCOMPARE(pooled.samples, std::size_t(5));
        QVERIFY(qAbs(pooled.mean_ms - 5.8) < 1e-12);
        QVERIFY(qAbs(pooled.std_ms - direct.std_ms) < 1e-12);
        // The mean of the means would be 6.67; the streams alone have stds 1.25 and 1.0.
        QVERIFY(qAbs(pooled.std_ms - 4.4) < 1e-12);
        QCOMPARE(TimingStats::pooled({}).samples, std::size_t(0));
    }

    void evalScoresOnlyDoneFrames()
    {
        // Frame 0: a ball the all-green frame cannot show (a miss); frame 1: nothing; frame 2 is
        // not done, so its ball is not counted.
        const QByteArray truth = R"({"format": "fieldsight-annotations/1", "frames": {
            "frame_000000.png": {"done": true, "balls": [{"x": 20, "y": 30, "radius": 4}],
                                 "field_boundary": [[0, 0], [63, 0]]},
            "frame_000001.png": {"done": true, "field_boundary": [[0, 0], [63, 0]]},
            "frame_000002.png": {"done": false, "balls": [{"x": 20, "y": 30, "radius": 4}]}}})";
        const QString truth_path = path("truth.json");
        QFile file(truth_path);
        QVERIFY(file.open(QIODevice::WriteOnly));
        file.write(truth);
        file.close();

        const QString json = path("eval.json");
        const CliOutcome o = fieldsight({"eval", m_stream, "--truth", truth_path, "--json", json});
        QCOMPARE(o.status, 0);
        QVERIFY(o.out.contains("precision = 1 when TP+FP = 0"));
        const QJsonObject doc = readObject(json);
        QCOMPARE(doc.value("format").toString(), QString("fieldsight-eval/1"));
        QCOMPARE(doc.value("frames").toInt(), 2);
        QCOMPARE(doc.value("frames_not_done").toInt(), 1);
        const QJsonObject ball = doc.value("classes").toObject().value("ball").toObject();
        QCOMPARE(ball.value("tp").toInt(-1), 0);
        QCOMPARE(ball.value("fp").toInt(-1), 0);
        QCOMPARE(ball.value("fn").toInt(-1), 1);
        QCOMPARE(ball.value("precision").toDouble(), 1.0);
        QCOMPARE(ball.value("recall").toDouble(), 0.0);
        QCOMPARE(doc.value("field_boundary").toObject().value("frames").toInt(), 2);
        // The additions of docs/formats.md: reviewed frames, concealed counts, field lines, and
        // the frame with the missed ball (its truth ball 0) as the one disagreement.
        QCOMPARE(doc.value("frames_reviewed").toInt(-1), 0);
        QCOMPARE(ball.value("concealed_found").toInt(-1), 0);
        QVERIFY(doc.value("classes").toObject().contains("field_line"));
        const QJsonArray disagreements = doc.value("disagreements").toArray();
        QCOMPARE(disagreements.size(), 1);
        const QJsonObject miss = disagreements.at(0).toObject();
        QCOMPARE(miss.value("frame").toString(), QString("frame_000000.png"));
        QCOMPARE(miss.value("index").toInt(-1), 0);
        QCOMPARE(miss.value("class").toString(), QString("ball"));
        QCOMPARE(miss.value("missed").toArray(), QJsonArray{0});
        QVERIFY(miss.value("false_detections").toArray().isEmpty());
        QVERIFY(o.out.contains("field line "));

        // A missing truth file is bad input.
        const CliOutcome missing = fieldsight({"eval", m_stream, "--truth", path("nope.json")});
        QCOMPARE(missing.status, 2);
        verifyOneLineError(missing, path("nope.json"));

        // Annotations without a done frame: nothing to score, not a perfect 1.000 (issue 10).
        const QString none_done = path("none_done.json");
        QFile undone(none_done);
        QVERIFY(undone.open(QIODevice::WriteOnly));
        undone.write(R"({"format": "fieldsight-annotations/1", "frames": {
            "frame_000000.png": {"done": false}}})");
        undone.close();
        const CliOutcome nothing = fieldsight({"eval", m_stream, "--truth", none_done});
        QCOMPARE(nothing.status, 2);
        verifyOneLineError(nothing, none_done);
        QVERIFY(nothing.err.contains("nothing to score"));
    }
    void evalRefusesAFrameUnderTwoNamesOrOutsideTheStream()
    {
        // Once scored twice; once scored as this stream's frame_000000.png.
        const std::pair<QByteArray, QString> cases[] = {
            {R"({"frame_000000.png": {"done": true}, "frame_000000": {"done": true}})",
             "name the same frame"},
            {R"({"../lab2/frame_000000.png": {"done": true}})", "path separator"},
            {R"({"frame_000000.png\u0000": {"done": true}})", "frame_000000.png\\0"},
        };
        for (const auto& [frames, reason] : cases) {
            const QString truth = path("named.json");
            QFile file(truth);
            QVERIFY(file.open(QIODevice::WriteOnly | QIODevice::Truncate));
            file.write(R"({"format": "fieldsight-annotations/1", "frames": )" + frames + "}");
            file.close();
            const CliOutcome o = fieldsight({"eval", m_stream, "--truth", truth});
            QCOMPARE(o.status, 2);
            verifyOneLineError(o, truth);
            QVERIFY2(o.err.contains(reason.toUtf8()) && !o.err.contains('\0'), o.err.constData());
        }
    }

    void lutBuildWritesATableFromSamples()
    {
        // The stream's frames are solid green (40, 150 + 10 i, 40): samples of frames 0 and 2.
        const QString samples = path("samples.json");
        QFile file(samples);
        QVERIFY(file.open(QIODevice::WriteOnly));
        file.write(R"({"format": "fieldsight-lut-samples/1", "smoothing": 0, "samples": [
            {"frame": "frame_000000.png", "colour": "green", "polygon": [[0,0],[9,0],[9,9],[0,9]]},
            {"frame": "frame_000002", "colour": "white", "polygon": [[0,0],[19,0],[19,9],[0,9]]}]})");
        file.close();
        const QString out = path("built.lut");
        const QString kept = path("kept_samples.json");
        const CliOutcome o = fieldsight(
            {"lut", "build", m_stream, "--samples", samples, "--out", out, "--save-samples", kept});
        QCOMPARE(o.status, 0);
        QVERIFY2(o.out.contains("2 samples over 2 frames, 300 pixels"), o.out.constData());
        QVERIFY2(o.out.contains("white 1, green 1"), o.out.constData());
        auto lut = fieldsight::ColourLut::load(out.toStdString());
        QVERIFY(lut.ok());
        std::size_t classified = 0;
        for (std::size_t i = 0; i < fieldsight::ColourLut::kCells; ++i)
            classified += lut.value().cell(i) != fieldsight::Colour::Unclassified;
        QCOMPARE(classified, std::size_t(2));
        const QJsonObject saved = readObject(kept);
        QCOMPARE(saved.value("format").toString(), QString("fieldsight-lut-samples/1"));
        QCOMPARE(saved.value("samples").toArray().size(), 2);

        // `lut convert` still works beside it.
        const CliOutcome convert = fieldsight({"lut", "convert", out, path("converted.lut")});
        QCOMPARE(convert.status, 0);
    }

    void lutBuildNamesABadSamplesFile()
    {
        const QString samples = path("bad_samples.json");
        QFile file(samples);
        QVERIFY(file.open(QIODevice::WriteOnly));
        file.write(R"({"format": "fieldsight-lut-samples/1", "samples": [
            {"frame": "frame_000000.png", "colour": "mauve", "polygon": [[0,0],[9,0],[0,9]]}]})");
        file.close();
        const QString out = path("never.lut");
        CliOutcome o = fieldsight({"lut", "build", m_stream, "--samples", samples, "--out", out});
        QCOMPARE(o.status, 2);
        verifyOneLineError(o, samples);
        verifyOneLineError(o, "mauve");
        QVERIFY(!QFileInfo::exists(out));

        // A sample of a frame the stream lacks, no --out, and no annotations: bad input too.
        QVERIFY(file.open(QIODevice::WriteOnly | QIODevice::Truncate));
        file.write(R"({"format": "fieldsight-lut-samples/1", "samples": [
            {"frame": "frame_000042.png", "colour": "green", "polygon": [[0,0],[9,0],[0,9]]}]})");
        file.close();
        o = fieldsight({"lut", "build", m_stream, "--samples", samples, "--out", out});
        QCOMPARE(o.status, 2);
        verifyOneLineError(o, "frame_000042.png");
        o = fieldsight({"lut", "build", m_stream, "--samples", samples});
        QCOMPARE(o.status, 2);
        verifyOneLineError(o, "--out");
        o = fieldsight({"lut", "build", m_stream, "--out", out});
        QCOMPARE(o.status, 2);
        verifyOneLineError(o, "annotations.json");
        o = fieldsight({"lut", "frobnicate"});
        QCOMPARE(o.status, 2);
        verifyOneLineError(o, "frobnicate");
    }

    void lutBuildFromAnnotationsWithoutSamples()
    {
        const QString out = path("lab2.lut");
        const CliOutcome o = fieldsight(
            {"lut", "build", QString::fromStdString(fieldsight::test::sampleStreamsDir() + "/lab2"),
             "--out", out});
        QCOMPARE(o.status, 0);
        QVERIFY2(o.out.contains("over 30 frames"), o.out.constData());
        auto lut = fieldsight::ColourLut::load(out.toStdString());
        QVERIFY(lut.ok());
        // lab2's field, lines, posts (yellow) and ball all got cells.
        std::set<fieldsight::Colour> classes;
        for (std::size_t i = 0; i < fieldsight::ColourLut::kCells; ++i)
            classes.insert(lut.value().cell(i));
        QCOMPARE(classes, (std::set<fieldsight::Colour>{
                              fieldsight::Colour::Unclassified, fieldsight::Colour::White,
                              fieldsight::Colour::Green, fieldsight::Colour::Orange,
                              fieldsight::Colour::Yellow}));
    }

    void renderWritesOnePngPerFrameWithTheTruth()
    {
        // The process has no display and no platform plugin set: the painter needs neither.
        const QString dir = path("render");
        const CliOutcome o = fieldsight(
            {"run", QString::fromStdString(fieldsight::test::sampleStreamsDir() + "/lab1"),
             "--limit", "3", "--out", path("render.json"), "--render", dir, "--layers", "truth",
             "--scale", "1"},
            true);
        QCOMPARE(o.status, 0);
        const QStringList pngs = QDir(dir).entryList({"*.png"}, QDir::Files, QDir::Name);
        QCOMPARE(pngs, (QStringList{"frame_000000.png", "frame_000001.png", "frame_000002.png"}));
        // lab1's first frame has a true field boundary, drawn thin in the truth colour.
        const QImage image(dir + "/frame_000000.png");
        QCOMPARE(image.size(), QSize(320, 240));
        const QImage frame(QString::fromStdString(fieldsight::test::sampleStreamsDir() +
                                                  "/lab1/frame_000000.png"));
        QCOMPARE(frame.size(), image.size());
        const QRgb ink = qRgb(fieldsight::kTruthColour.r, fieldsight::kTruthColour.g,
                              fieldsight::kTruthColour.b);
        int truth_pixels = 0; // in the truth colour where the frame itself is not
        for (int y = 0; y < image.height(); ++y)
            for (int x = 0; x < image.width(); ++x)
                truth_pixels += image.pixel(x, y) == ink && frame.pixel(x, y) != ink;
        QVERIFY2(truth_pixels >= 320, qPrintable(QString::number(truth_pixels)));

        // --layers without --render is a usage error, an unknown layer bad input.
        QCOMPARE(fieldsight({"run", m_stream, "--layers", "truth"}).status, 2);
        const CliOutcome bad = fieldsight({"run", m_stream, "--render", dir, "--layers", "nope"});
        QCOMPARE(bad.status, 2);
        verifyOneLineError(bad, "nope");
    }

    void paramsFileAndSetApplyTogether()
    {
        const QString params = path("params.json");
        QFile file(params);
        QVERIFY(file.open(QIODevice::WriteOnly));
        file.write(R"({"format": "fieldsight-params/1", "stages": {"ball": {"min_radius": 500}}})");
        file.close();
        const CliOutcome bad = fieldsight({"run", m_stream, "--params", params});
        QCOMPARE(bad.status, 2);
        verifyOneLineError(bad, params); // the message names the file
        // --set wins over the file.
        const CliOutcome good = fieldsight(
            {"run", m_stream, "--params", params, "--set", "ball.min_radius=3", "--out", "-"});
        QCOMPARE(good.status, 0);
    }

    void numericOptionsOutOfRangeAreRefusedNotTruncated()
    {
        // 4294967312 would become 16 through an int (issue 10).
        const CliOutcome wide = fieldsight({"synth", "--width", "4294967312", "--out", path("w")});
        QCOMPARE(wide.status, 2);
        QVERIFY2(wide.err.contains("--width: expected a whole number from 16 to 8192, got "
                                   "'4294967312'"),
                 qPrintable(wide.err));
        QVERIFY(!QFileInfo::exists(path("w")));
        const CliOutcome frames = fieldsight({"run", m_stream, "--limit", "99999999999"});
        QCOMPARE(frames.status, 2);
        QVERIFY(frames.err.contains("--limit"));
    }

    void librariesPrintNothingOfTheirOwn()
    {
        // A file no video back end can open (GStreamer and FFmpeg used to print their own lines)
        // and a PNG whose header is damaged (libpng used to print "libpng error"): one line each.
        const QString video = path("noise.avi");
        QFile noise(video);
        QVERIFY(noise.open(QIODevice::WriteOnly));
        for (int i = 0; i < 500; ++i)
            noise.write(QByteArray::number(i * 7919 % 10007).repeated(3));
        noise.close();
        const CliOutcome bad_video = fieldsight({"run", video, "--out", path("v.json")});
        QCOMPARE(bad_video.status, 2);
        verifyOneLineError(bad_video, video);

        const QString folder = path("damaged_png");
        makeStream(folder, true, 1);
        const QString frame = folder + "/" + frameName(0);
        QFile png(frame);
        QVERIFY(png.open(QIODevice::ReadWrite));
        png.seek(20); // inside the header's height: its checksum no longer matches
        png.write("\x7f", 1);
        png.close();
        const CliOutcome bad_png = fieldsight({"run", folder, "--out", path("p.json")});
        QCOMPARE(bad_png.status, 2);
        verifyOneLineError(bad_png, frame);
    }

    void withoutADisplayTheWindowSaysHowToRunIt()
    {
        // Qt used to abort with four lines about platform plugins (and a core dump).
        for (const QStringList& args : {QStringList{"gui", m_stream}, QStringList{}}) {
            const CliOutcome o = fieldsight(args, true);
            QCOMPARE(o.status, 2);
            verifyOneLineError(o, "no display");
            QVERIFY2(o.err.contains("xvfb-run") && o.err.contains("QT_QPA_PLATFORM=offscreen"),
                     o.err.constData());
        }
    }

    void brokenFrameEntriesAreWarnedOfOnStderr()
    {
        // A dangling link named as a frame used to be skipped without a word.
        const QString folder = path("with_broken_entry");
        makeStream(folder, true, 2);
        QVERIFY(QFile::link(folder + "/gone.png", folder + "/frame_000005.png"));
        const CliOutcome o = fieldsight({"run", folder, "--out", path("broken.json")});
        QCOMPARE(o.status, 0);
        QCOMPARE(QString::fromLocal8Bit(o.err).trimmed(),
                 "fieldsight: warning: " + folder +
                     "/frame_000005.png: skipped, a link to a file that does not exist");
        QCOMPARE(readObject(path("broken.json")).value("frames").toArray().size(), 2);
    }

    void aFrameNameThatIsNotUtf8IsWrittenNotThrown()
    {
        // A frame file named in Latin-1 ("caf\xe9.png"): the results JSON is still written,
        // valid, with U+FFFD for the bad byte (it used to end in a raw library exception).
        const QString folder = path("latin1");
        makeStream(folder, true, 1);
        const std::string from = (folder + "/" + frameName(0)).toStdString();
        const std::string to = folder.toStdString() + "/caf\xe9.png";
        std::filesystem::rename(from, to);
        const QString json = path("latin1.json");
        const CliOutcome o = fieldsight({"run", folder, "--out", json});
        QCOMPARE(o.status, 0);
        const QJsonObject doc = readObject(json);
        const QJsonArray frames = doc.value("frames").toArray();
        QCOMPARE(frames.size(), 1);
        QCOMPARE(frames[0].toObject().value("name").toString(), QString::fromUtf8("caf\uFFFD.png"));
    }
};

FIELDSIGHT_TEST_SUITE(TestCli, Core)

#include "test_cli.moc"
