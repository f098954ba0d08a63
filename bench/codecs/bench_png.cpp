// PNG encoding of a colour-mapped picture (test_picture.h) at 1024² and
// 2048²: time per encode and the file's bytes (counter "bytes"), for the
// writer before libdeflate (libpng, zlib level 2, "up"), libpng's default,
// zlib level 1 with each filter, libdeflate at several levels and filters,
// and the run encoder the writer uses (run_deflate.h) with each filter
// (docs/performance.md, "Codecs").
#include "libpng_encode.h"
#include "test_picture.h"

#include "png_encoder.h"

#include <benchmark/benchmark.h>
#include <png.h>

#include <algorithm>
#include <functional>
#include <string>
#include <vector>

namespace {

using darkroom::io::PngFilter;
using Encode = std::function<std::string(const std::vector<unsigned char>&, int)>;

void run(benchmark::State& state, const Encode& encode) {
    const int size = int(state.range(0));
    const auto picture = darkroom::bench::colourMappedPicture(size);
    std::size_t bytes = 0;
    for (auto _ : state) {
        const std::string png = encode(picture, size);
        bytes = png.size();
        benchmark::DoNotOptimize(png.data());
    }
    state.counters["bytes"] = double(bytes);
}

Encode libpng(int level, int filters) {
    return [=](const std::vector<unsigned char>& p, int size) {
        return darkroom::bench::libpngEncode(p.data(), size, size, 4, level, filters);
    };
}

Encode libdeflate(int level, PngFilter filter) {
    return [=](const std::vector<unsigned char>& p, int size) {
        return darkroom::io::encodePng({size, size, 4, p.data()}, {filter, level});
    };
}

Encode runs(PngFilter filter) {
    return [=](const std::vector<unsigned char>& p, int size) {
        return darkroom::io::encodePng({size, size, 4, p.data()}, {filter, 1, darkroom::io::Deflater::Runs});
    };
}

double minimum(const std::vector<double>& v) { return v.empty() ? 0.0 : *std::min_element(v.begin(), v.end()); }

void add(const std::string& name, Encode encode) {
    benchmark::RegisterBenchmark(("png/" + name).c_str(), [encode](benchmark::State& s) { run(s, encode); })
        ->Arg(1024)
        ->Arg(2048)
        ->Unit(benchmark::kMillisecond)
        ->UseRealTime()
        ->ComputeStatistics("min", minimum);  // the least disturbed by a shared machine's load
}

int registerAll() {
    add("libpng_z2_up_before", libpng(2, PNG_FILTER_UP));
    add("libpng_z6_adaptive_default", libpng(6, PNG_ALL_FILTERS));
    add("libpng_z1_none", libpng(1, PNG_FILTER_NONE));
    add("libpng_z1_sub", libpng(1, PNG_FILTER_SUB));
    add("libpng_z1_up", libpng(1, PNG_FILTER_UP));
    add("libpng_z1_paeth", libpng(1, PNG_FILTER_PAETH));
    add("libpng_z1_adaptive", libpng(1, PNG_ALL_FILTERS));
    const std::pair<const char*, PngFilter> filters[] = {{"none", PngFilter::None},   {"sub", PngFilter::Sub},
                                                         {"up", PngFilter::Up},       {"paeth", PngFilter::Paeth},
                                                         {"adaptive", PngFilter::Adaptive}};
    for (const auto& [name, f] : filters) add(std::string("libdeflate_l1_") + name, libdeflate(1, f));
    for (int level : {2, 3, 4, 6})
        add("libdeflate_l" + std::to_string(level) + "_up", libdeflate(level, PngFilter::Up));
    add("libdeflate_l6_adaptive", libdeflate(6, PngFilter::Adaptive));
    for (const auto& [name, f] : filters) add(std::string("runs_") + name, runs(f));
    return 0;
}
const int registered = registerAll();

}  // namespace
