#include "pass_bench.h"

// Overlays copy R, G, B, A and draw a few thousand pixels of text: the copy
// dominates, so they are measured against it.
static void BM_ColorLegend(benchmark::State& state) {
    darkroom::bench::runPass(state, "ColorLegend", int(state.range(0)), 4, {{"title", darkroom::Value("Height")}});
}
static void BM_Annotation(benchmark::State& state) {
    darkroom::bench::runPass(state, "Annotation", int(state.range(0)), 4,
                             {{"text", darkroom::Value("t = {time:.2f} s")}, {"row", darkroom::Value("time=1.5")}});
}
BENCHMARK(BM_ColorLegend)->Arg(1024)->Arg(2048)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_Annotation)->Arg(1024)->Arg(2048)->Unit(benchmark::kMillisecond)->UseRealTime();
