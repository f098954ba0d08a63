#include "pass_bench.h"

// FXAA filters R, G, B, A and copies the other 6 channels of the synthetic
// G-buffer through, so it must read all 10 input channels (and write 10).
static void BM_FXAA(benchmark::State& state) {
    const std::string preset = std::to_string(state.range(1));
    state.SetLabel("preset " + preset);
    darkroom::bench::runPass(state, "FXAA", int(state.range(0)), 10, {{"preset", darkroom::Value(preset)}});
}
BENCHMARK(BM_FXAA)
    ->ArgsProduct({{1024, 2048}, {12, 29, 39}})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
