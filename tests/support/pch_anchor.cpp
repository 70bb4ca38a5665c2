// The program the test suites' precompiled headers are made for (tests/CMakeLists.txt): compiled
// with the same options as the suites, it is never run.
int main()
{
    return 0;
}
