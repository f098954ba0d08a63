// Reading a 2048² EXR of R, G, B, A, Z and a scalar (float, zip: what
// CinemaWriter writes) with OpenEXR's global thread pool at 0 (the reading
// thread alone), 1 and 2 threads (docs/performance.md, "Codecs").
#include <darkroom/buffer.h>
#include <darkroom/data/image_io.h>

#include <ImfThreading.h>
#include <benchmark/benchmark.h>

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
    ExrFile() {
        path = (fs::temp_directory_path() / ("darkroom_bench_exr_" + std::to_string(::getpid()) + ".exr")).string();
        const int n = 2048;
        const char* names[] = {"R", "G", "B", "A", "Z", "value"};
        std::vector<darkroom::ChannelDesc> channels;
        for (const char* name : names) channels.push_back({name, darkroom::ChannelType::Float32});
        auto b = darkroom::makeCpuBuffer(n, n, channels);
        for (int c = 0; c < 6; ++c) {
            float* p = b->writeFloat(names[c]);
            const float scale = c == 4 ? 10.0f : 1.0f, background = c == 4 ? INFINITY : 0.0f;
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

const ExrFile& exrFile() {
    static const ExrFile file;
    return file;
}

void BM_ExrRead(benchmark::State& state) {
    const std::string& path = exrFile().path;
    Imf::setGlobalThreadCount(int(state.range(0)));
    for (auto _ : state) benchmark::DoNotOptimize(darkroom::readImage(path));
    state.counters["threads"] = double(state.range(0));
}
double minimum(const std::vector<double>& v) { return v.empty() ? 0.0 : *std::min_element(v.begin(), v.end()); }
BENCHMARK(BM_ExrRead)
    ->Arg(0)
    ->Arg(1)
    ->Arg(2)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->ComputeStatistics("min", minimum);  // the least disturbed by a shared machine's load

}  // namespace
