#pragma once
#include <darkroom/capture_backend.h>

#include <memory>

namespace darkroom::embree {

class SceneBvh;

// The "embree" capture backend: triangles, round linear curves and sphere
// points traced natively with coherent 8-wide packets over 16x16 tiles.
std::unique_ptr<CaptureBackend> createBackend();

// How a capture with CaptureRequest::layers > 1 finds the crossings behind
// the first (layered_tile.h): one traversal with a filter collecting the K
// nearest, or one traversal per layer. Filter is what render() uses: it
// measured faster (docs/capture.md, "Layers"); Repeat stays for the
// benchmark and as a cross-check in the tests.
enum class LayerMethod { Filter, Repeat };

// What the backend's render() does, on a BVH built by the caller (the in
// situ library builds it over a simulation's own arrays, embree_scene.h).
BufferPtr renderGBuffer(const SceneBvh& bvh, const Camera& camera, const CaptureRequest& request, Context& ctx,
                        LayerMethod method = LayerMethod::Filter);

}  // namespace darkroom::embree
