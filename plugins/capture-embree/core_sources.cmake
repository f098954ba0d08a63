# The sources of the Embree capture core (the tracer and G-buffer writer), in
# one list for the two builds that compile them: this plugin's static
# library and the fuzz sub-build's in situ harness (tests/fuzz), which cannot
# see this project's targets. Paths relative to plugins/capture-embree.
set(DARKROOM_EMBREE_CORE_SOURCES
  src/bvh_settings.cpp src/embree_backend.cpp src/embree_scene.cpp src/gbuffer_writer.cpp
  src/layered_tile.cpp src/packet_rows.cpp src/shading_normal.cpp)
