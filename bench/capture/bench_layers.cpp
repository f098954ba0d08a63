// What layered captures cost (issue 30 items 1 and 4): capture time for K =
// 1, 2, 4, 8 surface crossings per pixel with both ways of finding them
// (one traversal with a K-nearest filter, one traversal per layer), and the
// two storage layouts for K layers: the flat one (K sets of channels in one
// multi-channel EXR, darkroom/layers.h, what every reader reads) against
// an OpenEXR deep image (one sample per crossing, missing layers not
// stored), bytes and write/read time.
//
//   bench_layers [--size WxH] [--reps R] [--out DIR]
//
// Captures run on one thread and are timed in CPU seconds of the process
// (the best of R), so that the ratios hold on a loaded machine; the report
// prints the load average. Scenes: two nested isosurfaces of the demo field
// and a stack of eight parallel sheets. bench/capture/run_layers_bench.sh
// runs it; docs/capture.md ("Layers") has the figures.
#include "embree_backend.h"
#include "embree_scene.h"
#include "layers_storage.h"

#include <darkroom/core/run_filter.h>
#include <darkroom/scene/camera_bounds.h>
#include <darkroom/scene/generators.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

using namespace darkroom;

namespace {

double cpuSeconds() {
    timespec ts;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
    return double(ts.tv_sec) + 1e-9 * double(ts.tv_nsec);
}

std::string loadAverage() {
    std::ifstream f("/proc/loadavg");
    std::string a, b, c;
    f >> a >> b >> c;
    return a + " " + b + " " + c;
}

struct BenchScene {
    std::string name;
    std::shared_ptr<Scene> scene;
};

BenchScene nestedIsosurfaces() {
    auto s = std::make_shared<Scene>();
    for (const char* iso : {"0.3", "0.6"})
        for (auto& o : generate("isosurface", {{"resolution", "96"}, {"isovalue", iso}})) s->objects.push_back(o);
    return {"nested isosurfaces (demo field at 0.3 and 0.6)", s};
}

BenchScene sheets() {
    auto s = std::make_shared<Scene>();
    for (int i = 0; i < 8; ++i) {
        const std::string z = std::to_string(-0.25 * i);
        for (auto& o : generate("plane", {{"size", "4"}, {"subdivisions", "32"}, {"center", "0," + std::string("0,") + z}}))
            s->objects.push_back(o);
    }
    return {"a stack of 8 sheets", s};
}

Camera cameraFor(const Scene& scene, int w, int h) {
    const Bounds b = scene.bounds();
    const Vec3 c = camera_bounds::sceneCentre(b);
    const double r = camera_bounds::sceneRadius(b);
    Camera cam;
    cam.width = w;
    cam.height = h;
    cam.fovYDegrees = 30;
    cam.position = c + Vec3{0.35 * r, 0.45 * r, 2.6 * r};
    cam.forward = normalize(c - cam.position);
    cam.up = {0, 1, 0};
    return cam;
}

CaptureRequest requestFor(const Scene& scene, int layers) {
    CaptureRequest r;
    for (const auto& f : scene.objects.front().fields)
        if (f.name != "N.x" && f.name != "N.y" && f.name != "N.z") r.scalars.push_back(f.name);
    r.normals = r.objectId = true;
    r.layers = layers;
    return r;
}

// The best of `reps` captures, in CPU seconds, and the last buffer.
double timeCapture(const embree::SceneBvh& bvh, const Camera& cam, const CaptureRequest& req,
                   embree::LayerMethod method, int reps, BufferPtr* out) {
    FilterRunOptions options;
    options.threads = 1;
    auto ctx = makeStandaloneContext(options, "bench-layers");
    double best = 1e30;
    for (int i = 0; i < reps; ++i) {
        const double t0 = cpuSeconds();
        BufferPtr g = embree::renderGBuffer(bvh, cam, req, *ctx, method);
        best = std::min(best, cpuSeconds() - t0);
        if (out) *out = std::move(g);
    }
    return best;
}

void benchScene(const BenchScene& s, int w, int h, int reps, const std::string& dir) {
    const embree::SceneBvh bvh(std::make_shared<embree::Device>(), s.scene);
    const Camera cam = cameraFor(*s.scene, w, h);
    std::printf("\n## %s, %d x %d, one thread, best of %d (CPU s), load %s\n\n", s.name.c_str(), w, h, reps,
                loadAverage().c_str());
    std::printf("| K | filter s | repeat s | filter / (K x one layer) | repeat / (K x one layer) | mean crossings/pixel |\n");
    std::printf("|---|---|---|---|---|---|\n");
    const double one = timeCapture(bvh, cam, requestFor(*s.scene, 1), embree::LayerMethod::Filter, reps, nullptr);
    std::printf("| 1 | %.3f | %.3f | 1.00 | 1.00 | |\n", one, one);
    std::vector<std::pair<int, BufferPtr>> layered;
    for (int k : {2, 4, 8}) {
        BufferPtr g;
        const double filter = timeCapture(bvh, cam, requestFor(*s.scene, k), embree::LayerMethod::Filter, reps, &g);
        const double repeat = timeCapture(bvh, cam, requestFor(*s.scene, k), embree::LayerMethod::Repeat, reps, nullptr);
        std::printf("| %d | %.3f | %.3f | %.2f | %.2f | %.2f |\n", k, filter, repeat, filter / (k * one),
                    repeat / (k * one), bench::meanCrossings(*g));
        layered.emplace_back(k, g);
    }
    std::printf("\nStorage (per G-buffer; read = file to the flat channel layout the graph reads):\n\n");
    std::printf("| K | layout | MB | write s (CPU s) | read s (CPU s) |\n|---|---|---|---|---|\n");
    for (const auto& [k, g] : layered)
        for (const auto& r : bench::measureStorage(*g, dir, reps))
            std::printf("| %d | %s | %.2f | %.3f (%.3f) | %.3f (%.3f) |\n", k, r.layout.c_str(), 1e-6 * double(r.bytes),
                        r.writeSeconds, r.writeCpu, r.readSeconds, r.readCpu);
    std::fflush(stdout);
}

}  // namespace

int main(int argc, char** argv) {
    int w = 1024, h = 768, reps = 3;
    std::string dir = std::filesystem::temp_directory_path().string() + "/bench_layers";
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        if (a == "--size" && i + 1 < argc) std::sscanf(argv[++i], "%dx%d", &w, &h);
        else if (a == "--reps" && i + 1 < argc) reps = std::max(1, std::atoi(argv[++i]));
        else if (a == "--out" && i + 1 < argc) dir = argv[++i];
        else {
            std::fprintf(stderr, "usage: bench_layers [--size WxH] [--reps R] [--out DIR]\n");
            return 2;
        }
    }
    std::filesystem::create_directories(dir);
    try {
        benchScene(nestedIsosurfaces(), w, h, reps, dir);
        benchScene(sheets(), w, h, reps, dir);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "bench_layers: %s\n", e.what());
        return 1;
    }
    return 0;
}
