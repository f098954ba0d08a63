# Defines darkroom_text_drawing, the static library through which the overlay
# nodes (plugins/color-legend, plugins/annotation) draw text and shapes with
# cairo and pango, in a font found through fontconfig (DejaVu Sans, Debian's
# fonts-dejavu-core). Included by each user (plugin folders are configured in
# name order), defined once. Those nodes are part of what CI tests, so with
# tests enabled a missing package stops configuration and names it; without
# tests a warning says the nodes are skipped and the target does not exist.
include_guard(GLOBAL)
pkg_check_modules(PANGOCAIRO QUIET IMPORTED_TARGET GLOBAL pangocairo cairo)
find_file(DARKROOM_DEJAVU_SANS DejaVuSans.ttf
  PATHS /usr/share/fonts/truetype/dejavu /usr/share/fonts/TTF /usr/share/fonts/dejavu NO_DEFAULT_PATH)
set(_text_missing "")
if(NOT PANGOCAIRO_FOUND)
  list(APPEND _text_missing libpango1.0-dev libcairo2-dev)
endif()
if(NOT DARKROOM_DEJAVU_SANS)
  list(APPEND _text_missing fonts-dejavu-core)
endif()
if(_text_missing)
  list(JOIN _text_missing " " _text_packages)
  string(CONCAT _text_message "ColorLegend and Annotation draw text with pango and cairo in DejaVu Sans: install "
         "the Debian package(s) ${_text_packages} (apt-get install ${_text_packages}, or run "
         "scripts/install-deps.sh as root)")
  if(DARKROOM_BUILD_TESTS)
    message(FATAL_ERROR "${_text_message}")
  endif()
  message(WARNING "${_text_message}. ColorLegend and Annotation are NOT built.")
else()
  add_library(darkroom_text_drawing STATIC ${CMAKE_CURRENT_LIST_DIR}/src/text_drawing.cpp
    ${CMAKE_CURRENT_LIST_DIR}/src/text_limits.cpp)
  target_include_directories(darkroom_text_drawing PUBLIC ${CMAKE_CURRENT_LIST_DIR}/src)
  target_link_libraries(darkroom_text_drawing PUBLIC darkroom_sdk PRIVATE PkgConfig::PANGOCAIRO)
endif()
