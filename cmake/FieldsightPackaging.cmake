# `cpack -G DEB` from a build folder: a Debian package of what `cmake --install` puts in place
# (resources/CMakeLists.txt lists it). Its Depends come from dpkg-shlibdeps (Debian's package
# names of the libraries the executable links), plus the Qt plugin that draws the SVG icons,
# which no library names.
set(CPACK_PACKAGE_NAME fieldsight)
set(CPACK_PACKAGE_VENDOR "The Fieldsight developers")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "colour-segmentation robot vision workbench")
set(CPACK_PACKAGE_DESCRIPTION "\
Fieldsight runs a RoboCup-style colour-segmentation vision pipeline (green
horizon, scanlines, goalposts, field lines, ball and obstacles) over recorded
image streams and shows what every stage found, frame by frame. Its window
builds a venue's colour table by clicking, brushing or sampling pixels, with a
preview of what each edit changes in the whole stream; the same pipeline runs
headless from the command line, which also converts other teams' colour tables
and scores the detections against annotations.")
set(CPACK_PACKAGE_CONTACT
    "Fieldsight maintainers <maintainers@users.noreply.h-seed-4deea454.example>")
set(CPACK_STRIP_FILES ON)
set(CPACK_GENERATOR DEB)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_RELEASE 1)
set(CPACK_DEBIAN_PACKAGE_SECTION science)
set(CPACK_DEBIAN_PACKAGE_PRIORITY optional)
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
set(CPACK_DEBIAN_PACKAGE_DEPENDS "libqt6svg6")
include(CPack)
