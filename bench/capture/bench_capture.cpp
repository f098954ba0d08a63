// Capture throughput against Embree's own loops, measured in the same process
// with the same rays, the same BVH build and the same TBB threads:
//   plain-rows   rtcIntersect1 per pixel, rows in parallel, writes only t
//   plain-tiles  rtcIntersect1 per pixel, 16x16 tiles in parallel, writes only t
//   packet-t     rtcIntersect8 (coherent) over the backend's tiles, writes only t
//   capture      the "embree" backend's render(): Z + one scalar + normals
// The target: capture at least 1.5x faster than the faster plain loop.
//
// Usage: bench_capture [--mesh PATH] [--size N] [--threads T] [--reps R] [--camera-json PATH]
//                      [--shapes] (also time other packet shapes) [--profile METHOD] (for perf record)
#include "embree_scene.h"
#include "flush_denormals.h"
#include "primary_rays.h"

#include <darkroom/capture_backend.h>
#include <darkroom/error.h>
#include <darkroom/core/registry.h>
#include <darkroom/core/run_filter.h>
#include <darkroom/scene/mesh_readers.h>
#include <embree3/rtcore.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <functional>
#include <limits>
#include <string>
#include <thread>
#include <type_traits>
#include <vector>

using namespace darkroom;
using darkroom::embree::FlushDenormals;

namespace {

struct Options {
    std::string mesh = std::string(DARKROOM_SHARED_DATA_DIR) + "/meshes/stanford-bunny.obj";
    int size = 1024;
    int threads = 0;
    int reps = 7;
    std::string cameraJson;
    bool shapes = false;  // also time other packet shapes and sizes
    std::string profile;  // run only this method 20 times (for perf record)
};

// ~100k triangles of a bumpy sphere, used when the bunny is not available.
SceneObject generatedMesh() {
    SceneObject o;
    o.name = "bumpy-sphere";
    const int rings = 224, segs = 224;
    const double pi = 3.14159265358979323846;
    for (int i = 0; i <= rings; ++i)
        for (int j = 0; j < segs; ++j) {
            const double th = pi * i / rings, ph = 2 * pi * j / segs;
            const double r = 1.0 + 0.05 * std::sin(7 * th) * std::cos(9 * ph);
            o.vertices.insert(o.vertices.end(), {float(r * std::sin(th) * std::cos(ph)), float(r * std::cos(th)),
                                                 float(r * std::sin(th) * std::sin(ph)), 0.0f});
        }
    for (int i = 0; i < rings; ++i)
        for (int j = 0; j < segs; ++j) {
            const std::uint32_t a = i * segs + j, b = i * segs + (j + 1) % segs;
            o.indices.insert(o.indices.end(), {a, a + segs, b, b, a + segs, b + std::uint32_t(segs)});
        }
    return o;
}

// The mesh as one surface object with a point scalar "height" (= y), so the
// capture interpolates a field like a real one would.
std::shared_ptr<Scene> loadScene(const Options& opt, std::string& label) {
    auto scene = std::make_shared<Scene>();
    SceneObject surface;
    if (std::filesystem::exists(opt.mesh)) {
        for (auto& o : readMesh(opt.mesh))
            if (o.representation == Representation::Surface) surface = std::move(o);
        label = std::filesystem::path(opt.mesh).filename().string();
    } else {
        surface = generatedMesh();
        label = "generated bumpy sphere";
    }
    ScalarField h{"height", ScalarField::Association::Point, {}};
    for (std::size_t i = 0; i < surface.vertexCount(); ++i) h.values.push_back(surface.vertices[4 * i + 1]);
    surface.fields.push_back(std::move(h));
    scene->objects.push_back(std::move(surface));
    return scene;
}

// Looks at the bounds' centre from the front (+z) so the mesh fills most of the view.
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

void traceSingle(RTCScene scene, RTCIntersectContext* ic, const embree::PrimaryRays& rays, int x, int y,
                 float* out) {
    RTCRayHit rh;
    float o[3], d[3];
    rays(x, y, o, d);
    rh.ray.org_x = o[0], rh.ray.org_y = o[1], rh.ray.org_z = o[2];
    rh.ray.dir_x = d[0], rh.ray.dir_y = d[1], rh.ray.dir_z = d[2];
    rh.ray.tnear = 0.0f;
    rh.ray.tfar = std::numeric_limits<float>::infinity();
    rh.ray.time = 0.0f;
    rh.ray.mask = 0xFFFFFFFFu;
    rh.ray.id = 0;
    rh.ray.flags = 0;
    rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
    rtcIntersect1(scene, ic, &rh);
    *out = rh.hit.geomID == RTC_INVALID_GEOMETRY_ID ? std::numeric_limits<float>::infinity() : rh.ray.tfar;
}

void plainRows(Context& ctx, RTCScene scene, const Camera& cam, std::vector<float>& t) {
    const embree::PrimaryRays rays(cam);
    ctx.parallelFor(0, cam.height, 1, [&](int y0, int y1) {
        const FlushDenormals ftz;
        RTCIntersectContext ic;
        rtcInitIntersectContext(&ic);
        for (int y = y0; y < y1; ++y)
            for (int x = 0; x < cam.width; ++x) traceSingle(scene, &ic, rays, x, y, &t[std::size_t(y) * cam.width + x]);
    });
}

constexpr int kTile = 16;

void plainTiles(Context& ctx, RTCScene scene, const Camera& cam, std::vector<float>& t) {
    const embree::PrimaryRays rays(cam);
    const int tx = (cam.width + kTile - 1) / kTile, ty = (cam.height + kTile - 1) / kTile;
    ctx.parallelFor(0, tx * ty, 1, [&](int b, int e) {
        const FlushDenormals ftz;
        RTCIntersectContext ic;
        rtcInitIntersectContext(&ic);
        for (int tile = b; tile < e; ++tile) {
            const int x0 = (tile % tx) * kTile, y0 = (tile / tx) * kTile;
            for (int y = y0; y < std::min(y0 + kTile, cam.height); ++y)
                for (int x = x0; x < std::min(x0 + kTile, cam.width); ++x)
                    traceSingle(scene, &ic, rays, x, y, &t[std::size_t(y) * cam.width + x]);
        }
    });
}

// Packets without the G-buffer: how much of the capture's time is tracing.
// PW x PH pixel blocks traced as one packet of N = PW * PH rays (8 or 16).
template <int PW, int PH>
void packetT(Context& ctx, RTCScene scene, const Camera& cam, std::vector<float>& t) {
    constexpr int N = PW * PH;
    static_assert(N == 8 || N == 16);
    using RayHitN = std::conditional_t<N == 8, RTCRayHit8, RTCRayHit16>;
    const embree::PrimaryRays rays(cam);
    const int tx = (cam.width + kTile - 1) / kTile, ty = (cam.height + kTile - 1) / kTile;
    ctx.parallelFor(0, tx * ty, 1, [&](int b, int e) {
        const FlushDenormals ftz;
        RTCIntersectContext ic;
        rtcInitIntersectContext(&ic);
        ic.flags = RTC_INTERSECT_CONTEXT_FLAG_COHERENT;
        alignas(64) RayHitN rh;
        alignas(64) int valid[N];
        for (int tile = b; tile < e; ++tile) {
            const int x0 = (tile % tx) * kTile, y0 = (tile / tx) * kTile;
            for (int py = y0; py < std::min(y0 + kTile, cam.height); py += PH)
                for (int px = x0; px < std::min(x0 + kTile, cam.width); px += PW) {
                    for (int k = 0; k < N; ++k) {
                        const int x = px + k % PW, y = py + k / PW;
                        valid[k] = (x < cam.width && y < cam.height) ? -1 : 0;
                        float o[3] = {0, 0, 0}, d[3] = {0, 0, 1};
                        if (valid[k]) rays(x, y, o, d);
                        rh.ray.org_x[k] = o[0], rh.ray.org_y[k] = o[1], rh.ray.org_z[k] = o[2];
                        rh.ray.dir_x[k] = d[0], rh.ray.dir_y[k] = d[1], rh.ray.dir_z[k] = d[2];
                        rh.ray.tnear[k] = 0.0f;
                        rh.ray.tfar[k] = std::numeric_limits<float>::infinity();
                        rh.ray.time[k] = 0.0f;
                        rh.ray.mask[k] = 0xFFFFFFFFu;
                        rh.ray.id[k] = unsigned(k);
                        rh.ray.flags[k] = 0;
                        rh.hit.geomID[k] = RTC_INVALID_GEOMETRY_ID;
                        rh.hit.instID[0][k] = RTC_INVALID_GEOMETRY_ID;
                    }
                    if constexpr (N == 8) rtcIntersect8(valid, scene, &ic, &rh);
                    else rtcIntersect16(valid, scene, &ic, &rh);
                    for (int k = 0; k < N; ++k)
                        if (valid[k])
                            t[std::size_t(py + k / PW) * cam.width + px + k % PW] =
                                rh.hit.geomID[k] == RTC_INVALID_GEOMETRY_ID ? std::numeric_limits<float>::infinity()
                                                                            : rh.ray.tfar[k];
                }
        }
    });
}

// Wall-clock seconds of f(); also adds the process's CPU seconds to *cpu.
// On a shared, loaded machine CPU time is the steadier measure of the work
// done (wall time also counts time other processes held our cores).
std::vector<double>* cpuSink = nullptr;
double processCpu() {
    timespec ts;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
    return double(ts.tv_sec) + 1e-9 * double(ts.tv_nsec);
}
double seconds(const std::function<void()>& f) {
    const double c0 = processCpu();
    const auto t0 = std::chrono::steady_clock::now();
    f();
    const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    if (cpuSink) cpuSink->push_back(processCpu() - c0);
    return wall;
}

struct Timings {
    std::vector<double> wall, cpu;
    void run(const std::function<void()>& f) {
        cpuSink = &cpu;
        wall.push_back(seconds(f));
        cpuSink = nullptr;
    }
};

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v[v.size() / 2];
}

void writeCameraJson(const std::string& path, const Camera& c, const std::string& mesh) {
    std::ofstream f(path);
    f << "{\n  \"mesh\": \"" << mesh << "\",\n  \"width\": " << c.width << ",\n  \"height\": " << c.height
      << ",\n  \"position\": [" << c.position.x << ", " << c.position.y << ", " << c.position.z << "],\n"
      << "  \"focal_point\": [" << c.position.x + c.forward.x << ", " << c.position.y + c.forward.y << ", "
      << c.position.z + c.forward.z << "],\n  \"view_up\": [" << c.up.x << ", " << c.up.y << ", " << c.up.z
      << "],\n  \"view_angle\": " << c.fovYDegrees << "\n}\n";
}

}  // namespace

int main(int argc, char** argv) {
    Options opt;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        auto next = [&]() -> std::string {
            if (i + 1 >= argc) {
                std::fprintf(stderr, "%s needs a value\n", a.c_str());
                std::exit(2);
            }
            return argv[++i];
        };
        if (a == "--mesh") opt.mesh = next();
        else if (a == "--size") opt.size = std::stoi(next());
        else if (a == "--threads") opt.threads = std::stoi(next());
        else if (a == "--reps") opt.reps = std::max(1, std::stoi(next()));
        else if (a == "--camera-json") opt.cameraJson = next();
        else if (a == "--profile") opt.profile = next();
        else if (a == "--shapes") opt.shapes = true;
        else {
            std::fprintf(stderr, "usage: %s [--mesh PATH] [--size N] [--threads T] [--reps R] [--camera-json PATH] [--shapes] [--profile METHOD]\n",
                         argv[0]);
            return 2;
        }
    }
    try {
        std::string label;
        auto scene = loadScene(opt, label);
        const Camera cam = frame(*scene, opt.size);
        if (!opt.cameraJson.empty()) writeCameraJson(opt.cameraJson, cam, opt.mesh);
        const int threads = opt.threads > 0 ? opt.threads : int(std::thread::hardware_concurrency());

        Registry registry;
        // DARKROOM_BENCH_PLUGIN_DIR in the environment times another build's
        // backend (e.g. a copy of the tree before a change) with this harness.
        const char* pluginDir = std::getenv("DARKROOM_BENCH_PLUGIN_DIR");
        const Diagnostics d = registry.loadPlugins({pluginDir && *pluginDir ? pluginDir : DARKROOM_BENCH_PLUGIN_DIR});
        for (const auto& x : d) std::fprintf(stderr, "%s\n", x.str().c_str());
        auto backend = registry.createBackend("embree");
        FilterRunOptions ro;
        ro.threads = threads;
        ro.registry = &registry;
        auto ctx = makeStandaloneContext(ro, "bench");

        double tBuild = seconds([&] { backend->setScene(scene); });
        // The plain loops trace the same rays against an identically built BVH.
        auto device = std::make_shared<embree::Device>();
        embree::SceneBvh bvh(device, scene);

        CaptureRequest req;
        req.scalars = {"height"};
        req.normals = true;
        std::vector<float> t(std::size_t(cam.width) * cam.height);
        Timings rows, tiles, packets, cap, capZ, alloc, p8x1, p2x4, p4x4, p8x2;
        BufferPtr image;
        if (!opt.profile.empty()) {
            for (int r = 0; r < 20; ++r) {
                if (opt.profile == "capture") backend->render(cam, req, *ctx);
                else if (opt.profile == "capture-Z") backend->render(cam, CaptureRequest{}, *ctx);
                else if (opt.profile == "packet-t") packetT<4, 2>(*ctx, bvh.handle(), cam, t);
                else if (opt.profile == "plain-rows") plainRows(*ctx, bvh.handle(), cam, t);
                else throw Error("--profile: unknown method '" + opt.profile + "'");
            }
            return 0;
        }
        // Warm-up, then interleaved repetitions so background load hits all alike.
        plainRows(*ctx, bvh.handle(), cam, t);
        image = backend->render(cam, req, *ctx);
        for (int r = 0; r < opt.reps; ++r) {
            rows.run(([&] { plainRows(*ctx, bvh.handle(), cam, t); }));
            tiles.run(([&] { plainTiles(*ctx, bvh.handle(), cam, t); }));
            packets.run(([&] { packetT<4, 2>(*ctx, bvh.handle(), cam, t); }));
            if (opt.shapes) {
                p8x1.run(([&] { packetT<8, 1>(*ctx, bvh.handle(), cam, t); }));
                p2x4.run(([&] { packetT<2, 4>(*ctx, bvh.handle(), cam, t); }));
                p4x4.run(([&] { packetT<4, 4>(*ctx, bvh.handle(), cam, t); }));
                p8x2.run(([&] { packetT<8, 2>(*ctx, bvh.handle(), cam, t); }));
            }
            cap.run(([&] { image = backend->render(cam, req, *ctx); }));
            capZ.run(([&] { backend->render(cam, CaptureRequest{}, *ctx); }));
            alloc.run(([&] { ctx->allocate(cam.width, cam.height, {{"Z"}, {"height"}, {"N.x"}, {"N.y"}, {"N.z"}}); }));
        }
        // Sanity: the capture's depth is the plain loop's t.
        plainRows(*ctx, bvh.handle(), cam, t);
        const float* z = image->requireFloat("Z");
        std::size_t hits = 0, mismatches = 0;
        for (std::size_t i = 0; i < t.size(); ++i) {
            hits += std::isfinite(z[i]);
            if (!(z[i] == t[i]) && !(std::isinf(z[i]) && std::isinf(t[i])) && std::abs(z[i] - t[i]) > 1e-6f * t[i])
                ++mismatches;
        }

        const double rays = double(cam.width) * cam.height;
        const double bytes = double(image->channels().size()) * 4.0 * rays;
        // Wall time (what a user waits) and process CPU time (the work done,
        // robust to other processes sharing the cores) per frame, medians.
        auto report = [&](const char* name, const Timings& v, double mb) {
            const double s = median(v.wall), c = median(v.cpu);
            std::printf("%-12s wall %8.2f ms %7.2f Mrays/s | cpu %8.2f ms %7.2f Mrays/s per core-second", name,
                        s * 1e3, rays / s * 1e-6, c * 1e3, rays / c * 1e-6);
            if (mb > 0) std::printf(" | %7.1f MB/s G-buffer (wall)", mb / s * 1e-6);
            std::printf("\n");
            return std::make_pair(s, c);
        };
        std::printf("mesh: %s, %zu triangles, %dx%d, %d threads, %d reps (median), %.1f%% pixels hit\n",
                    label.c_str(), scene->objects[0].indices.size() / 3, cam.width, cam.height, threads, opt.reps,
                    100.0 * hits / rays);
        std::printf("BVH build (backend setScene): %.1f ms\n", tBuild * 1e3);
        const auto sRows = report("plain-rows", rows, 0);
        const auto sTiles = report("plain-tiles", tiles, 0);
        const auto sPackets = report("packet 4x2", packets, 0);
        if (opt.shapes) {
            report("packet 8x1", p8x1, 0);
            report("packet 2x4", p2x4, 0);
            report("packet 4x4", p4x4, 0);
            report("packet 8x2", p8x2, 0);
        }
        const auto sCap = report("capture", cap, bytes);
        report("capture-Z", capZ, 4.0 * rays);
        std::printf("allocate     wall %8.2f ms  (ctx.allocate of the 5-channel G-buffer alone)\n", median(alloc.wall) * 1e3);
        std::printf("G-buffer: %zu channels (Z, height, N.x, N.y, N.z), %.1f MB\n", image->channels().size(),
                    bytes * 1e-6);
        const double plain = std::min(sRows.first, sTiles.first);
        const double plainCpu = std::min(sRows.second, sTiles.second);
        std::printf("speed-up capture vs plain loop (best of rows, tiles): wall %.2fx, cpu %.2fx\n",
                    plain / sCap.first, plainCpu / sCap.second);
        std::printf("speed-up packet 4x2 (t only) vs plain loop:          wall %.2fx, cpu %.2fx\n",
                    plain / sPackets.first, plainCpu / sPackets.second);
        std::printf("depth mismatches capture vs plain: %zu\n", mismatches);
        std::printf("RESULT capture_ms=%.3f plain_ms=%.3f ratio=%.3f cpu_ratio=%.3f\n", sCap.first * 1e3, plain * 1e3,
                    plain / sCap.first, plainCpu / sCap.second);
        return 0;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "bench_capture: %s\n", e.what());
        return 1;
    }
}
