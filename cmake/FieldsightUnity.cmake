# Unity builds (CMAKE_UNITY_BUILD=ON: the README's test command and the sanitizer build) compile a
# target's sources in batches of eight, one translation unit each: the big headers (Qt, OpenCV,
# nlohmann-json) are parsed once per batch instead of once per file. A file whose file-local names
# (anonymous namespaces, `using` aliases) clash with another file's is compiled alone: listed here.
set(FIELDSIGHT_UNITY_ALONE
    app/commands/compare_command.cpp
    app/commands/eval_command.cpp
    ui/dialogs/fit_result_dialog.cpp
    tools/synth/synth.cpp
    visioncore/src/io/stream_reader.cpp
    tools/synth/scenario_script.cpp
    tools/synth/scenario_cast.cpp
    visioncore/src/io/coco_export.cpp
)
function(fieldsight_unity_alone)
    foreach(file ${FIELDSIGHT_UNITY_ALONE})
        get_filename_component(dir "${PROJECT_SOURCE_DIR}/${file}" DIRECTORY)
        # The property belongs to the directory whose CMakeLists.txt adds the file's target.
        string(REGEX REPLACE "^([^/]+)/.*" "\\1" top "${file}")
        set_source_files_properties("${PROJECT_SOURCE_DIR}/${file}"
            DIRECTORY "${PROJECT_SOURCE_DIR}/${top}" PROPERTIES SKIP_UNITY_BUILD_INCLUSION ON)
    endforeach()
endfunction()
