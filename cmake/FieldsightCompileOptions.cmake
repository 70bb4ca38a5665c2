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
    if(FIELDSIGHT_SANITIZE)
        target_compile_options(${target} PRIVATE -fsanitize=address,undefined
            -fno-omit-frame-pointer -fno-sanitize-recover=undefined)
        target_link_options(${target} PRIVATE -fsanitize=address,undefined)
    endif()
    if(FIELDSIGHT_FUZZ AND target MATCHES "^(fieldsight_visioncore|fieldsight_fuzz_support|fuzz_)")
        # Coverage for libFuzzer in what the fuzz targets run (tests/fuzz/: the core and
        # themselves); nothing else needs it.
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

# The test build (.ci/setup without targets) compiles the window's library and the commands
# unoptimised: they are glue between the core, the generator and Qt, which stay optimised, and
# the suites run as fast either way (98 s), while the build takes about 28 s less on two cores
# (their compile 133 s -> 75 s of CPU). The window the main command builds is optimised.
option(FIELDSIGHT_UNOPTIMISED_GLUE "Compile the window's library and the commands at -O0" OFF)
function(fieldsight_glue_options target)
    fieldsight_target_options(${target})
    if(FIELDSIGHT_UNOPTIMISED_GLUE)
        target_compile_options(${target} PRIVATE -O0)
    endif()
endfunction()
