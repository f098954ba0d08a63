#include "pass_bench.h"

// Three directional lights with Blinn-Phong on captured normals: reads Z,
// N.x/N.y/N.z, R, G, B.
static void BM_Lighting(benchmark::State& state) {
    darkroom::bench::runPass(state, "Lighting", int(state.range(0)), 7,
                             {{"mode", darkroom::Value("directional")}, {"lightCount", darkroom::Value(3)}});
}
BENCHMARK(BM_Lighting)->Arg(1024)->Arg(2048)->Unit(benchmark::kMillisecond)->UseRealTime();
