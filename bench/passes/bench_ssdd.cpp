#include "pass_bench.h"

// Default sigma (1 % of the image height: ~10 px at 1024, ~20 px at 2048).
static void BM_SSDD(benchmark::State& state) {
    darkroom::bench::runPass(state, "SSDD", int(state.range(0)), 1);
}
BENCHMARK(BM_SSDD)->Arg(1024)->Arg(2048)->Unit(benchmark::kMillisecond)->UseRealTime();
