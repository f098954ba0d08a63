#include "pass_bench.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <utility>
#include <vector>

// FXAA reads R, G, B, A and writes them; the other 6 channels of the
// synthetic G-buffer are the input's planes, shared.
static void BM_FXAA(benchmark::State& state) {
    const std::string preset = std::to_string(state.range(1));
    state.SetLabel("preset " + preset);
    darkroom::bench::runPass(state, "FXAA", int(state.range(0)), 4, {{"preset", darkroom::Value(preset)}});
}
BENCHMARK(BM_FXAA)
    ->ArgsProduct({{1024, 2048}, {12, 29, 39}})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

namespace {

// A small deterministic generator, so every run draws the same picture.
class Lcg {
public:
    explicit Lcg(std::uint32_t seed) : s_(seed) {}
    double next() {
        s_ = s_ * 1664525u + 1013904223u;
        return double(s_ >> 8) / double(1u << 24);
    }

private:
    std::uint32_t s_;
};

// RGBA planes being painted; disc() stamps a filled disc of one colour.
struct Canvas {
    int size;
    float* c[4];
    void disc(double cx, double cy, double radius, const float rgb[3]) {
        const int x0 = std::max(0, int(cx - radius)), x1 = std::min(size - 1, int(cx + radius) + 1);
        const int y0 = std::max(0, int(cy - radius)), y1 = std::min(size - 1, int(cy + radius) + 1);
        for (int y = y0; y <= y1; ++y)
            for (int x = x0; x <= x1; ++x) {
                const double dx = x + 0.5 - cx, dy = y + 0.5 - cy;
                if (dx * dx + dy * dy > radius * radius) continue;
                const std::size_t i = std::size_t(y) * std::size_t(size) + std::size_t(x);
                for (int k = 0; k < 3; ++k) c[k][i] = rgb[k];
            }
    }
};

// The kind of picture the demo pipeline hands FXAA: a background gradient
// under many thin curved lines (streamlines) and small discs (particles),
// each with a dark outline (IBS), aliased, so that a large share of the
// pixels are edge pixels that go through the end-of-edge search. The
// terrain of syntheticGBuffer has few edges and hides that cost.
darkroom::BufferPtr edgeHeavyImage(int size) {
    auto b = darkroom::makeCpuBuffer(size, size, {{"R"}, {"G"}, {"B"}, {"A"}});
    Canvas canvas{size, {b->writeFloat("R"), b->writeFloat("G"), b->writeFloat("B"), b->writeFloat("A")}};
    for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x) {
            const std::size_t i = std::size_t(y) * std::size_t(size) + std::size_t(x);
            const float t = float(y) / float(size);
            canvas.c[0][i] = 0.02f + 0.25f * t;
            canvas.c[1][i] = 0.02f + 0.25f * t;
            canvas.c[2][i] = 0.25f + 0.1f * t;
            canvas.c[3][i] = 1.0f;
        }
    // The same picture at every size, as a scene rendered at a higher
    // resolution: lines and discs scale with the image (the share of edge
    // pixels halves from 1024² to 2048²).
    const double scale = size / 1024.0;
    const float outline[3] = {0.01f, 0.01f, 0.02f};
    Lcg rng(12345u);
    for (int line = 0; line < 80; ++line) {
        double x = rng.next() * size, y = rng.next() * size, angle = rng.next() * 6.2832;
        const double turn = (rng.next() - 0.5) * 0.01 / scale, radius = 1.5 + 1.5 * rng.next();
        const float colour[3] = {float(0.05 + 0.3 * rng.next()), float(0.3 + 0.5 * rng.next()), 0.4f};
        // The outline along the whole line first, then the line over it.
        std::vector<std::pair<double, double>> path;
        for (int step = 0; step < int(500 * scale); ++step, angle += turn) {
            x += std::cos(angle);
            y += std::sin(angle);
            path.emplace_back(x, y);
        }
        for (const auto& [px, py] : path) canvas.disc(px, py, (radius + 1.0) * scale, outline);
        for (const auto& [px, py] : path) canvas.disc(px, py, radius * scale, colour);
    }
    for (int particle = 0; particle < 1200; ++particle) {
        const double x = rng.next() * size, y = rng.next() * size, radius = (2.0 + 3.0 * rng.next()) * scale;
        const float colour[3] = {float(0.2 + 0.6 * rng.next()), 0.05f, float(0.1 + 0.3 * rng.next())};
        canvas.disc(x, y, radius + scale, outline);
        canvas.disc(x, y, radius, colour);
    }
    return b;
}

}  // namespace

// FXAA on edge-heavy pictures (lines and discs, as the demo's streamlines and
// particles): here the end-of-edge search, not memory, sets the time.
static void BM_FXAA_Edges(benchmark::State& state) {
    const std::string preset = std::to_string(state.range(1));
    state.SetLabel("lines and discs, preset " + preset);
    const int size = int(state.range(0));
    darkroom::bench::runPassWithImages(state, "FXAA", size, 4, {{"image", {edgeHeavyImage(size)}}},
                                       {{"preset", darkroom::Value(preset)}});
}
BENCHMARK(BM_FXAA_Edges)
    ->ArgsProduct({{1024, 2048}, {12, 39}})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
