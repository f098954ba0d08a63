#include "pass_bench.h"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

namespace {

// `count` spheres spread over the synthetic G-buffer's view (camera at z = 5
// looking down -z, 30 degrees): radius 0.01 (about 2 px at 1024^2).
std::string pointList(int count) {
    const std::string path =
        (std::filesystem::temp_directory_path() / ("darkroom-bench-spheres-" + std::to_string(count) + ".csv")).string();
    std::ofstream out(path);
    out << "x,y,z,radius,value\n";
    for (int i = 0; i < count; ++i) {
        const double a = 0.61803398875 * i, r = std::sqrt((i + 0.5) / count);
        out << 1.2 * r * std::cos(6.2831853 * a) << "," << 1.2 * r * std::sin(6.2831853 * a) << ","
            << 0.2 * std::sin(0.37 * i) << ",0.01," << i << "\n";
    }
    return path;
}

}  // namespace

// Reads only the input's camera; writes Z, N.x/N.y/N.z, value and pointId.
static void BM_Spheres(benchmark::State& state) {
    static const std::string path = pointList(int(state.range(1)));
    darkroom::bench::runPass(state, "Spheres", int(state.range(0)), 0, {{"points", darkroom::Value(path)}});
}
BENCHMARK(BM_Spheres)->Args({1024, 10000})->Args({2048, 10000})->Unit(benchmark::kMillisecond)->UseRealTime();
