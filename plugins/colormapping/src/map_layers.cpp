#include "map_layers.h"

#include <darkroom/error.h>
#include <darkroom/layer_blend.h>
#include <darkroom/layers.h>

#include <cmath>
#include <limits>

namespace darkroom::colormapping {

namespace {

const float kInf = std::numeric_limits<float>::infinity();
const char* const kRGBA[4] = {"R", "G", "B", "A"};

bool background(float z) { return std::isinf(z) && z > 0; }

std::vector<ChannelDesc> colourChannels(int layerCount) {
    std::vector<ChannelDesc> names;
    for (int k = 0; k < layerCount; ++k)
        for (const char* c : kRGBA) names.emplace_back(layers::channel(c, k));
    return names;
}

// Blends the layers' colours (scratch, colourChannels order) front to back into out's R, G, B, A, Z.
void blendLayers(Context& ctx, const Buffer& scratch, const std::vector<const float*>& depth, WritableBuffer& out) {
    const int layerCount = int(depth.size()), w = out.width();
    std::vector<const float*> c(std::size_t(4 * layerCount));
    for (int k = 0; k < layerCount; ++k)
        for (int j = 0; j < 4; ++j) c[std::size_t(4 * k + j)] = scratch.hostFloat(layers::channel(kRGBA[j], k));
    float* o[5] = {out.writeFloat("R"), out.writeFloat("G"), out.writeFloat("B"), out.writeFloat("A"),
                   out.writeFloat("Z")};
    ctx.parallelFor(0, out.height(), 8, [&](int y0, int y1) {
        std::vector<layers::Surface> s(static_cast<std::size_t>(layerCount));
        for (std::size_t i = std::size_t(y0) * std::size_t(w); i < std::size_t(y1) * std::size_t(w); ++i) {
            for (int k = 0; k < layerCount; ++k) {
                const float* const* p = &c[std::size_t(4 * k)];
                s[std::size_t(k)] = {depth[std::size_t(k)][i], p[0][i], p[1][i], p[2][i], p[3][i]};
            }
            const layers::Blended b = layers::blendFrontToBack(s.data(), layerCount);
            o[0][i] = b.r, o[1][i] = b.g, o[2][i] = b.b, o[3][i] = b.a, o[4][i] = b.z;
        }
    });
}

}  // namespace

ObjectIds objectIds(const Buffer& in, int layer) {
    const std::string name = layers::channel("objectId", layer);
    ObjectIds ids{in.hostUInt(name), in.hostFloat(name)};
    if (!ids.u && !ids.f)
        throw Error("objectOpacity needs the object ids, but the image has no channel '" + name +
                    "' (capture it with the objectId channel)");
    return ids;
}

void applyObjectOpacity(Context& ctx, const ObjectOpacity& objects, const ObjectIds& ids, const float* depth,
                        float* alpha, std::size_t pixels) {
    const int rows = int((pixels + 4095) / 4096);
    ctx.parallelFor(0, rows, 1, [&](int r0, int r1) {
        const std::size_t end = std::min(pixels, std::size_t(r1) * 4096);
        for (std::size_t i = std::size_t(r0) * 4096; i < end; ++i)
            if (!depth || !background(depth[i])) alpha[i] *= objects(ids[i]);
    });
}

std::vector<std::vector<float>> visibleDepths(const Buffer& in, int layerCount, float opacity,
                                              const ObjectOpacity& objects) {
    const std::size_t n = in.pixelCount();
    std::vector<float> transmit(n, 1.0f);
    std::vector<std::vector<float>> out(std::size_t(layerCount), std::vector<float>(n, kInf));
    for (int k = 0; k < layerCount; ++k) {
        const float* z = in.hostFloat(layers::channel("Z", k));
        const ObjectIds ids = objects.empty() ? ObjectIds{} : objectIds(in, k);
        for (std::size_t i = 0; i < n; ++i) {
            if (background(z[i])) continue;
            const float a = objects.empty() ? opacity : opacity * objects(ids[i]);
            if (transmit[i] > 0 && a > 0) out[std::size_t(k)][i] = z[i];
            transmit[i] *= 1.0f - std::min(a, 1.0f);
        }
    }
    return out;
}

BufferPtr mapLayers(Context& ctx, const BufferPtr& in, const std::string& channel, MapJob job, bool logScale,
                    const ObjectOpacity& objects, bool keep) {
    const int layerCount = layers::count(*in), w = in->width(), h = in->height();
    // Every colour plane is written for every pixel below.
    auto colour = ctx.allocate(w, h, colourChannels(layerCount), Fill::None);
    std::vector<const float*> depth;
    for (int k = 0; k < layerCount; ++k) {
        const std::string scalarName = layers::channel(channel, k), zName = layers::channel("Z", k);
        const ScalarChannel scalar{in->hostFloat(scalarName), in->hostUInt(scalarName)};
        if (!scalar.f && !scalar.u)
            throw Error("layer " + std::to_string(k) + " of the image has no channel '" + scalarName +
                        "'; every layer needs the mapped channel");
        job.depth = in->hostFloat(zName);
        depth.push_back(job.depth);
        for (int j = 0; j < 4; ++j) job.out[j] = colour->writeFloat(layers::channel(kRGBA[j], k));
        mapPixels(ctx, job, scalar, w, h, logScale);
        if (!objects.empty())
            applyObjectOpacity(ctx, objects, objectIds(*in, k), job.depth, job.out[3], in->pixelCount());
        if (keep) colour->setPlane({zName}, in->plane(zName));
    }
    colour->metadata() = in->metadata();
    if (keep) return colour;
    auto out = ctx.allocate(w, h, {"R", "G", "B", "A", "Z"}, Fill::None);
    out->metadata() = in->metadata();
    blendLayers(ctx, *colour, depth, *out);
    return out;
}

}  // namespace darkroom::colormapping
