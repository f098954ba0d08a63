#include "colour_blend.h"

#include <darkroom/layer_blend.h>
#include <darkroom/layers.h>

namespace darkroom::compositing {

ColourLayers::ColourLayers(const std::vector<BufferPtr>& inputs, const std::string& depthName) {
    for (std::size_t i = 0; i < inputs.size(); ++i) {
        const Buffer& b = *inputs[i];
        const int count = layers::count(b);
        frontAlpha_.push_back(nullptr);
        for (int k = 0; k < count; ++k) {
            auto f = [&](const char* name) { return b.hostFloat(layers::channel(name, k)); };
            const Layer l{int(i), b.hostFloat(layers::channel(depthName, k)), f("R"), f("G"), f("B"), f("A")};
            if (!l.z || !l.r || !l.g || !l.b || !l.a) continue;
            if (k == 0) frontAlpha_.back() = l.a;
            layers_.push_back(l);
        }
    }
}

void ColourLayers::blendRow(std::size_t row, int width, const int* winner, float* const out[4]) const {
    std::vector<layers::Surface> s(layers_.size());
    for (int x = 0; x < width; ++x) {
        const int k = winner[x];
        if (k < 0) continue;
        const std::size_t i = row + std::size_t(x);
        const float* front = frontAlpha_[std::size_t(k)];
        // An opaque nearest surface hides everything behind it: the z-buffer
        // merge already wrote its colour (NaN alpha counts as opaque, as it did).
        if (!front || !(front[i] < 1)) continue;
        for (std::size_t l = 0; l < layers_.size(); ++l) {
            const Layer& L = layers_[l];
            s[l] = {L.z[i], L.r[i], L.g[i], L.b[i], L.a[i]};
        }
        const layers::Blended c = layers::blendFrontToBack(s.data(), int(s.size()));
        // Nothing visible (every surface transparent): keep the nearest
        // surface's own values, as a z-buffer merge gives them.
        if (c.contributing == 0) continue;
        out[0][i] = c.r;
        out[1][i] = c.g;
        out[2][i] = c.b;
        out[3][i] = c.a;
    }
}

}  // namespace darkroom::compositing
