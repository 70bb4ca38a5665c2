// The fieldsight executable: the command word picks the GUI or a headless command (SPEC §5);
// the headless commands live in app/commands/, the GUI in ui/ (opened by gui_command.cpp).
#include "commands/commands.h"
#include "gui_command.h"

#include <QCoreApplication>

#include <csignal>
#include <iostream>

int main(int argc, char* argv[])
{
    using namespace fieldsight;
    // Past a file-size limit (ulimit -f) a write fails with EFBIG and is reported like a full
    // disk, naming the file, instead of the process being killed mid-save.
    std::signal(SIGXFSZ, SIG_IGN);
    const QString command = argc > 1 ? ui::fromLocalPath(argv[1]) : QString();
    const cli::Context ctx{Pipeline::standard(), std::cout, std::cerr};
    if (command.isEmpty() || command == "gui")
        return cli::guiCommand(argc, argv, ctx);
    if (command == "--version" || command == "-v") {
        std::cout << "fieldsight " << FIELDSIGHT_VERSION << '\n';
        return cli::kExitOk;
    }

    QCoreApplication app(argc, argv);
    QCoreApplication::setApplicationName("fieldsight");
    QCoreApplication::setApplicationVersion(QStringLiteral(FIELDSIGHT_VERSION));
    // A command's parser sees the program name followed by the command's own arguments.
    // Not QCoreApplication::arguments(): a path that is not UTF-8 must reach the command unchanged.
    QStringList args = ui::argumentsOf(argc, argv);
    args.removeAt(1);
    return cli::runHeadless(command, args, ctx);
}
