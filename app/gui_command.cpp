// `fieldsight [gui [STREAM] [--lut FILE] [--set ...] [--params FILE]]`: the main window.
#include "gui_command.h"

#include "ui/actions/file_commands.h"
#include "ui/adapters/local_path.h"
#include "ui/application.h"
#include "ui/main_window.h"
#include "ui/settings/window_settings.h"

#include <QApplication>

#include <cstdlib>

namespace fieldsight::cli {

#ifdef Q_OS_LINUX
namespace {

bool isSet(const char* name)
{
    const char* value = std::getenv(name);
    return value && *value;
}

} // namespace
#endif

int guiCommand(int& argc, char** argv, const Context& ctx)
{
    QCoreApplication::setOrganizationName(QStringLiteral("Fieldsight"));
    QCoreApplication::setApplicationName(QStringLiteral("fieldsight"));
    QCoreApplication::setApplicationVersion(QStringLiteral(FIELDSIGHT_VERSION));
    ParamSet params;
    QString lut;
    QStringList positional;
    {
        // The arguments are checked before the window's application exists: a bad --params
        // needs no display, and no line of Qt's comes before the one error line.
        QCoreApplication parsing(argc, argv);
        QStringList args = ui::argumentsOf(argc, argv); // exact bytes of paths (local_path.h)
        if (args.size() > 1 && args[1] == QLatin1String("gui"))
            args.removeAt(1);
        QCommandLineParser parser;
        parser.setApplicationDescription(
            "Opens the GUI on STREAM (a folder of images, a .strm file, a video file or "
            "camera:N), or on the last session's stream, or on the bundled sample stream.");
        parser.addPositionalArgument("STREAM", "The stream to open.", "[STREAM]");
        parser.addOption(lutOption());
        parser.addOption(setOption());
        parser.addOption(paramsOption());
        if (const std::optional<int> done = parseCommand(parser, "gui", args, 0, 1, ctx))
            return *done;
        auto checked = paramsFrom(parser, ctx.pipeline);
        if (!checked)
            return badInput(ctx, checked.error().message);
        params = std::move(checked).value();
        lut = parser.value(QStringLiteral("lut"));
        positional = parser.positionalArguments();
    }
#ifdef Q_OS_LINUX
    // Without a display Qt aborts with its own four lines about platform plugins; say it in one,
    // with the two ways to run the window anyway.
    if (!isSet("DISPLAY") && !isSet("WAYLAND_DISPLAY") && !isSet("QT_QPA_PLATFORM"))
        return badInput(ctx, "gui: no display (DISPLAY and WAYLAND_DISPLAY are not set); run it as "
                             "'xvfb-run -a fieldsight gui ...', or with QT_QPA_PLATFORM=offscreen "
                             "(the window then draws into memory only)");
#endif
    QApplication app(argc, argv);
    ui::identifyApplication();

    ui::MainWindow window(ctx.pipeline);
    window.session().settings().reset(params);  // checked above
    window.session().setParamOverrides(params); // over every stream's own, as on the command line
    window.show();
    if (!positional.isEmpty())
        window.files().openStream(positional.front(), lut);
    else if (!lut.isEmpty())
        window.files().openStream(ui::FileCommands::sampleStreamCopy(), lut);
    else if (const ui::WindowSettings last = ui::WindowSettings::load(); true)
        window.files().openLastSession(last.stream, last.lut);
    return QApplication::exec();
}

} // namespace fieldsight::cli
