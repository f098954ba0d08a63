// What Embree's build quality and the compact flag cost on one mesh: build
// time, the memory the build peaks at and keeps, and the trace time of the
// backend's render() (Z + a point scalar) for one view from above at 45
// degrees. One setting per run, so that each peak is measured alone:
//
//   bench_bvh_settings --mesh PATH [--quality low|medium|high] [--compact]
//                      [--pieces P] [--size N] [--reps R] [--threads T]
//                      [--general-reader]
//
// --pieces P: surfaces in Embree geometries of at most P triangles
// (BvhSettings::piecePrimitives; 0, the default here: whole).
//
// It also reports how long reading the mesh took and the memory it peaked at
// (--general-reader: a PLY through readPly's general reader instead of the
// direct one).
//
// bench/capture/run_ingest_bench.sh runs it over the settings on a
// generated height field; docs/performance.md ("Capture ingest") has the table.
#include "embree_backend.h"
#include "embree_scene.h"

#include <darkroom/capture_backend.h>
#include <darkroom/core/run_filter.h>
#include <darkroom/scene/mesh_readers.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <fstream>
#include <string>
#include <thread>
#include <vector>

using namespace darkroom;

namespace {

struct Options {
    std::string mesh;
    embree::BvhSettings settings;
    int size = 1024, reps = 3, threads = 0;
    bool generalReader = false;  // --general-reader: readPly's general reader, for comparison
};

// VmRSS or VmHWM of this process, in bytes.
double statusBytes(const char* key) {
    std::ifstream f("/proc/self/status");
    std::string line;
    while (std::getline(f, line))
        if (line.rfind(key, 0) == 0) return std::atof(line.c_str() + std::char_traits<char>::length(key)) * 1024.0;
    return 0;
}

// Resets VmHWM to the current RSS (Linux's clear_refs "5"), so the build's
// own peak can be read afterwards.
void resetPeak() { std::ofstream("/proc/self/clear_refs") << "5"; }

double cpuSeconds() {
    timespec ts;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
    return double(ts.tv_sec) + 1e-9 * double(ts.tv_nsec);
}

double wallSeconds() {
    return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

Options parse(int argc, char** argv) {
    Options o;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        const char* v = i + 1 < argc ? argv[i + 1] : "";
        if (a == "--mesh") o.mesh = v, ++i;
        else if (a == "--quality") {
            const std::string q = v;
            ++i;
            o.settings.quality = q == "low"      ? embree::BvhSettings::Quality::Low
                                 : q == "medium" ? embree::BvhSettings::Quality::Medium
                                                 : embree::BvhSettings::Quality::High;
        } else if (a == "--compact") o.settings.compact = true;
        else if (a == "--pieces") o.settings.piecePrimitives = std::size_t(std::atoll(v)), ++i;
        else if (a == "--general-reader") o.generalReader = true;
        else if (a == "--size") o.size = std::atoi(v), ++i;
        else if (a == "--reps") o.reps = std::max(1, std::atoi(v)), ++i;
        else if (a == "--threads") o.threads = std::atoi(v), ++i;
        else {
            std::fprintf(stderr, "usage: %s --mesh PATH [--quality low|medium|high] [--compact] [--pieces P] "
                                 "[--size N] [--reps R] [--threads T] [--general-reader]\n", argv[0]);
            std::exit(2);
        }
    }
    if (o.mesh.empty()) std::exit((std::fprintf(stderr, "--mesh is required\n"), 2));
    return o;
}

Camera viewFromAbove(const Scene& scene, int size) {
    const Bounds b = scene.bounds();
    Camera c;
    c.fovYDegrees = 40.0;
    const Vec3 dir = Vec3{0, 1, 1} * (1 / std::sqrt(2.0));
    c.position = b.center() + dir * (2.2 * b.radius());
    c.forward = dir * -1.0;
    c.up = Vec3{0, 1, -1} * (1 / std::sqrt(2.0));
    c.width = c.height = size;
    return c;
}

}  // namespace

int main(int argc, char** argv) {
    const Options opt = parse(argc, argv);
    try {
        auto scene = std::make_shared<Scene>();
        const double r0 = wallSeconds();
        if (opt.generalReader) {
            PlyReadOptions general;
            general.direct = false;
            scene->objects = readPly(opt.mesh, general);
        } else {
            scene->objects = readMesh(opt.mesh);
        }
        const double read = wallSeconds() - r0, readPeak = statusBytes("VmHWM:");
        std::size_t triangles = 0;
        for (const auto& o : scene->objects) triangles += embree::primitiveCountOf(o);
        const double base = statusBytes("VmRSS:");
        resetPeak();
        auto device = std::make_shared<embree::Device>();
        const double w0 = wallSeconds(), c0 = cpuSeconds();
        embree::SceneBvh bvh(device, scene, opt.settings);
        const double build = wallSeconds() - w0, buildCpu = cpuSeconds() - c0;
        const double peak = statusBytes("VmHWM:") - base, kept = statusBytes("VmRSS:") - base;

        FilterRunOptions ro;
        ro.threads = opt.threads > 0 ? opt.threads : int(std::thread::hardware_concurrency());
        auto ctx = makeStandaloneContext(ro, "bench");
        const Camera cam = viewFromAbove(*scene, opt.size);
        CaptureRequest request;
        request.scalars = {scene->objects.front().fields.empty() ? "" : scene->objects.front().fields.front().name};
        if (request.scalars.front().empty()) request.scalars.clear();
        embree::renderGBuffer(bvh, cam, request, *ctx);  // warm-up
        std::vector<double> trace;
        for (int r = 0; r < opt.reps; ++r) {
            const double t0 = wallSeconds();
            embree::renderGBuffer(bvh, cam, request, *ctx);
            trace.push_back(wallSeconds() - t0);
        }
        std::sort(trace.begin(), trace.end());
        const char* q = opt.settings.quality == embree::BvhSettings::Quality::High     ? "high"
                        : opt.settings.quality == embree::BvhSettings::Quality::Medium ? "medium"
                                                                                       : "low";
        std::printf("READ read_s=%.2f read_peak_MB=%.0f rss_after_read_MB=%.0f rss_after_read_B_per_tri=%.1f\n", read,
                    readPeak / 1e6, base / 1e6, base / double(triangles));
        std::printf(
            "RESULT quality=%s compact=%d pieces=%zu triangles=%zu build_s=%.2f build_cpu_s=%.2f "
            "build_peak_MB=%.0f bvh_MB=%.0f peak_B_per_tri=%.1f bvh_B_per_tri=%.1f trace_ms=%.1f\n",
            q, int(opt.settings.compact), opt.settings.piecePrimitives, triangles, build, buildCpu, peak / 1e6, kept / 1e6, peak / double(triangles),
            kept / double(triangles), trace[trace.size() / 2] * 1e3);
        return 0;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "bench_bvh_settings: %s\n", e.what());
        return 1;
    }
}
