#include "pass_bench.h"

static void BM_ColorMapping(benchmark::State& state) {
    darkroom::bench::runPass(state, "ColorMapping", int(state.range(0)), 2,
                             {{"channel", darkroom::Value("value")}});
}
BENCHMARK(BM_ColorMapping)->Arg(1024)->Arg(2048)->Unit(benchmark::kMillisecond)->UseRealTime();
