#include "pass_through.h"

#include <darkroom/error.h>

#include <algorithm>
#include <cstring>

namespace darkroom::passes {

std::shared_ptr<WritableBuffer> allocatePassThrough(Context& ctx, const Buffer& in,
                                                    const std::vector<std::string>& added) {
    std::vector<ChannelDesc> channels;
    std::vector<ChannelDesc> copied;
    for (const auto& c : in.channels()) {
        const bool replaced = std::find(added.begin(), added.end(), c.name) != added.end();
        // A replaced uint32 channel of the same name becomes float32.
        if (replaced) continue;
        channels.push_back(c);
        copied.push_back(c);
    }
    for (const auto& a : added) channels.push_back({a, ChannelType::Float32});
    auto out = ctx.allocate(in.width(), in.height(), channels);
    out->metadata() = in.metadata();
    const std::size_t n = in.pixelCount();
    const int rows = in.height(), w = in.width();
    for (const auto& c : copied) {
        const void* src = c.type == ChannelType::Float32 ? static_cast<const void*>(in.hostFloat(c.name))
                                                          : static_cast<const void*>(in.hostUInt(c.name));
        void* dst = c.type == ChannelType::Float32 ? static_cast<void*>(out->hostFloat(c.name))
                                                    : static_cast<void*>(out->hostUInt(c.name));
        if (!src || !dst || n == 0) continue;
        // Both types are 4 bytes per pixel.
        ctx.parallelFor(0, rows, 64, [&](int y0, int y1) {
            const std::size_t b = std::size_t(y0) * w * 4, e = std::size_t(y1) * w * 4;
            std::memcpy(static_cast<char*>(dst) + b, static_cast<const char*>(src) + b, e - b);
        });
    }
    return out;
}

Camera requireCamera(const Buffer& in, const std::string& what) {
    if (!in.metadata().camera)
        throw Error(what + " carries no camera in its metadata; depth-based passes need the camera "
                           "that produced the depth (capture with Darkroom, or read an EXR that has one)");
    Camera c = *in.metadata().camera;
    c.width = in.width();
    c.height = in.height();
    return c;
}

}  // namespace darkroom::passes
