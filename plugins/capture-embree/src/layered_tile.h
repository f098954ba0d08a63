#pragma once
// Traces one tile of a capture with CaptureRequest::layers > 1: per pixel
// the K nearest surface crossings (crossing_rule.h), each written by its
// own GBufferWriter into its own TileBuffer and then into the layer's
// channels (darkroom/layers.h). Layer 0 is what a one-layer capture gives,
// bit for bit.
#include "embree_backend.h"
#include "embree_scene.h"
#include "gbuffer_writer.h"
#include "primary_rays.h"

#include <vector>

namespace darkroom::embree {

// LayerMethod (embree_backend.h): both give the same layers.
// - Filter: one traversal per packet, an intersection filter collecting the
//   K nearest candidates (k_nearest_context.h);
// - Repeat: one traversal per layer, each starting at the previous layer's
//   depth and skipping its crossing (NextCrossingContext).

// The per-thread state of layered tracing: one tile buffer per layer.
struct LayeredTileState {
    explicit LayeredTileState(const std::vector<GBufferWriter>& writers);
    std::vector<TileBuffer> tiles;
};

// `writers[k]` writes layer k; (x0, y0) is the tile's corner; tiles are
// TileBuffer::kSize square, traced in 4x2 packets as the one-layer capture
// traces them.
void traceLayeredTile(const SceneBvh& bvh, LayerMethod method, const PrimaryRays& rays,
                      const std::vector<GBufferWriter>& writers, LayeredTileState& state, int width, int height,
                      int x0, int y0);

}  // namespace darkroom::embree
