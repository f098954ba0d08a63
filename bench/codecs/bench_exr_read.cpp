// Reading a 2048² EXR of R, G, B, A, Z and a scalar (float, zip: what
// CinemaWriter writes), and one of Z and `height` alone (what `darkroom
// capture` writes for a surface): with OpenEXR's C++ library, its global
// thread pool at 0 (the reading thread alone), 1 and 2 threads, and with the
// direct decoder (exr_direct.h) on one TBB thread and on all
// (docs/performance.md, "Codecs").
#include "exr_file.h"

#include <darkroom/buffer.h>
#include <darkroom/data/image_io.h>

#include <ImfThreading.h>
#include <benchmark/benchmark.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include <unistd.h>

namespace {

namespace fs = std::filesystem;

// Written once per process into the temporary folder; removed at exit.
struct ExrFile {
    std::string path;
    explicit ExrFile(const std::vector<const char*>& names) {
        path = (fs::temp_directory_path() /
                ("darkroom_bench_exr_" + std::to_string(::getpid()) + "_" + std::to_string(names.size()) + ".exr"))
                   .string();
        const int n = 2048;
        std::vector<darkroom::ChannelDesc> channels;
        for (const char* name : names) channels.push_back({name, darkroom::ChannelType::Float32});
        auto b = darkroom::makeCpuBuffer(n, n, channels);
        for (std::size_t c = 0; c < names.size(); ++c) {
            float* p = b->writeFloat(names[c]);
            const bool depth = std::string(names[c]) == "Z";
            const float scale = depth ? 10.0f : 1.0f, background = depth ? INFINITY : 0.0f;
            for (int y = 0; y < n; ++y)
                for (int x = 0; x < n; ++x) {
                    const float u = float(x) / n, v = float(y) / n;
                    const bool inside = (u - 0.5f) * (u - 0.5f) + (v - 0.5f) * (v - 0.5f) < 0.16f;
                    p[std::size_t(y) * n + x] =
                        inside ? std::sin(float(c + 1) * u * 7.0f + v * 3.0f) * scale : background;
                }
        }
        darkroom::writeImage(*b, path);
        darkroom::readImage(path);  // sizes OpenEXR's pool once (exr_file.cpp), before the benchmarks set it
    }
    ~ExrFile() {
        std::error_code ec;
        fs::remove(path, ec);
    }
};

const ExrFile& sixChannels() {
    static const ExrFile file({"R", "G", "B", "A", "Z", "value"});
    return file;
}
const ExrFile& depthAndHeight() {
    static const ExrFile file({"Z", "height"});
    return file;
}

// OpenEXR's C++ library with its pool at range(0) threads.
void readWithOpenExr(benchmark::State& state, const std::string& path) {
    Imf::setGlobalThreadCount(int(state.range(0)));
    for (auto _ : state) benchmark::DoNotOptimize(darkroom::io::readExr(path, darkroom::io::ExrPixelPath::OpenExrOnly));
    state.counters["threads"] = double(state.range(0));
}
// The direct decoder in a TBB arena of range(0) threads (0: TBB's default, all cores).
void readDirect(benchmark::State& state, const std::string& path) {
    tbb::task_arena arena(state.range(0) > 0 ? int(state.range(0)) : tbb::task_arena::automatic);
    for (auto _ : state) arena.execute([&] { benchmark::DoNotOptimize(darkroom::io::readExr(path)); });
    state.counters["threads"] = double(arena.max_concurrency());
}

void BM_ExrRead(benchmark::State& state) { readWithOpenExr(state, sixChannels().path); }
void BM_ExrReadDirect(benchmark::State& state) { readDirect(state, sixChannels().path); }
void BM_ExrReadZHeight(benchmark::State& state) { readWithOpenExr(state, depthAndHeight().path); }
void BM_ExrReadZHeightDirect(benchmark::State& state) { readDirect(state, depthAndHeight().path); }
double minimum(const std::vector<double>& v) { return v.empty() ? 0.0 : *std::min_element(v.begin(), v.end()); }
// The least of the repetitions is the one least disturbed by a shared machine's load.
BENCHMARK(BM_ExrRead)->Arg(0)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime()->ComputeStatistics("min", minimum);
BENCHMARK(BM_ExrReadDirect)->Arg(1)->Arg(0)->Unit(benchmark::kMillisecond)->UseRealTime()->ComputeStatistics("min", minimum);
BENCHMARK(BM_ExrReadZHeight)->Arg(0)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime()->ComputeStatistics("min", minimum);
BENCHMARK(BM_ExrReadZHeightDirect)->Arg(1)->Arg(0)->Unit(benchmark::kMillisecond)->UseRealTime()->ComputeStatistics("min", minimum);

}  // namespace
