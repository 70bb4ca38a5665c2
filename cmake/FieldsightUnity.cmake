# Unity builds (CMAKE_UNITY_BUILD=ON: the README's test command and the sanitizer build) compile a
# target's sources in batches of eight, one translation unit each: the big headers (Qt, OpenCV,
# nlohmann-json) are parsed once per batch instead of once per file. A file whose file-local names
# (anonymous namespaces, `using` aliases) clash with another file's is compiled alone: listed here.
set(FIELDSIGHT_UNITY_ALONE
    tests/core/test_strm_stream.cpp
    tests/core/test_lut_import.cpp
    tests/core/test_camera_data_wrapper.cpp
    tests/core/test_cli.cpp
    tests/ui/test_annotate_tools.cpp
    tests/ui/test_bad_input.cpp
    tests/core/test_annotation_editing.cpp
    tests/core/test_annotation_exchange.cpp
    tests/core/test_compare.cpp
    tests/core/test_fake_percept.cpp
    tests/core/test_fake_stage.cpp
    tests/core/test_light_drift.cpp
    tests/core/test_log_import.cpp
    tests/core/test_no_overwrite.cpp
    tests/core/test_orientation.cpp
    tests/ui/test_annotate_actions.cpp
    tests/ui/test_auto_table_trial.cpp
    tests/ui/test_fake_percept_window.cpp
    tests/ui/test_nothing_lost.cpp
    tests/ui/test_orientation_gui.cpp
    tests/ui/test_session.cpp
    app/commands/compare_command.cpp
    app/commands/eval_command.cpp
    ui/dialogs/fit_result_dialog.cpp
    tools/synth/synth.cpp
    visioncore/src/io/stream_reader.cpp
    tools/synth/scenario_script.cpp
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
