#pragma once
#include <darkroom/capture_backend.h>

#include <memory>

namespace darkroom::embree {

class SceneBvh;

// The "embree" capture backend: triangles, round linear curves and sphere
// points traced natively with coherent 8-wide packets over 16x16 tiles.
std::unique_ptr<CaptureBackend> createBackend();

// What the backend's render() does, on a BVH built by the caller (the in
// situ library builds it over a simulation's own arrays, embree_scene.h).
BufferPtr renderGBuffer(const SceneBvh& bvh, const Camera& camera, const CaptureRequest& request, Context& ctx);

}  // namespace darkroom::embree
