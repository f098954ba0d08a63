#include "pass_bench.h"

#include <darkroom/core/registry.h>
#include <darkroom/core/run_filter.h>

#include <algorithm>
#include <chrono>
#include <ctime>
#include <set>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <limits>

namespace darkroom::bench {

namespace {
Registry& registry() {
    static Registry* r = [] {
        auto* x = new Registry();
        // DARKROOM_BENCH_PLUGIN_DIR in the environment times another build's
        // plugins (e.g. a copy of the tree before a change) with this harness.
        const char* dir = std::getenv("DARKROOM_BENCH_PLUGIN_DIR");
        x->loadPlugins({dir && *dir ? dir : DARKROOM_BENCH_PLUGIN_DIR});
        return x;
    }();
    return *r;
}

// A memcpy of `bytes` between two buffers whose pages are already mapped.
class MemcpyReference {
public:
    explicit MemcpyReference(std::size_t bytes) : a_(bytes, 1), b_(bytes, 2) {}
    double seconds() {
        const auto t0 = std::chrono::steady_clock::now();
        std::memcpy(b_.data(), a_.data(), a_.size());
        benchmark::DoNotOptimize(b_.data());
        benchmark::ClobberMemory();
        return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    }

private:
    std::vector<char> a_, b_;
};

// CPU time of the whole process (all threads), seconds.
double processCpuSeconds() {
    timespec ts;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
    return double(ts.tv_sec) + 1e-9 * double(ts.tv_nsec);
}

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    const std::size_t n = v.size();
    return n == 0 ? 0.0 : (n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]));
}
}  // namespace

BufferPtr syntheticGBuffer(int size) {
    std::vector<ChannelDesc> ch = {{"Z"}, {"N.x"}, {"N.y"}, {"N.z"}, {"value"}, {"R"}, {"G"}, {"B"}, {"A"},
                                   {"objectId", ChannelType::UInt32}};
    auto b = makeCpuBuffer(size, size, ch);
    Camera cam;
    cam.width = cam.height = size;
    cam.position = {0, 0, 5};
    cam.forward = {0, 0, -1};
    b->metadata().camera = cam;
    float* z = b->writeFloat("Z");
    float* v = b->writeFloat("value");
    float* nx = b->writeFloat("N.x");
    float* ny = b->writeFloat("N.y");
    float* nz = b->writeFloat("N.z");
    float* rgba[4] = {b->writeFloat("R"), b->writeFloat("G"), b->writeFloat("B"), b->writeFloat("A")};
    std::uint32_t* id = b->writeUInt("objectId");
    for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x) {
            const std::size_t i = std::size_t(y) * size + x;
            const double u = double(x) / size, w = double(y) / size;
            const bool bg = (u - 0.5) * (u - 0.5) + (w - 0.5) * (w - 0.5) > 0.2;
            const double h = 0.2 * std::sin(12 * u) * std::cos(9 * w);
            z[i] = bg ? std::numeric_limits<float>::infinity() : float(5.0 - h);
            v[i] = float(h);
            const double gx = 0.2 * 12 * std::cos(12 * u) * std::cos(9 * w), gy = -0.2 * 9 * std::sin(12 * u) * std::sin(9 * w);
            const double l = std::sqrt(gx * gx + gy * gy + 1);
            nx[i] = float(-gx / l);
            ny[i] = float(gy / l);
            nz[i] = float(1 / l);
            for (int c = 0; c < 3; ++c) rgba[c][i] = float(0.5 + 0.5 * std::sin(h * 10 + c));
            rgba[3][i] = bg ? 0.0f : 1.0f;
            id[i] = bg ? ~0u : std::uint32_t(x / 64 + y / 64);
        }
    return b;
}

namespace {

// Times `filter` on `inputs` and sets the counters described in pass_bench.h.
void timePass(benchmark::State& state, Filter& filter, const std::map<std::string, std::vector<Value>>& inputs,
              int size, int channelsRead) {
    FilterRunOptions o;
    o.registry = &registry();
    o.poison = false;
    // One warm-up run tells how many planes the pass writes: those of its
    // outputs that are not an input's plane passed on.
    const FilterRunResult warm = runFilter(filter, inputs, o);
    std::set<const Plane*> inputPlanes;
    for (const auto& [port, values] : inputs)
        for (const auto& v : values)
            if (const auto* b = std::get_if<BufferPtr>(&v.storage()); b && *b)
                for (const auto& c : (*b)->channels()) inputPlanes.insert((*b)->plane(c.name).get());
    std::size_t written = 0;
    for (const auto& [k, v] : warm.outputs)
        if (const auto* b = std::get_if<BufferPtr>(&v.storage()); b && *b)
            for (const auto& c : (*b)->channels()) written += inputPlanes.count((*b)->plane(c.name).get()) ? 0 : 1;
    const std::size_t bytes = std::size_t(size) * size * 4 * (std::size_t(channelsRead) + written);
    // The memcpy runs before every iteration (outside the timed part), so the
    // two see the same load of a shared machine; the ratio is of the medians.
    MemcpyReference copy(bytes);
    std::vector<double> passTimes, copyTimes, cpuTimes;
    for (auto _ : state) {
        state.PauseTiming();
        copyTimes.push_back(copy.seconds());
        state.ResumeTiming();
        const double c0 = processCpuSeconds();
        const auto t0 = std::chrono::steady_clock::now();
        {
            FilterRunResult r = runFilter(filter, inputs, o);
            benchmark::DoNotOptimize(r);
        }
        passTimes.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
        cpuTimes.push_back(processCpuSeconds() - c0);
    }
    const double per = median(passTimes);
    state.counters["MP/s"] = double(size) * size / per / 1e6;
    state.counters["vs_memcpy"] = per / median(copyTimes);
    state.counters["median_ms"] = per * 1e3;
    // The work done, all threads together: steadier than wall time when other
    // processes hold the cores (it also counts the pool's threads waiting for work).
    state.counters["cpu_ms"] = median(cpuTimes) * 1e3;
    state.counters["bytes"] = double(bytes);
}

}  // namespace

void runPass(benchmark::State& state, const std::string& type, int size, int channelsRead,
             const std::map<std::string, Value>& parameters) {
    auto filter = registry().createFilter(type);
    std::map<std::string, std::vector<Value>> inputs;
    const BufferPtr g = syntheticGBuffer(size);
    for (const auto& p : filter->ports().inputs)
        if (p.type == PortType::Image && !p.optional) inputs[p.name] = {Value(g)};
    for (const auto& [k, v] : parameters) inputs[k] = {v};
    timePass(state, *filter, inputs, size, channelsRead);
}

void runPassWithImages(benchmark::State& state, const std::string& type, int size, int channelsRead,
                       const std::map<std::string, std::vector<BufferPtr>>& images,
                       const std::map<std::string, Value>& parameters) {
    auto filter = registry().createFilter(type);
    std::map<std::string, std::vector<Value>> inputs;
    for (const auto& [port, buffers] : images)
        for (const auto& b : buffers) inputs[port].emplace_back(b);  // in place: push_back(Value(b)) trips GCC 12's maybe-uninitialized
    for (const auto& [k, v] : parameters) inputs[k] = {v};
    timePass(state, *filter, inputs, size, channelsRead);
}

}  // namespace darkroom::bench
