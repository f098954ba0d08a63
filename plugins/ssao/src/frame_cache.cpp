#include "frame_cache.h"

namespace darkroom::ssao {

namespace {

// The id of a float plane read through `in` (0: absent).
std::uint64_t idOf(const Buffer& in, const char* name) {
    if (!in.hostFloat(name)) return 0;  // hostFloat records the read
    const PlanePtr p = in.plane(name);
    return p ? p->id() : 0;
}

}  // namespace

const Frame& FrameCache::get(const Buffer& in, const Camera& camera, bool useNormals, int border, Context& ctx) {
    Key key;
    key.z = idOf(in, "Z");
    if (useNormals) {
        key.n[0] = idOf(in, "N.x");
        key.n[1] = idOf(in, "N.y");
        key.n[2] = idOf(in, "N.z");
    }
    key.camera = camera;
    key.useNormals = useNormals;
    key.border = border;
    key.width = in.width();
    key.height = in.height();
    if (!(frame_ && key_ == key)) {
        frame_.reset();  // its planes go back to the pool for the new frame
        frame_ = buildFrame(in, camera, useNormals, border, ctx);
        key_ = key;
    }
    return *frame_;
}

}  // namespace darkroom::ssao
