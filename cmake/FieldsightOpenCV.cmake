# Finds the four OpenCV modules Fieldsight uses as imported targets opencv_core, opencv_imgproc,
# opencv_imgcodecs and opencv_videoio. Debian ships OpenCVConfig.cmake only with the umbrella
# libopencv-dev (which pulls in VTK, Qt5 and MPI), so with the lean per-module packages we locate
# headers and libraries ourselves.
find_package(OpenCV 4 QUIET COMPONENTS core imgproc imgcodecs videoio)
if(OpenCV_FOUND)
    message(STATUS "OpenCV ${OpenCV_VERSION} from its CMake config")
    return()
endif()

find_path(FIELDSIGHT_OPENCV_INCLUDE_DIR opencv2/core.hpp PATH_SUFFIXES opencv4 REQUIRED)
foreach(module core imgproc imgcodecs videoio)
    find_library(FIELDSIGHT_OPENCV_${module}_LIBRARY NAMES opencv_${module} REQUIRED)
    add_library(opencv_${module} SHARED IMPORTED GLOBAL)
    set_target_properties(opencv_${module} PROPERTIES
        IMPORTED_LOCATION "${FIELDSIGHT_OPENCV_${module}_LIBRARY}"
        INTERFACE_INCLUDE_DIRECTORIES "${FIELDSIGHT_OPENCV_INCLUDE_DIR}")
endforeach()
message(STATUS "OpenCV modules from ${FIELDSIGHT_OPENCV_INCLUDE_DIR}")
