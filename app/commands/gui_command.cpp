// `fieldsight [gui [STREAM] [--lut FILE] [--set ...] [--params FILE]]`: the main window.
#include "commands/commands.h"
#include "ui/actions/file_commands.h"
#include "ui/adapters/local_path.h"
#include "ui/application.h"
#include "ui/main_window.h"
#include "ui/settings/window_settings.h"

#include <QApplication>

namespace fieldsight::cli {

int guiCommand(int& argc, char** argv, const Context& ctx)
{
    QApplication app(argc, argv);
    ui::identifyApplication();
    QApplication::setApplicationVersion(QStringLiteral(FIELDSIGHT_VERSION));

    QStringList args = ui::argumentsOf(argc, argv); // exact bytes of paths (local_path.h)
    if (args.size() > 1 && args[1] == QLatin1String("gui"))
        args.removeAt(1);
    QCommandLineParser parser;
    parser.setApplicationDescription("Opens the GUI on STREAM (a folder of images, a .strm file, "
                                     "a video file or camera:N), or on the last session's "
                                     "stream, or on the bundled sample stream.");
    parser.addPositionalArgument("STREAM", "The stream to open.", "[STREAM]");
    parser.addOption(lutOption());
    parser.addOption(setOption());
    parser.addOption(paramsOption());
    if (const std::optional<int> done = parseCommand(parser, "gui", args, 0, 1, ctx))
        return *done;
    auto params = paramsFrom(parser);
    if (!params)
        return badInput(ctx, params.error().message);
    if (Status s = params.value().check(ctx.pipeline); !s)
        return badInput(ctx, s.error().message);

    ui::MainWindow window(ctx.pipeline);
    window.session().settings().reset(params.value()); // checked above
    window.show();
    const QString lut = parser.value(QStringLiteral("lut"));
    const QStringList positional = parser.positionalArguments();
    if (!positional.isEmpty())
        window.files().openStream(positional.front(), lut);
    else if (!lut.isEmpty())
        window.files().openStream(ui::FileCommands::bundledSampleStream(), lut);
    else if (const ui::WindowSettings last = ui::WindowSettings::load(); true)
        window.files().openLastSession(last.stream, last.lut);
    return QApplication::exec();
}

} // namespace fieldsight::cli
