// The main of an area's test runner: `core_tests test_stages [Qt Test options]` runs one suite
// with the application object its file asked for (tests/support/test_suite.h).

#include "support/test_suite.h"

#include <cstdio>
#include <map>
#include <vector>

#ifdef QT_WIDGETS_LIB
#include <QApplication>
#endif

namespace fieldsight::test {
namespace {

struct Entry
{
    App app = App::None;
    SuiteMain main = nullptr;
};

std::map<std::string, Entry>& suites()
{
    static std::map<std::string, Entry> all;
    return all;
}

std::string& current()
{
    static std::string name;
    return name;
}

std::string baseName(std::string file)
{
    if (const auto slash = file.find_last_of('/'); slash != std::string::npos)
        file.erase(0, slash + 1);
    if (const auto dot = file.rfind('.'); dot != std::string::npos)
        file.erase(dot);
    return file;
}

template <typename Application> int runUnder(int argc, char** argv, SuiteMain main)
{
    Application app(argc, argv);
    app.setAttribute(Qt::AA_Use96Dpi, true);
    // Named for the suite, as its own program was: its settings, recovery files and test-mode
    // folders stay apart from another suite's running beside it (ctest -j).
    QCoreApplication::setApplicationName(QString::fromStdString(current()));
    return main(argc, argv);
}

} // namespace

bool registerSuite(const char* file, App app, SuiteMain main)
{
    suites()[baseName(file)] = {app, main};
    return true;
}

const std::string& currentSuite()
{
    return current();
}

} // namespace fieldsight::test

int main(int argc, char** argv)
{
    const auto& all = fieldsight::test::suites();
    const auto found = argc >= 2 ? all.find(argv[1]) : all.end();
    if (found == all.end()) {
        std::fprintf(stderr, "usage: %s SUITE [Qt Test options]\nsuites:", argv[0]);
        for (const auto& [name, entry] : all)
            std::fprintf(stderr, " %s", name.c_str());
        std::fprintf(stderr, "\n");
        return 2;
    }
    fieldsight::test::current() = found->first;
    // The suite sees the program and its own options, as under Qt Test's main.
    std::vector<char*> args{argv[0]};
    args.insert(args.end(), argv + 2, argv + argc);
    args.push_back(nullptr);
    int count = argc - 1;
    switch (found->second.app) {
    case fieldsight::test::App::None:
        return found->second.main(count, args.data());
    case fieldsight::test::App::Core:
        return fieldsight::test::runUnder<QCoreApplication>(count, args.data(), found->second.main);
    case fieldsight::test::App::Widgets:
#ifdef QT_WIDGETS_LIB
        return fieldsight::test::runUnder<QApplication>(count, args.data(), found->second.main);
#else
        std::fprintf(stderr, "%s needs a widgets runner\n", argv[1]);
        return 2;
#endif
    }
    return 2;
}
