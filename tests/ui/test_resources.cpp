// What ships with the window (resources/): the application icon and desktop id, every tool's
// icon found by its id, the default parameters file kept equal to the stage registry's
// defaults, and the installed sample stream found from the installed executable.
#include "support/test_suite.h"
#include "support/fake_tool.h"
#include "ui/actions/session_files.h"
#include "ui/application.h"
#include "ui/document/editing_session.h"
#include "ui/tools/tool_manager.h"
#include "visioncore/framework/controller.h"
#include "visioncore/framework/param_set.h"

#include <QAction>
#include <QApplication>
#include <QDir>
#include <QFile>
#include <QIcon>
#include <QImage>
#include <QSaveFile>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QtTest>

using namespace fieldsight;
using namespace fieldsight::ui;
using fieldsight::test::FakeTool;

namespace {

/// How many pixels of `icon` drawn at `side` px are opaque, and how many of those are green
/// (green well above red and blue).
struct Coverage
{
    int opaque = 0;
    int green = 0;
};

Coverage coverageOf(const QIcon& icon, int side)
{
    const QImage image = icon.pixmap(side, side).toImage().convertToFormat(QImage::Format_ARGB32);
    Coverage c;
    for (int y = 0; y < image.height(); ++y)
        for (int x = 0; x < image.width(); ++x) {
            const QColor p = image.pixelColor(x, y);
            if (p.alpha() < 128)
                continue;
            ++c.opaque;
            if (p.green() > p.red() + 40 && p.green() > p.blue() + 40)
                ++c.green;
        }
    return c;
}

QString sourcePath(const QString& relative)
{
    return QStringLiteral(FIELDSIGHT_SOURCE_DIR "/") + relative;
}

/// Every parameter of `pipeline` at its default, as a parameter set.
ParamSet registryDefaults(const Pipeline& pipeline)
{
    ParamSet defaults;
    for (const StageDescriptor& stage : pipeline.descriptors())
        for (const ParamInfo& param : stage.params)
            defaults.set(stage.info.id, param.name, param.default_value);
    return defaults;
}

} // namespace

class TestResources : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase() { QStandardPaths::setTestModeEnabled(true); }

    void theApplicationHasItsIconAndDesktopId()
    {
        identifyApplication();
        QCOMPARE(applicationId(), QStringLiteral("io.github.fieldsight.Fieldsight"));
        QCOMPARE(QGuiApplication::desktopFileName(), applicationId());
        QCOMPARE(QApplication::applicationDisplayName(), QStringLiteral("Fieldsight"));
        // The desktop entry and metainfo that name the id are the files installed by that name.
        QVERIFY(QFile::exists(sourcePath("resources/" + applicationId() + ".desktop")));
        QVERIFY(QFile::exists(sourcePath("resources/" + applicationId() + ".metainfo.xml")));

        // The window icon is drawn (the SVG icon engine is there) and is mostly the green field.
        const Coverage c = coverageOf(QApplication::windowIcon(), 64);
        QVERIFY2(c.opaque > 64 * 64 / 2,
                 qPrintable(QStringLiteral("%1 opaque pixels of 4096: is the Qt SVG plugin "
                                           "(libqt6svg6) installed?")
                                .arg(c.opaque)));
        QVERIFY2(c.green > c.opaque / 3, qPrintable(QString::number(c.green)));
        QCoreApplication::setOrganizationName("FieldsightTest"); // settings stay the test's
        QCoreApplication::setApplicationName("test_resources");
    }

    void everyToolGetsTheIconNamedByItsId()
    {
        EditingSession session;
        std::vector<ToolFactory> tools = standardTools();
        tools.push_back(toolFactory<FakeTool>()); // a tool with no icon file
        ToolManager manager(session, tools);
        QStringList ids;
        for (QAction* action : manager.actions()) {
            const QString id = action->data().toString();
            ids << id;
            if (id == QLatin1String("fake")) {
                QVERIFY(action->icon().isNull());
                continue;
            }
            QVERIFY2(!action->icon().isNull(), qPrintable(id));
            const Coverage c = coverageOf(action->icon(), 24);
            QVERIFY2(c.opaque > 40, qPrintable(QStringLiteral("%1: %2").arg(id).arg(c.opaque)));
        }
        // The annotation tools follow the LUT tools, one per kind drawn by hand.
        QStringList expected{"pan", "click", "brush", "erase", "wand", "sample"};
        for (const PerceptKind* kind : session.annotations().kinds())
            if (kind->form != ShapeForm::None)
                expected << QStringLiteral("annotate.%1")
                                .arg(QString::fromUtf8(kind->truth_key.data(),
                                                       qsizetype(kind->truth_key.size())));
        expected << "fake";
        QVERIFY(expected.size() > 8);
        QCOMPARE(ids, expected);
        // Every icon file is a tool's: none is left behind when a tool is renamed.
        QStringList icons;
        for (const auto& tool : manager.tools())
            icons << (tool->info().icon.isEmpty() ? tool->info().id : tool->info().icon);
        for (const QString& file : QDir(QStringLiteral(":/icons/tools")).entryList()) {
            QVERIFY2(file.endsWith(QLatin1String(".svg")), qPrintable(file));
            QVERIFY2(icons.contains(file.chopped(4)), qPrintable(file + " is no tool's icon"));
        }
    }

    void defaultParamsFileIsTheRegistryDefaults()
    {
        const Pipeline& pipeline = Pipeline::standard();
        const std::string expected = registryDefaults(pipeline).toJson();
        if (qEnvironmentVariableIsSet("FIELDSIGHT_REGENERATE_GOLDEN")) {
            QSaveFile out(sourcePath("resources/config/default_params.json"));
            QVERIFY(out.open(QIODevice::WriteOnly));
            out.write(expected.data(), qint64(expected.size()));
            QVERIFY(out.commit());
            QFAIL("regenerated resources/config/default_params.json; run again without "
                  "FIELDSIGHT_REGENERATE_GOLDEN");
        }
        QFile file(QStringLiteral(":/config/default_params.json"));
        QVERIFY(file.open(QIODevice::ReadOnly));
        const std::string text = file.readAll().toStdString();
        auto params = ParamSet::fromJson(text, "default_params.json");
        QVERIFY2(params, params ? "" : params.error().message.c_str());
        QVERIFY(params.value().check(pipeline));
        int count = 0;
        for (const StageDescriptor& stage : pipeline.descriptors()) {
            QVERIFY2(params.value().values.count(stage.info.id), stage.info.id.c_str());
            const auto& values = params.value().values.at(stage.info.id);
            QCOMPARE(values.size(), stage.params.size());
            for (const ParamInfo& param : stage.params) {
                QCOMPARE(values.at(param.name), param.default_value);
                ++count;
            }
        }
        QVERIFY(count > 20);
        QVERIFY2(text == expected,
                 "resources/config/default_params.json differs from the "
                 "registry's defaults: FIELDSIGHT_REGENERATE_GOLDEN=1 remakes it");
    }

    void theInstalledExecutableFindsTheInstalledSampleStream()
    {
        QTemporaryDir prefix;
        QVERIFY(prefix.isValid());
        const QString bin = prefix.filePath("bin");
        const QString installed = prefix.filePath("share/fieldsight/sample_streams/lab1");
        QVERIFY(QDir().mkpath(bin));
        const QString before = qEnvironmentVariable("FIELDSIGHT_SAMPLE_STREAM");
        qunsetenv("FIELDSIGHT_SAMPLE_STREAM");
        // Nothing installed yet: the source tree's stream.
        QCOMPARE(SessionFiles::bundledSampleStream(bin),
                 QDir::cleanPath(sourcePath("sample_streams/lab1")));
        QVERIFY(QDir().mkpath(installed));
        QCOMPARE(SessionFiles::bundledSampleStream(bin), QDir::cleanPath(installed));
        if (!before.isEmpty())
            qputenv("FIELDSIGHT_SAMPLE_STREAM", before.toLocal8Bit());
    }
};

FIELDSIGHT_TEST_SUITE(TestResources, Widgets)

#include "test_resources.moc"
