// Capture throughput against Embree's own loops, measured in the same process
// with the same rays, the same BVH build and the same TBB threads:
//   plain-rows   rtcIntersect1 per pixel, rows in parallel, writes only t
//   plain-tiles  rtcIntersect1 per pixel, 16x16 tiles in parallel, writes only t
//   packet-t     rtcIntersect8 (coherent) over the backend's tiles, writes only t
//   capture      the "embree" backend's render(): Z + one scalar + normals
// The target: capture at least 1.5x faster than the faster plain loop.
//
// Usage: bench_capture [--mesh PATH] [--size N] [--threads T] [--reps R] [--camera-json PATH]
#include "embree_scene.h"
#include "primary_rays.h"

#include <darkroom/capture_backend.h>
#include <darkroom/error.h>
#include <darkroom/framework/registry.h>
#include <darkroom/framework/run_filter.h>
#include <darkroom/framework/scene/mesh_readers.h>
#include <embree3/rtcore.h>
#include <pmmintrin.h>
#include <xmmintrin.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <limits>
#include <string>
#include <thread>
#include <vector>

using namespace darkroom;

namespace {

struct Options {
    std::string mesh = std::string(DARKROOM_SHARED_DATA_DIR) + "/meshes/stanford-bunny.obj";
    int size = 1024;
    int threads = 0;
    int reps = 7;
    std::string cameraJson;
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

class FlushDenormals {
public:
    FlushDenormals() : saved_(_mm_getcsr()) {
        _MM_SET_FLUSH_ZERO_MODE(_MM_FLUSH_ZERO_ON);
        _MM_SET_DENORMALS_ZERO_MODE(_MM_DENORMALS_ZERO_ON);
    }
    ~FlushDenormals() { _mm_setcsr(saved_); }

private:
    unsigned saved_;
};

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
void packetT(Context& ctx, RTCScene scene, const Camera& cam, std::vector<float>& t) {
    const embree::PrimaryRays rays(cam);
    const int tx = (cam.width + kTile - 1) / kTile, ty = (cam.height + kTile - 1) / kTile;
    ctx.parallelFor(0, tx * ty, 1, [&](int b, int e) {
        const FlushDenormals ftz;
        RTCIntersectContext ic;
        rtcInitIntersectContext(&ic);
        ic.flags = RTC_INTERSECT_CONTEXT_FLAG_COHERENT;
        alignas(32) RTCRayHit8 rh;
        alignas(32) int valid[8];
        for (int tile = b; tile < e; ++tile) {
            const int x0 = (tile % tx) * kTile, y0 = (tile / tx) * kTile;
            for (int py = y0; py < std::min(y0 + kTile, cam.height); py += 2)
                for (int px = x0; px < std::min(x0 + kTile, cam.width); px += 4) {
                    for (int k = 0; k < 8; ++k) {
                        const int x = px + k % 4, y = py + k / 4;
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
                    rtcIntersect8(valid, scene, &ic, &rh);
                    for (int k = 0; k < 8; ++k)
                        if (valid[k])
                            t[std::size_t(py + k / 4) * cam.width + px + k % 4] =
                                rh.hit.geomID[k] == RTC_INVALID_GEOMETRY_ID ? std::numeric_limits<float>::infinity()
                                                                            : rh.ray.tfar[k];
                }
        }
    });
}

double seconds(const std::function<void()>& f) {
    const auto t0 = std::chrono::steady_clock::now();
    f();
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

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
        else {
            std::fprintf(stderr, "usage: %s [--mesh PATH] [--size N] [--threads T] [--reps R] [--camera-json PATH]\n",
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
        const Diagnostics d = registry.loadPlugins({DARKROOM_BENCH_PLUGIN_DIR});
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
        std::vector<double> rows, tiles, packets, cap;
        BufferPtr image;
        // Warm-up, then interleaved repetitions so background load hits all alike.
        plainRows(*ctx, bvh.handle(), cam, t);
        image = backend->render(cam, req, *ctx);
        for (int r = 0; r < opt.reps; ++r) {
            rows.push_back(seconds([&] { plainRows(*ctx, bvh.handle(), cam, t); }));
            tiles.push_back(seconds([&] { plainTiles(*ctx, bvh.handle(), cam, t); }));
            packets.push_back(seconds([&] { packetT(*ctx, bvh.handle(), cam, t); }));
            cap.push_back(seconds([&] { image = backend->render(cam, req, *ctx); }));
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
        auto report = [&](const char* name, const std::vector<double>& v, double mb) {
            const double s = median(v);
            std::printf("%-12s %8.2f ms  %8.2f Mrays/s", name, s * 1e3, rays / s * 1e-6);
            if (mb > 0) std::printf("  %8.1f MB/s G-buffer", mb / s * 1e-6);
            std::printf("\n");
            return s;
        };
        std::printf("mesh: %s, %zu triangles, %dx%d, %d threads, %d reps (median), %.1f%% pixels hit\n",
                    label.c_str(), scene->objects[0].indices.size() / 3, cam.width, cam.height, threads, opt.reps,
                    100.0 * hits / rays);
        std::printf("BVH build (backend setScene): %.1f ms\n", tBuild * 1e3);
        const double sRows = report("plain-rows", rows, 0);
        const double sTiles = report("plain-tiles", tiles, 0);
        const double sPackets = report("packet-t", packets, 0);
        const double sCap = report("capture", cap, bytes);
        std::printf("G-buffer: %zu channels (Z, height, N.x, N.y, N.z), %.1f MB\n", image->channels().size(),
                    bytes * 1e-6);
        const double plain = std::min(sRows, sTiles);
        std::printf("ratio capture / plain (best of rows, tiles): %.2fx faster\n", plain / sCap);
        std::printf("ratio packet-t / plain: %.2fx faster\n", plain / sPackets);
        std::printf("depth mismatches capture vs plain: %zu\n", mismatches);
        std::printf("RESULT capture_ms=%.3f plain_ms=%.3f ratio=%.3f\n", sCap * 1e3, plain * 1e3, plain / sCap);
        return 0;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "bench_capture: %s\n", e.what());
        return 1;
    }
}
