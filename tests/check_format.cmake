# Fails when a C++ file of the project differs from what clang-format (.clang-format) makes of it.
file(GLOB_RECURSE files
    "${SOURCE_DIR}/visioncore/*.h" "${SOURCE_DIR}/visioncore/*.cpp"
    "${SOURCE_DIR}/ui/*.h" "${SOURCE_DIR}/ui/*.cpp"
    "${SOURCE_DIR}/app/*.h" "${SOURCE_DIR}/app/*.cpp"
    "${SOURCE_DIR}/tools/*.h" "${SOURCE_DIR}/tools/*.cpp"
    "${SOURCE_DIR}/tests/*.h" "${SOURCE_DIR}/tests/*.cpp")
execute_process(COMMAND "${CLANG_FORMAT}" --dry-run --Werror ${files}
    RESULT_VARIABLE status ERROR_VARIABLE problems)
if(NOT status EQUAL 0)
    message(FATAL_ERROR "not clang-formatted (run clang-format -i on these):\n${problems}")
endif()
list(LENGTH files count)
message(STATUS "${count} files are clang-formatted")
