// What code writes on file descriptor 2 while it runs, where libraries print their own lines
// (libjpeg and libpng with fprintf, OpenCV's decoders through std::cerr).
#pragma once

#include <cstdio>
#include <iostream>
#include <string>

#include <unistd.h>

namespace fieldsight::test {

template <class Run> std::string stderrOf(Run run)
{
    std::cerr.flush();
    std::fflush(stderr);
    FILE* capture = std::tmpfile();
    const int saved = ::dup(2);
    ::dup2(::fileno(capture), 2);
    run();
    std::cerr.flush();
    std::fflush(stderr);
    ::dup2(saved, 2);
    ::close(saved);
    std::string text;
    std::rewind(capture);
    for (int c = std::fgetc(capture); c != EOF; c = std::fgetc(capture))
        text += char(c);
    std::fclose(capture);
    return text;
}

} // namespace fieldsight::test
