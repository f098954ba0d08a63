#include "pass_bench.h"

// Default: 2 scales of 8 neighbours in log depth; reads Z, R, G, B.
static void BM_EyeDomeLighting(benchmark::State& state) {
    darkroom::bench::runPass(state, "EyeDomeLighting", int(state.range(0)), 4);
}
BENCHMARK(BM_EyeDomeLighting)->Arg(1024)->Arg(2048)->Unit(benchmark::kMillisecond)->UseRealTime();
