#pragma once
#include <darkroom/capture_backend.h>

#include <memory>

namespace darkroom::embree {

// The "embree" capture backend: triangles, round linear curves and sphere
// points traced natively with coherent 8-wide packets over 16x16 tiles.
std::unique_ptr<CaptureBackend> createBackend();

}  // namespace darkroom::embree
