# Warnings and sanitizers, applied per target (no global flags).
function(fieldsight_target_options target)
    target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic -Wshadow -Wconversion
        -Wno-sign-conversion)
    if(FIELDSIGHT_WERROR)
        target_compile_options(${target} PRIVATE -Werror)
    endif()
    if(CMAKE_UNITY_BUILD AND CMAKE_CXX_COMPILER_ID STREQUAL "GNU")
        # A unity batch #includes its .cpp files, and GCC then warns of a class in one of them
        # using a type from its anonymous namespace as if the file were a header shared by
        # several translation units; it is not.
        target_compile_options(${target} PRIVATE -Wno-subobject-linkage)
    endif()
    # The scene generator renders test scenes, and instrumented it took most of the sanitizer
    # suite's time (test_hd_window's three 1280x720 frames: 121 s); its own tests (label
    # generator) run only in the normal build. What it renders is checked there.
    if(FIELDSIGHT_SANITIZE AND NOT target STREQUAL "fieldsight_synth")
        target_compile_options(${target} PRIVATE -fsanitize=address,undefined
            -fno-omit-frame-pointer -fno-sanitize-recover=undefined)
        target_link_options(${target} PRIVATE -fsanitize=address,undefined)
    endif()
    if(FIELDSIGHT_FUZZ AND target MATCHES "^(fieldsight_readers|fieldsight_fuzz_support|fuzz_)")
        # Coverage for libFuzzer in what the fuzz targets fuzz (tests/fuzz/: the core's readers,
        # visioncore/CMakeLists.txt, and themselves); nothing else needs it.
        target_compile_options(${target} PRIVATE -fsanitize=fuzzer-no-link)
    endif()
endfunction()

# Precompiled headers for the libraries: most of a translation unit's compile time is parsing the
# same big headers (nlohmann-json, OpenCV's core, Qt's widgets), so each library parses them once.
# A library's own headers are not in them (an edit would rebuild the library whole).
option(FIELDSIGHT_PCH "Precompile the big third-party headers of each library" ON)
function(fieldsight_precompile target)
    if(FIELDSIGHT_PCH)
        target_precompile_headers(${target} PRIVATE ${ARGN})
    endif()
endfunction()

# The test build (.ci/setup without targets) compiles the window's library unoptimised: it is glue
# between the core and Qt, which stay optimised, and its compile took 71 s of CPU instead of 101 s
# (about 15 s of the build's wall time on two cores) while the window's suites took about 0.5 s
# longer each (the commands, which parse and write JSON, lost more than they saved: -O1). The
# window the main command builds is optimised.
option(FIELDSIGHT_UNOPTIMISED_GLUE "Compile the window's library at -O0" OFF)
function(fieldsight_glue_options target)
    fieldsight_target_options(${target})
    if(FIELDSIGHT_UNOPTIMISED_GLUE)
        target_compile_options(${target} PRIVATE -O0)
    endif()
endfunction()
