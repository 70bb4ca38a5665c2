#pragma once
// A suite's entry in its area's test runner (tests/CMakeLists.txt): one executable per area runs
// the suite named by its first argument, so the ~50 suites share one link and one moc step per
// area. A suite file ends with FIELDSIGHT_TEST_SUITE(TestClass, None|Core|Widgets) (test::App)
// where a Qt Test file would end with a QTEST_*MAIN; CTest keeps one entry per suite (`core_tests
// test_stages`).

#include <QtTest>

#include <string>

namespace fieldsight::test {

/// The application object a suite runs under, as Qt Test's main macros make it.
enum class App {
    None,   ///< QTEST_APPLESS_MAIN
    Core,   ///< QTEST_GUILESS_MAIN: a QCoreApplication
    Widgets ///< QTEST_MAIN in a widgets program: a QApplication
};

using SuiteMain = int (*)(int argc, char** argv);

/// Registers the suite defined in `file` (its name is the file's base name, `test_stages`).
bool registerSuite(const char* file, App app, SuiteMain main);

/// The name the running suite was started by (to run itself again in a child process).
const std::string& currentSuite();

} // namespace fieldsight::test

#define FIELDSIGHT_TEST_SUITE(TestObject, app)                                                     \
    namespace {                                                                                    \
    int runSuite##TestObject(int argc, char** argv)                                                \
    {                                                                                              \
        QT_PREPEND_NAMESPACE(QTest::Internal::callInitMain)<TestObject>();                         \
        TestObject tc;                                                                             \
        QTEST_SET_MAIN_SOURCE_PATH                                                                 \
        return QTest::qExec(&tc, argc, argv);                                                      \
    }                                                                                              \
    [[maybe_unused]] const bool registered##TestObject = ::fieldsight::test::registerSuite(        \
        __FILE__, ::fieldsight::test::App::app, &runSuite##TestObject);                            \
    }
