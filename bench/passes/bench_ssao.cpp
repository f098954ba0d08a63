#include "pass_bench.h"

// SSAO reads Z only (normals are reconstructed) and writes AO; the pass also
// copies every input channel through, which the memcpy baseline does not count.
// Unnamed variants run at the pass's default resolution (half); *Full at every
// pixel.
static void ssao(benchmark::State& state, const char* method, int quality1, int quality2,
                 const char* geometry = "surface", const char* resolution = nullptr, double radius = 0) {
    std::map<std::string, darkroom::Value> p{{"method", darkroom::Value(method)},
                                             {"geometry", darkroom::Value(geometry)}};
    if (resolution) p["resolution"] = darkroom::Value(resolution);
    if (radius > 0) p["radius"] = darkroom::Value(radius);
    if (std::string(method) == "hemisphere") {
        p["samples"] = darkroom::Value(std::int64_t(quality1));
    } else {
        p["slices"] = darkroom::Value(std::int64_t(quality1));
        p["steps"] = darkroom::Value(std::int64_t(quality2));
    }
    darkroom::bench::runPass(state, "SSAO", int(state.range(0)), 1, p);
}

static void BM_SSAO_Hemisphere8(benchmark::State& s) { ssao(s, "hemisphere", 8, 0); }
static void BM_SSAO_Hemisphere16(benchmark::State& s) { ssao(s, "hemisphere", 16, 0); }
static void BM_SSAO_Hemisphere32(benchmark::State& s) { ssao(s, "hemisphere", 32, 0); }
static void BM_SSAO_Horizon2x4(benchmark::State& s) { ssao(s, "horizon", 2, 4); }
static void BM_SSAO_Horizon4x8(benchmark::State& s) { ssao(s, "horizon", 4, 8); }
static void BM_SSAO_Hemisphere16Points(benchmark::State& s) { ssao(s, "hemisphere", 16, 0, "points"); }
static void BM_SSAO_Horizon4x8Points(benchmark::State& s) { ssao(s, "horizon", 4, 8, "points"); }
static void BM_SSAO_Hemisphere16Full(benchmark::State& s) { ssao(s, "hemisphere", 16, 0, "surface", "full"); }
static void BM_SSAO_Horizon4x8Full(benchmark::State& s) { ssao(s, "horizon", 4, 8, "surface", "full"); }
// The demo pipeline's radius (0.08 image heights: 82 px at 1024, 164 at
// 2048; the default is 0.05), where the samples reach farthest.
static void BM_SSAO_Horizon4x8R08(benchmark::State& s) { ssao(s, "horizon", 4, 8, "surface", nullptr, 0.08); }
BENCHMARK(BM_SSAO_Hemisphere8)->Arg(1024)->Arg(2048)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_SSAO_Hemisphere16)->Arg(1024)->Arg(2048)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_SSAO_Hemisphere32)->Arg(1024)->Arg(2048)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_SSAO_Horizon2x4)->Arg(1024)->Arg(2048)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_SSAO_Horizon4x8)->Arg(1024)->Arg(2048)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_SSAO_Hemisphere16Points)->Arg(1024)->Arg(2048)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_SSAO_Horizon4x8Points)->Arg(1024)->Arg(2048)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_SSAO_Hemisphere16Full)->Arg(1024)->Arg(2048)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_SSAO_Horizon4x8Full)->Arg(1024)->Arg(2048)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_SSAO_Horizon4x8R08)->Arg(1024)->Arg(2048)->Unit(benchmark::kMillisecond)->UseRealTime();
