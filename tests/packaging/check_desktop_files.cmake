# The desktop entry and AppStream metainfo pass Debian's own validators with no error and no
# warning, and name the same id, executable and version as the build. Skipped (ctest's SKIP
# pattern) where desktop-file-validate or appstreamcli is not installed.
# -DSOURCE_DIR=<repo> -DAPP_ID=<reverse-DNS id> -DVERSION=<project version> -DWHAT=desktop|metainfo
if(WHAT STREQUAL "desktop")
    set(file "${SOURCE_DIR}/resources/${APP_ID}.desktop")
    find_program(validator desktop-file-validate)
    set(command "${validator}" "${file}")
else()
    set(file "${SOURCE_DIR}/resources/${APP_ID}.metainfo.xml")
    find_program(validator appstreamcli)
    set(command "${validator}" validate --no-net --no-color "${file}")
endif()

file(READ "${file}" text)
if(WHAT STREQUAL "desktop")
    foreach(line "Exec=fieldsight gui %f" "Icon=${APP_ID}" "TryExec=fieldsight")
        string(FIND "${text}" "\n${line}\n" at)
        if(at EQUAL -1)
            message(FATAL_ERROR "${file}: no line '${line}'")
        endif()
    endforeach()
else()
    foreach(part "<id>${APP_ID}</id>" "<launchable type=\"desktop-id\">${APP_ID}.desktop<"
                 "<binary>fieldsight</binary>" "<release version=\"${VERSION}\"")
        string(FIND "${text}" "${part}" at)
        if(at EQUAL -1)
            message(FATAL_ERROR "${file}: does not contain '${part}' (the build's id, "
                                "executable and version)")
        endif()
    endforeach()
    # The package's changelog (revision 1, cmake/FieldsightPackaging.cmake) and the manual page
    # name the same version.
    file(STRINGS "${SOURCE_DIR}/resources/packaging/changelog" first LIMIT_COUNT 1)
    if(NOT first MATCHES "^fieldsight \\(${VERSION}-1\\) ")
        message(FATAL_ERROR "resources/packaging/changelog: the first entry is not version "
                            "${VERSION}-1: ${first}")
    endif()
    file(STRINGS "${SOURCE_DIR}/resources/packaging/fieldsight.1" title REGEX "^\\.TH ")
    if(NOT title MATCHES "\"fieldsight ${VERSION}\"")
        message(FATAL_ERROR "resources/packaging/fieldsight.1: not version ${VERSION}: ${title}")
    endif()
endif()

if(NOT validator)
    message(STATUS "SKIPPED: no validator installed for ${file} (Debian: desktop-file-utils, "
                   "appstream)")
    return()
endif()
execute_process(COMMAND ${command} RESULT_VARIABLE status OUTPUT_VARIABLE out
    ERROR_VARIABLE out)
message(STATUS "${validator}: ${out}")
# desktop-file-validate prints nothing for a clean file; appstreamcli only its success line.
string(REGEX MATCH "(error|warning|hint|E: |W: )" problem "${out}")
if(NOT status EQUAL 0 OR problem)
    message(FATAL_ERROR "${file} does not validate cleanly (exit ${status}):\n${out}")
endif()
