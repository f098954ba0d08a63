#include "pass_bench.h"

#include <cmath>

namespace {

// n copies of the synthetic G-buffer, each pushed back and forth in depth by
// its own smooth pattern so that the winner changes across the image.
std::vector<darkroom::BufferPtr> layers(int size, int n) {
    const darkroom::BufferPtr g = darkroom::bench::syntheticGBuffer(size);
    std::vector<darkroom::BufferPtr> out;
    for (int k = 0; k < n; ++k) {
        auto b = darkroom::makeCpuBuffer(size, size, g->channels());
        b->metadata() = g->metadata();
        const std::size_t px = g->pixelCount();
        for (const auto& c : g->channels()) {
            if (c.type == darkroom::ChannelType::UInt32) {
                std::copy_n(g->hostUInt(c.name), px, b->writeUInt(c.name));
                continue;
            }
            std::copy_n(g->hostFloat(c.name), px, b->writeFloat(c.name));
        }
        float* z = b->writeFloat("Z");
        for (int y = 0; y < size; ++y)
            for (int x = 0; x < size; ++x)
                z[std::size_t(y) * size + x] += 0.3f * float(std::sin(0.02 * x * (k + 1) + 0.013 * y * (3 - k)));
        out.push_back(b);
    }
    return out;
}

void compositing(benchmark::State& state, int n) {
    const int size = int(state.range(0));
    // Reads every input's depth and the winner's 10 channels; writes 10.
    darkroom::bench::runPassWithImages(state, "Compositing", size, n + 9, {{"images", layers(size, n)}});
}

}  // namespace

static void BM_Compositing2(benchmark::State& state) { compositing(state, 2); }
static void BM_Compositing4(benchmark::State& state) { compositing(state, 4); }
BENCHMARK(BM_Compositing2)->Arg(1024)->Arg(2048)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_Compositing4)->Arg(1024)->Arg(2048)->Unit(benchmark::kMillisecond)->UseRealTime();
