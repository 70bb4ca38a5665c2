# `cmake --install` into a fresh prefix puts every file where a Debian system looks for it, and the
# installed executable runs the pipeline over the installed sample stream with its table.
# -DBUILD_DIR=<build folder> -DPREFIX=<empty folder to install into> -DAPP_ID=<reverse-DNS id>
file(REMOVE_RECURSE "${PREFIX}")
execute_process(COMMAND "${CMAKE_COMMAND}" --install "${BUILD_DIR}" --prefix "${PREFIX}"
    RESULT_VARIABLE status OUTPUT_QUIET ERROR_VARIABLE err)
if(NOT status EQUAL 0)
    message(FATAL_ERROR "cmake --install failed: ${err}")
endif()

set(expected
    bin/fieldsight
    share/applications/${APP_ID}.desktop
    share/metainfo/${APP_ID}.metainfo.xml
    share/icons/hicolor/scalable/apps/${APP_ID}.svg
    share/icons/hicolor/48x48/apps/${APP_ID}.png
    share/icons/hicolor/64x64/apps/${APP_ID}.png
    share/icons/hicolor/128x128/apps/${APP_ID}.png
    share/icons/hicolor/256x256/apps/${APP_ID}.png
    share/fieldsight/default_params.json
    share/fieldsight/sample_streams/lab1/stream.json
    share/fieldsight/sample_streams/lab1/default.lut
    share/fieldsight/sample_streams/lab1/annotations.json
    share/fieldsight/sample_streams/lab1/frame_000029.png
    share/doc/fieldsight/copyright
    share/doc/fieldsight/changelog.Debian.gz
    share/man/man1/fieldsight.1.gz)
foreach(f IN LISTS expected)
    if(NOT EXISTS "${PREFIX}/${f}")
        message(FATAL_ERROR "cmake --install did not put ${f} in ${PREFIX}")
    endif()
endforeach()

execute_process(COMMAND "${PREFIX}/bin/fieldsight" eval
                        "${PREFIX}/share/fieldsight/sample_streams/lab1"
    RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT status EQUAL 0 OR NOT out MATCHES "ball")
    message(FATAL_ERROR "the installed fieldsight could not evaluate the installed sample "
                        "stream (exit ${status}): ${err}${out}")
endif()
# The media module (OpenCV's codecs, loaded on demand) is installed where the executable finds
# it: the installed synth writes its PNG frames through it.
file(GLOB_RECURSE module "${PREFIX}/lib*/libfieldsight_media.so")
if(NOT module)
    message(FATAL_ERROR "cmake --install did not put libfieldsight_media.so under ${PREFIX}/lib")
endif()
execute_process(COMMAND "${PREFIX}/bin/fieldsight" synth --scenario lab1 --frames 1 --width 64
                        --height 48 --out "${PREFIX}/synth-check"
    RESULT_VARIABLE status OUTPUT_QUIET ERROR_VARIABLE err)
if(NOT status EQUAL 0 OR NOT EXISTS "${PREFIX}/synth-check/frame_000000.png")
    message(FATAL_ERROR "the installed fieldsight could not write a PNG through its media "
                        "module (exit ${status}): ${err}")
endif()
message(STATUS "installed into ${PREFIX}; the installed executable evaluates lab1:\n${out}")
file(REMOVE_RECURSE "${PREFIX}")
