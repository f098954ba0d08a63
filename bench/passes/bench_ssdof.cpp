#include "pass_bench.h"

#include <string>

// SSDoF on the synthetic terrain (depth 5 +- 0.2, ~37 % background), focused on
// the centre; a lens of 1 world unit gives the terrain CoCs of a few pixels on
// both sides of the focal plane and the background the clamped maximum, so
// maxBlur sets the cost. Reads R, G, B, A, Z.
namespace {

std::map<std::string, darkroom::Value> lens(const char* method, double maxBlur, int samples) {
    return {{"method", darkroom::Value(method)},
            {"aperture", darkroom::Value(1.0)},
            {"focalDistance", darkroom::Value(0.0)},
            {"maxBlur", darkroom::Value(maxBlur)},
            {"samples", darkroom::Value(std::int64_t(samples))}};
}

}  // namespace

// Args: size, maxBlur, samples.
static void BM_SSDoF_Disc(benchmark::State& state) {
    state.SetLabel("maxBlur " + std::to_string(state.range(1)) + ", " + std::to_string(state.range(2)) + " taps");
    darkroom::bench::runPass(state, "SSDoF", int(state.range(0)), 5,
                             lens("disc", double(state.range(1)), int(state.range(2))));
}
BENCHMARK(BM_SSDoF_Disc)
    ->ArgsProduct({{1024, 2048}, {8, 16}, {16, 32, 64}})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

// Args: size, maxBlur.
static void BM_SSDoF_Hexagon(benchmark::State& state) {
    state.SetLabel("maxBlur " + std::to_string(state.range(1)));
    darkroom::bench::runPass(state, "SSDoF", int(state.range(0)), 5,
                             lens("hexagon", double(state.range(1)), 32));
}
BENCHMARK(BM_SSDoF_Hexagon)
    ->ArgsProduct({{1024, 2048}, {8, 16}})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
