// Our SSAO on a G-buffer of the Stanford bunny captured with the embree
// backend, framed as bench_capture frames it (front view, 30 degrees, the
// mesh filling most of the view), timed per frame; vtk_ssao_peer.py renders
// the same mesh with the same camera through VTK's vtkSSAOPass, and
// run_ssao_peer.sh prints the ratio.
//
// Usage: bench_ssao_peer [--mesh PATH] [--size N] [--reps R] [--threads T]
//                        [--camera-json PATH] [--png PATH]
// Prints one RESULT line per setting: "RESULT ssao_ms <setting>=<ms>".
#include <darkroom/capture_backend.h>
#include <darkroom/error.h>
#include <darkroom/core/registry.h>
#include <darkroom/core/run_filter.h>
#include <darkroom/scene/mesh_readers.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <vector>

using namespace darkroom;

namespace {

struct Options {
    std::string mesh = std::string(DARKROOM_SHARED_DATA_DIR) + "/meshes/stanford-bunny.obj";
    int size = 1024;
    int reps = 9;
    int threads = 0;
    std::string cameraJson;
};

// bench_capture's framing: the bounds' centre seen from +z, the bounding
// sphere filling 80 % of the 30-degree view.
Camera frame(const Scene& scene, int size) {
    const Bounds b = scene.bounds();
    Camera c;
    c.fovYDegrees = 30.0;
    const double dist = b.radius() / std::tan(c.fovYDegrees * 3.14159265358979323846 / 360.0) * 0.8;
    c.position = b.center() + Vec3{0, 0, dist};
    c.forward = {0, 0, -1};
    c.up = {0, 1, 0};
    c.width = c.height = size;
    return c;
}

// The occlusion radius in world units: SSAO's default (0.05 image heights)
// at the distance of the bounds' centre, so VTK (whose radius is in world
// units) and we use the same one.
double worldRadius(const Scene& scene, const Camera& c) {
    const double dist = length(scene.bounds().center() - c.position);
    return 0.05 * 2.0 * dist * std::tan(c.fovYDegrees * 3.14159265358979323846 / 360.0);
}

void writeCameraJson(const std::string& path, const Camera& c, const std::string& mesh, double radius) {
    std::ofstream f(path);
    f << "{\n  \"mesh\": \"" << mesh << "\",\n  \"width\": " << c.width << ",\n  \"height\": " << c.height
      << ",\n  \"position\": [" << c.position.x << ", " << c.position.y << ", " << c.position.z << "],\n"
      << "  \"focal_point\": [" << c.position.x + c.forward.x << ", " << c.position.y + c.forward.y << ", "
      << c.position.z + c.forward.z << "],\n  \"view_up\": [" << c.up.x << ", " << c.up.y << ", " << c.up.z
      << "],\n  \"view_angle\": " << c.fovYDegrees << ",\n  \"radius\": " << radius << "\n}\n";
    if (!f) throw Error("cannot write " + path);
}

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v[v.size() / 2];
}

}  // namespace

int main(int argc, char** argv) {
    Options opt;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        auto next = [&]() -> std::string {
            if (i + 1 >= argc) {
                std::fprintf(stderr, "bench_ssao_peer: %s needs a value\n", a.c_str());
                std::exit(2);
            }
            return argv[++i];
        };
        if (a == "--mesh") opt.mesh = next();
        else if (a == "--size") opt.size = std::stoi(next());
        else if (a == "--reps") opt.reps = std::max(1, std::stoi(next()));
        else if (a == "--threads") opt.threads = std::stoi(next());
        else if (a == "--camera-json") opt.cameraJson = next();
        else {
            std::fprintf(stderr, "usage: bench_ssao_peer [--mesh PATH] [--size N] [--reps R] [--threads T] "
                                 "[--camera-json PATH]\n");
            return 2;
        }
    }
    try {
        if (!std::filesystem::exists(opt.mesh)) throw Error("mesh " + opt.mesh + " not found (see --mesh)");
        auto scene = std::make_shared<Scene>();
        for (auto& o : readMesh(opt.mesh))
            if (o.representation == Representation::Surface) scene->objects.push_back(std::move(o));
        if (scene->objects.empty()) throw Error("no surface in " + opt.mesh);
        const Camera cam = frame(*scene, opt.size);
        const double radius = worldRadius(*scene, cam);
        if (!opt.cameraJson.empty()) writeCameraJson(opt.cameraJson, cam, opt.mesh, radius);

        Registry registry;
        registry.loadPlugins({DARKROOM_BENCH_PLUGIN_DIR});
        FilterRunOptions ro;
        ro.threads = opt.threads;
        ro.registry = &registry;
        ro.poison = false;
        auto ctx = makeStandaloneContext(ro, "bench_ssao_peer");
        auto backend = registry.createBackend("embree");
        if (!backend) throw Error("the embree capture backend is not built");
        backend->setScene(scene);
        const BufferPtr gbuffer = backend->render(cam, CaptureRequest{}, *ctx);
        std::size_t covered = 0;
        const float* z = gbuffer->requireFloat("Z");
        for (std::size_t i = 0; i < gbuffer->pixelCount(); ++i) covered += std::isfinite(z[i]);
        std::printf("darkroom SSAO on %s, %dx%d, %.0f%% of the pixels covered, radius %.4g (world), %d reps (median)\n",
                    std::filesystem::path(opt.mesh).filename().c_str(), opt.size, opt.size,
                    100.0 * double(covered) / double(gbuffer->pixelCount()), radius, opt.reps);

        // At the pass's defaults (half resolution) and at every pixel.
        struct Setting {
            const char* name;
            std::map<std::string, Value> params;
        };
        const std::vector<Setting> settings = {
            {"hemisphere16", {{"method", Value("hemisphere")}, {"samples", Value(16)}}},
            {"horizon4x8", {{"method", Value("horizon")}, {"slices", Value(4)}, {"steps", Value(8)}}},
            {"hemisphere16-full", {{"method", Value("hemisphere")}, {"samples", Value(16)}, {"resolution", Value("full")}}},
            {"horizon4x8-full",
             {{"method", Value("horizon")}, {"slices", Value(4)}, {"steps", Value(8)}, {"resolution", Value("full")}}},
        };
        auto filter = registry.createFilter("SSAO");
        for (const Setting& s : settings) {
            std::map<std::string, std::vector<Value>> in{{"image", {Value(gbuffer)}},
                                                         {"radiusUnits", {Value("world")}},
                                                         {"radius", {Value(radius)}},
                                                         {"blurRadius", {Value(2)}}};
            for (const auto& [k, v] : s.params) in[k] = {v};
            runFilter(*filter, in, ro);  // warm-up: pooled planes, caches
            std::vector<double> ms;
            for (int r = 0; r < opt.reps; ++r) {
                const auto t0 = std::chrono::steady_clock::now();
                const FilterRunResult out = runFilter(*filter, in, ro);
                ms.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count());
            }
            std::printf("%-18s %8.2f ms  (min %.2f)\n", s.name, median(ms), *std::min_element(ms.begin(), ms.end()));
            std::printf("RESULT ssao_ms %s=%.3f\n", s.name, median(ms));
        }
    } catch (const std::exception& e) {
        std::fprintf(stderr, "bench_ssao_peer: %s\n", e.what());
        return 1;
    }
    return 0;
}
