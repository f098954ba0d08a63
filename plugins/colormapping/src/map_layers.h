#pragma once
// ColorMapping on a layered G-buffer (issue 30, layers.h naming): every
// layer's scalar through the same map and range, an opacity per layer
// (the `opacity` port times the object's), then either the layers kept as
// a layered RGBA image or blended front to back into one.
#include "map_kernel.h"
#include "object_opacity.h"
#include "scalar_range.h"

#include <darkroom/buffer.h>
#include <darkroom/context.h>

#include <string>
#include <vector>

namespace darkroom::colormapping {

// Maps `scalar` into job.out over a w x h image (job.depth marks background).
void mapPixels(Context& ctx, const MapJob& job, const ScalarChannel& scalar, int w, int h, bool logScale);

// One layer's values and the depth that says where they count for the
// automatic range (+inf: not counted).
struct LayerValues {
    ScalarChannel scalar;
    const float* depth = nullptr;
};

// Where each layer of `in` can be seen: its depth, or +inf where it is
// missing or hidden (its own alpha is 0, or an opaque surface is in front).
// Opacity is `opacity` times the object's; NaN colours are not considered.
std::vector<std::vector<float>> visibleDepths(const Buffer& in, int layerCount, float opacity,
                                              const ObjectOpacity& objects);

// The objectId plane of layer `layer` (float or uint32), for per-object opacity.
// Throws when `in` has none.
struct ObjectIds {
    const std::uint32_t* u = nullptr;
    const float* f = nullptr;
    std::uint32_t operator[](std::size_t i) const { return u ? u[i] : std::uint32_t(f[i]); }
};
ObjectIds objectIds(const Buffer& in, int layer);

// Multiplies alpha of the pixels on geometry by their object's opacity.
void applyObjectOpacity(Context& ctx, const ObjectOpacity& objects, const ObjectIds& ids, const float* depth,
                        float* alpha, std::size_t pixels);

// The output of a layered input: `keep`: R, G, B, A, Z per layer (layer k's
// prefixed layer<k>.), straight alpha; else one layer blended front to back,
// Z the nearest surface that shows (+inf where none does).
BufferPtr mapLayers(Context& ctx, const BufferPtr& in, const std::string& channel, MapJob job, bool logScale,
                    const ObjectOpacity& objects, bool keep);

}  // namespace darkroom::colormapping
