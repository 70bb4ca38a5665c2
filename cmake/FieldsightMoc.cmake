# AUTOMOC for a target, through a moc that is given only the project's include directories
# (moc_own_includes.sh.in). moc follows every #include it can resolve to collect macros; a suite
# includes the core's headers, which include OpenCV, Eigen, JSON and the standard library, and
# Qt's own headers are most of the rest. With only the project's directories moc takes 0.02 s a
# file instead of 0.4 s (with Qt's) or 7 s (with every directory), for output that is the same
# byte for byte but for the headers Qt's classes ask their own moc output to include
# (Q_MOC_INCLUDE), which a subclass's does not need: the build would fail if it did.
get_target_property(FIELDSIGHT_MOC Qt6::moc IMPORTED_LOCATION)
if(NOT FIELDSIGHT_MOC)
    get_target_property(FIELDSIGHT_MOC Qt6::moc LOCATION)
endif()
set(FIELDSIGHT_MOC_WRAPPER "${PROJECT_BINARY_DIR}/moc_own_includes.sh")
configure_file("${CMAKE_CURRENT_LIST_DIR}/moc_own_includes.sh.in" "${FIELDSIGHT_MOC_WRAPPER}"
    @ONLY FILE_PERMISSIONS OWNER_READ OWNER_WRITE OWNER_EXECUTE GROUP_READ GROUP_EXECUTE
    WORLD_READ WORLD_EXECUTE)

function(fieldsight_automoc target)
    set_target_properties(${target} PROPERTIES AUTOMOC ON
        AUTOMOC_EXECUTABLE "${FIELDSIGHT_MOC_WRAPPER}")
endfunction()
