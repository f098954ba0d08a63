#include "pass_bench.h"

// Halving a size x size G-buffer (10 channels). MP/s counts OUTPUT pixels
// (size/2 squared; input megapixels/s are 4x that); the memcpy reference is
// the 10 input channels (40 per output pixel) plus the 10 output channels.
static void resize(benchmark::State& state, const char* filter) {
    const int size = int(state.range(0));
    darkroom::bench::runPassWithImages(state, "Resize", size / 2, 40,
                                       {{"image", {darkroom::bench::syntheticGBuffer(size)}}},
                                       {{"scale", darkroom::Value(0.5)}, {"filter", darkroom::Value(filter)}});
}
static void BM_ResizeBoxHalf(benchmark::State& state) { resize(state, "box"); }
static void BM_ResizeBilinearHalf(benchmark::State& state) { resize(state, "bilinear"); }
BENCHMARK(BM_ResizeBoxHalf)->Arg(1024)->Arg(2048)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_ResizeBilinearHalf)->Arg(1024)->Arg(2048)->Unit(benchmark::kMillisecond)->UseRealTime();
