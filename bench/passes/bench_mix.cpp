#include "pass_bench.h"

// Multiply colour by a factor channel of the same image (how AO is applied):
// reads R, G, B, A, the factor and Z (background is left alone); writes R, G,
// B, A; the other channels are the input's planes, shared.
static void BM_MixMultiply(benchmark::State& state) {
    darkroom::bench::runPass(state, "Mix", int(state.range(0)), 6,
                             {{"factorChannel", darkroom::Value("value")}});
}
BENCHMARK(BM_MixMultiply)->Arg(1024)->Arg(2048)->Unit(benchmark::kMillisecond)->UseRealTime();

// 'other' over 'image': both colours read (R, G, B, A of each); R, G, B, A written.
static void BM_MixOver(benchmark::State& state) {
    const int size = int(state.range(0));
    const darkroom::BufferPtr g = darkroom::bench::syntheticGBuffer(size);
    darkroom::bench::runPassWithImages(state, "Mix", size, 8, {{"image", {g}}, {"other", {g}}},
                                       {{"mode", darkroom::Value("over")}});
}
BENCHMARK(BM_MixOver)->Arg(1024)->Arg(2048)->Unit(benchmark::kMillisecond)->UseRealTime();
