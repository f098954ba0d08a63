#include "compositing.h"

#include "channel_union.h"
#include "colour_blend.h"
#include "nearest_input.h"

#include <darkroom/error.h>
#include <darkroom/channel_text.h>
#include <darkroom/layers.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <cstdint>
#include <limits>
#include <optional>
#include <vector>

namespace darkroom {

namespace {

std::string sizeText(const Buffer& b) { return std::to_string(b.width()) + "x" + std::to_string(b.height()); }

// What a pixel that is background in every input holds: transparent black
// colour (so a composite of ColorMapping outputs stays displayable and matches
// ColorMapping's own background), NaN ("no data") for other floats, and ~0u
// for ids, which is what the capture backend writes on background.
float backgroundFloat(const std::string& name) {
    if (name == "R" || name == "G" || name == "B" || name == "A") return 0.0f;
    return std::numeric_limits<float>::quiet_NaN();
}

// Whether two cameras show the same rays. Camera::operator== also compares the
// field of the unused projection (a perspective camera still carries a
// viewHeight, which capture derives from the scene's bounds), so it would flag
// captures of different objects from one viewpoint.
bool sameView(const std::optional<Camera>& a, const std::optional<Camera>& b) {
    if (!a || !b) return a.has_value() == b.has_value();
    const bool perspective = a->projection == Camera::Projection::Perspective;
    return a->position == b->position && a->forward == b->forward && a->up == b->up &&
           a->projection == b->projection && a->width == b->width && a->height == b->height &&
           (perspective ? a->fovYDegrees == b->fovYDegrees : a->viewHeight == b->viewHeight);
}

// Per output channel, where each input keeps it (nullptr when it lacks it).
struct ChannelSources {
    ChannelDesc desc;
    std::vector<const float*> floats;
    std::vector<const std::uint32_t*> uints;
    float* outFloat = nullptr;
    std::uint32_t* outUInt = nullptr;
    bool isDepth = false;
};

// Each input's depth plane; throws on a size mismatch or a missing depth.
std::vector<const float*> inputDepths(Context& ctx, const std::vector<BufferPtr>& inputs,
                                      const std::string& depthName) {
    const Buffer& first = *inputs[0];
    std::vector<const float*> depth(inputs.size());
    for (std::size_t i = 0; i < inputs.size(); ++i) {
        const Buffer& b = *inputs[i];
        if (b.width() != first.width() || b.height() != first.height())
            throw Error("input " + std::to_string(i) + " is " + sizeText(b) + " but input 0 is " +
                        sizeText(first) + "; all inputs must have the same size (use Resize)");
        depth[i] = b.hostFloat(depthName);
        if (!depth[i])
            throw Error("input " + std::to_string(i) + " has no float32 depth channel '" + depthName +
                        "'; it has " + channelListText(b));
        if (!sameView(b.metadata().camera, first.metadata().camera))
            ctx.warn("input " + std::to_string(i) +
                     " was rendered with another camera than input 0; the output keeps input 0's camera");
    }
    return depth;
}

}  // namespace

void Compositing::execute(Context& ctx) {
    const std::vector<BufferPtr> inputs = ctx.get(images_);
    if (inputs.empty()) throw Error("no input connected to 'images'; connect at least one G-buffer");
    for (std::size_t i = 0; i < inputs.size(); ++i)
        if (!inputs[i]) throw Error("input " + std::to_string(i) + " on 'images' holds no image");
    // One input has nothing to merge with: forward it untouched, unless its
    // layers are to be flattened.
    if (inputs.size() == 1 && layers::count(*inputs[0]) == 1) {
        ctx.set(result_, inputs[0]);
        return;
    }

    const std::string& depthName = ctx.get(depthChannel_);
    const Buffer& first = *inputs[0];
    const std::vector<const float*> depth = inputDepths(ctx, inputs, depthName);
    const compositing::ColourLayers colour(inputs, depthName);

    const std::vector<ChannelDesc> channels = channelUnion(inputs);
    const int w = first.width(), h = first.height();
    // Every channel of every pixel is written below.
    auto out = ctx.allocate(w, h, channels, Fill::None);
    out->metadata() = first.metadata();

    std::vector<ChannelSources> sources;
    for (const ChannelDesc& c : channels) {
        ChannelSources s;
        s.desc = c;
        s.isDepth = c.name == depthName;
        for (const BufferPtr& b : inputs) {
            s.floats.push_back(c.type == ChannelType::Float32 ? b->hostFloat(c.name) : nullptr);
            s.uints.push_back(c.type == ChannelType::UInt32 ? b->hostUInt(c.name) : nullptr);
        }
        if (c.type == ChannelType::Float32)
            s.outFloat = out->writeFloat(c.name);
        else
            s.outUInt = out->writeUInt(c.name);
        sources.push_back(std::move(s));
    }

    const float nan = std::numeric_limits<float>::quiet_NaN();
    const float inf = std::numeric_limits<float>::infinity();
    const std::uint32_t noId = 0xFFFFFFFFu;
    const int n = int(inputs.size());
    // Row by row: choose the winners of a row, then copy each channel of it
    // run by run (neighbouring pixels mostly come from the same input), so
    // the depths and the winner list stay in cache and the copies are memcpys.
    float* const colourOut[4] = {out->hostFloat("R") ? out->writeFloat("R") : nullptr,
                                 out->hostFloat("G") ? out->writeFloat("G") : nullptr,
                                 out->hostFloat("B") ? out->writeFloat("B") : nullptr,
                                 out->hostFloat("A") ? out->writeFloat("A") : nullptr};
    const bool blend = colour.any() && colourOut[0] && colourOut[1] && colourOut[2] && colourOut[3];
    ctx.parallelFor(0, h, 4, [&](int y0, int y1) {
        std::vector<int> winner(static_cast<std::size_t>(w));
        std::vector<std::pair<int, int>> runs;  // (first pixel, winner)
        std::vector<const float*> depthRow(depth.size());
        for (int y = y0; y < y1; ++y) {
            const std::size_t row = std::size_t(y) * std::size_t(w);
            for (std::size_t k = 0; k < depth.size(); ++k) depthRow[k] = depth[k] + row;
            compositing::nearestInputs(depthRow.data(), n, w, winner.data());
            runs.clear();
            for (int x = 0; x < w; ++x)
                if (x == 0 || winner[std::size_t(x)] != winner[std::size_t(x) - 1]) runs.emplace_back(x, winner[std::size_t(x)]);
            runs.emplace_back(w, -1);
            for (ChannelSources& s : sources) {
                const float bg = s.isDepth ? inf : backgroundFloat(s.desc.name);
                for (std::size_t r = 0; r + 1 < runs.size(); ++r) {
                    const auto [x0, k] = runs[r];
                    const std::size_t i = row + std::size_t(x0), count = std::size_t(runs[r + 1].first - x0);
                    if (s.outFloat) {
                        const float* src = k < 0 ? nullptr : s.floats[std::size_t(k)];
                        if (src)
                            std::memcpy(s.outFloat + i, src + i, count * sizeof(float));
                        else
                            std::fill_n(s.outFloat + i, count, k < 0 ? bg : nan);
                    } else {
                        const std::uint32_t* src = k < 0 ? nullptr : s.uints[std::size_t(k)];
                        if (src)
                            std::memcpy(s.outUInt + i, src + i, count * sizeof(std::uint32_t));
                        else
                            std::fill_n(s.outUInt + i, count, noId);
                    }
                }
            }
            if (blend) colour.blendRow(row, w, winner.data(), colourOut);
        }
    });
    ctx.progress(1.0);
    ctx.set(result_, out);
}

}  // namespace darkroom
