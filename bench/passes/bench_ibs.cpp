#include "pass_bench.h"

// Default: width 1, object ids on; reads Z, objectId, R, G, B, A.
static void BM_IBS(benchmark::State& state) {
    darkroom::bench::runPass(state, "IBS", int(state.range(0)), 6);
}
// With the headlight term on captured normals (reads N.* too).
static void BM_IBS_Lighting(benchmark::State& state) {
    darkroom::bench::runPass(state, "IBS", int(state.range(0)), 9, {{"lighting", darkroom::Value(true)}});
}
BENCHMARK(BM_IBS)->Arg(1024)->Arg(2048)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_IBS_Lighting)->Arg(1024)->Arg(2048)->Unit(benchmark::kMillisecond)->UseRealTime();
