#include "pass_bench.h"

// Reads Z; replace = true so the synthetic G-buffer's N.* are reconstructed, not kept.
static void BM_Normals(benchmark::State& state) {
    darkroom::bench::runPass(state, "Normals", int(state.range(0)), 1, {{"replace", darkroom::Value(true)}});
}
BENCHMARK(BM_Normals)->Arg(1024)->Arg(2048)->Unit(benchmark::kMillisecond)->UseRealTime();
