// Compositing translucent layered colour (issue 30): two databases, each a
// 2-layer RGBA image (ColorMapping with layers: keep), merged by depth and
// blended front to back: 4 layers per pixel. Every pixel is translucent, so
// every pixel takes the blend (the opaque path is bench_compositing.cpp).
#include "pass_bench.h"

#include <darkroom/layers.h>

#include <cmath>

namespace {

std::vector<darkroom::BufferPtr> translucentLayers(int size) {
    const darkroom::BufferPtr g = darkroom::bench::syntheticGBuffer(size);
    const std::size_t px = g->pixelCount();
    std::vector<darkroom::BufferPtr> out;
    for (int input = 0; input < 2; ++input) {
        std::vector<darkroom::ChannelDesc> channels;
        for (int k = 0; k < 2; ++k)
            for (const char* c : {"R", "G", "B", "A", "Z"}) channels.emplace_back(darkroom::layers::channel(c, k));
        auto b = darkroom::makeCpuBuffer(size, size, channels);
        b->metadata() = g->metadata();
        for (int k = 0; k < 2; ++k) {
            for (const char* c : {"R", "G", "B"})
                std::copy_n(g->hostFloat(c), px, b->writeFloat(darkroom::layers::channel(c, k)));
            std::fill_n(b->writeFloat(darkroom::layers::channel("A", k)), px, 0.5f);
            float* z = b->writeFloat(darkroom::layers::channel("Z", k));
            // The inputs' layers interleave differently across the image.
            for (int y = 0; y < size; ++y)
                for (int x = 0; x < size; ++x) {
                    const std::size_t i = std::size_t(y) * std::size_t(size) + std::size_t(x);
                    const float wave = float(std::sin(0.02 * x * (input + 1) + 0.013 * y * (2 - input)));
                    z[i] = g->hostFloat("Z")[i] + 0.3f * wave + float(k) * (1.0f + 0.2f * float(input));
                }
        }
        out.push_back(b);
    }
    return out;
}

void compositingLayers(benchmark::State& state) {
    const int size = int(state.range(0));
    // Reads R, G, B, A, Z of 4 layers (20 planes); writes R, G, B, A, Z.
    darkroom::bench::runPassWithImages(state, "Compositing", size, 20, {{"images", translucentLayers(size)}});
}

}  // namespace

static void BM_CompositingLayers4Translucent(benchmark::State& state) { compositingLayers(state); }
BENCHMARK(BM_CompositingLayers4Translucent)->Arg(1024)->Unit(benchmark::kMillisecond)->UseRealTime();
