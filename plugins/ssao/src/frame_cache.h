#pragma once
// SSAO's frame (depth planes and normals, frame.h) kept from one execution
// to the next. An edit of the radius, the samples or the intensity runs SSAO
// again on the same depth: in the editor's settle after a radius drag the
// frame was rebuilt from the same planes every time (about 20 ms of the
// pass at 2048 x 2048). The frame is keyed by the identity of the planes it
// was built from (Plane::id is never reused), the camera and the padding.
// One cache per filter instance, which one evaluator runs at a time.
#include "frame.h"

#include <cstdint>
#include <optional>

namespace darkroom::ssao {

class FrameCache {
public:
    // buildFrame(in, camera, useNormals, border, ctx), or the last one built
    // from the same planes. Either way the planes are read through `in`, so
    // the evaluator still records what SSAO depends on.
    const Frame& get(const Buffer& in, const Camera& camera, bool useNormals, int border, Context& ctx);

private:
    struct Key {
        std::uint64_t z = 0, n[3] = {0, 0, 0};
        Camera camera;
        bool useNormals = false;
        int border = 0, width = 0, height = 0;
        bool operator==(const Key&) const = default;
    };
    std::optional<Key> key_;
    std::optional<Frame> frame_;
};

}  // namespace darkroom::ssao
