# darkroom_add_plugin(NAME SOURCES src... [LIBRARIES lib...])
#
# Builds a Darkroom plugin: a shared module with hidden symbols whose only
# export is the DARKROOM_PLUGIN entry point. Inside the Darkroom source tree the
# module lands in the runner's plugin directory; out of tree it lands in the
# current binary directory (load it with --plugin-path or DARKROOM_PLUGIN_PATH).
function(darkroom_add_plugin NAME)
  cmake_parse_arguments(ARG "" "" "SOURCES;LIBRARIES" ${ARGN})
  if(NOT ARG_SOURCES)
    message(FATAL_ERROR "darkroom_add_plugin(${NAME}): SOURCES is required")
  endif()
  add_library(${NAME} MODULE ${ARG_SOURCES})
  target_link_libraries(${NAME} PRIVATE Darkroom::sdk ${ARG_LIBRARIES})
  target_compile_features(${NAME} PRIVATE cxx_std_20)
  set_target_properties(${NAME} PROPERTIES
    PREFIX "" OUTPUT_NAME "darkroom-${NAME}"
    CXX_VISIBILITY_PRESET hidden VISIBILITY_INLINES_HIDDEN ON)
  if(DEFINED DARKROOM_PLUGIN_OUTPUT_DIRECTORY)
    set_target_properties(${NAME} PROPERTIES
      LIBRARY_OUTPUT_DIRECTORY ${DARKROOM_PLUGIN_OUTPUT_DIRECTORY}
      INSTALL_RPATH "$ORIGIN/../..")
    install(TARGETS ${NAME} LIBRARY DESTINATION ${DARKROOM_PLUGIN_INSTALL_DIR})
    set_property(GLOBAL APPEND PROPERTY DARKROOM_PLUGIN_TARGETS ${NAME})
  endif()
endfunction()
