#include "pass_bench.h"

#include <string>

// Sigma as a fraction of the image height (the pass's default unit): 0.5 %,
// 1 % (the default: ~10 px at 1024, ~20 px at 2048), 2 % and 5 %. The box
// cascade's cost should not depend on it. Reads Z.
static void BM_SSDD(benchmark::State& state) {
    const double sigma = double(state.range(1)) / 1000.0;
    state.SetLabel("sigma " + std::to_string(state.range(1) / 10.0).substr(0, 3) + " % of height");
    darkroom::bench::runPass(state, "SSDD", int(state.range(0)), 1, {{"sigma", darkroom::Value(sigma)}});
}
BENCHMARK(BM_SSDD)
    ->ArgsProduct({{1024, 2048}, {5, 10, 20, 50}})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
