#include "pass_bench.h"

// FXAA reads R, G, B, A and writes them; the other 6 channels of the
// synthetic G-buffer are the input's planes, shared.
static void BM_FXAA(benchmark::State& state) {
    const std::string preset = std::to_string(state.range(1));
    state.SetLabel("preset " + preset);
    darkroom::bench::runPass(state, "FXAA", int(state.range(0)), 4, {{"preset", darkroom::Value(preset)}});
}
BENCHMARK(BM_FXAA)
    ->ArgsProduct({{1024, 2048}, {12, 29, 39}})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
