// What smooth normals cost (docs/capture.md, "Normals"): the time and memory
// of averageVertexNormals on a mesh, and the capture of Z + a point scalar +
// normals with the triangles' own normals against the interpolated ones,
// through the "embree" backend, interleaved repetitions, medians.
//
// Usage: bench_normals [--mesh PATH | --isosurface RESOLUTION] [--size N] [--threads T] [--reps R] [--angle DEGREES]
// Default mesh: the shared Stanford bunny.
#include <darkroom/capture_backend.h>
#include <darkroom/error.h>
#include <darkroom/core/registry.h>
#include <darkroom/core/run_filter.h>
#include <darkroom/scene/generators.h>
#include <darkroom/scene/mesh_readers.h>
#include <darkroom/scene/vertex_normals.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <functional>
#include <string>
#include <thread>
#include <vector>

using namespace darkroom;

namespace {

struct Options {
    std::string mesh = std::string(DARKROOM_SHARED_DATA_DIR) + "/meshes/stanford-bunny.obj";
    int isosurface = 0;  // > 0: the demo isosurface at this resolution instead (a bigger mesh)
    int size = 1024, threads = 2, reps = 7;
    double angle = 30;
};

SceneObject loadSurface(const Options& opt) {
    SceneObject surface;
    const auto parts = opt.isosurface > 0 ? generate("isosurface", {{"resolution", std::to_string(opt.isosurface)}})
                                          : readMesh(opt.mesh);
    for (const auto& o : parts)
        if (o.representation == Representation::Surface) surface = o;
    ScalarField h{"height", ScalarField::Association::Point, {}};
    for (std::size_t i = 0; i < surface.vertexCount(); ++i) h.values.push_back(surface.vertices[4 * i + 1]);
    surface.fields.push_back(std::move(h));
    return surface;
}

// The process's peak resident set so far (VmHWM), bytes.
double peakResident() {
    std::ifstream status("/proc/self/status");
    std::string line;
    while (std::getline(status, line))
        if (line.rfind("VmHWM:", 0) == 0) return 1024.0 * std::atof(line.c_str() + 6);
    return 0;
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

Camera frame(const Scene& scene, int size) {
    const Bounds b = scene.bounds();
    Camera c;
    c.fovYDegrees = 30.0;
    c.position = b.center() + Vec3{0, 0, b.radius() / std::tan(c.fovYDegrees * 3.14159265358979323846 / 360.0) * 0.8};
    c.forward = {0, 0, -1};
    c.width = c.height = size;
    return c;
}

Options parse(int argc, char** argv) {
    Options opt;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        if (i + 1 >= argc) throw Error("usage: bench_normals [--mesh PATH | --isosurface RESOLUTION] [--size N] "
                                       "[--threads T] [--reps R] [--angle DEGREES]");
        const std::string v = argv[++i];
        if (a == "--mesh") opt.mesh = v;
        else if (a == "--isosurface") opt.isosurface = std::stoi(v);
        else if (a == "--size") opt.size = std::stoi(v);
        else if (a == "--threads") opt.threads = std::stoi(v);
        else if (a == "--reps") opt.reps = std::max(1, std::stoi(v));
        else if (a == "--angle") opt.angle = std::stod(v);
        else throw Error("unknown option " + a);
    }
    return opt;
}

}  // namespace

int main(int argc, char** argv) try {
    const Options opt = parse(argc, argv);
    Registry registry;
    registry.loadPlugins({DARKROOM_BENCH_PLUGIN_DIR});
    FilterRunOptions ro;
    ro.threads = opt.threads;
    ro.registry = &registry;
    auto ctx = makeStandaloneContext(ro, "bench");

    const SceneObject mesh = loadSurface(opt);
    // The first computation on a fresh copy: the rise of the peak resident
    // set is what it needs beyond the mesh (its transient arrays and result).
    SceneObject smooth = mesh;
    const double before = peakResident();
    averageVertexNormals(smooth, opt.angle);
    const double peak = peakResident() - before;
    std::vector<double> normalTimes;
    for (int r = 0; r < opt.reps; ++r) {
        SceneObject copy = mesh;
        normalTimes.push_back(seconds([&] { averageVertexNormals(copy, opt.angle); }));
    }
    const std::size_t nv = mesh.vertexCount(), nt = mesh.indices.size() / 3, split = smooth.vertexCount() - nv;
    std::printf("mesh: %zu triangles, %zu vertices; feature angle %g: %zu vertices split off\n", nt, nv, opt.angle, split);
    std::printf("averageVertexNormals, %d threads: median %.1f ms; peak resident set +%.1f MB; kept +%.1f MB "
                "(normals 12 B a vertex, copies %zu B each)\n",
                opt.threads, 1e3 * median(normalTimes), peak / 1e6,
                double(12 * smooth.vertexCount() + split * (16 + 4 * mesh.fields.size())) / 1e6,
                16 + 4 * mesh.fields.size());

    auto sceneOf = [](SceneObject o) {
        auto s = std::make_shared<Scene>();
        s->objects.push_back(std::move(o));
        return s;
    };
    auto flat = registry.createBackend("embree"), interpolated = registry.createBackend("embree");
    flat->setScene(sceneOf(mesh));
    interpolated->setScene(sceneOf(smooth));
    const Camera cam = frame(*sceneOf(mesh), opt.size);
    CaptureRequest req;
    req.scalars = {"height"};
    req.normals = true;
    flat->render(cam, req, *ctx);  // warm-up
    interpolated->render(cam, req, *ctx);
    std::vector<double> tFlat, tSmooth;
    for (int r = 0; r < opt.reps; ++r) {
        tFlat.push_back(seconds([&] { flat->render(cam, req, *ctx); }));
        tSmooth.push_back(seconds([&] { interpolated->render(cam, req, *ctx); }));
    }
    std::printf("capture %dx%d Z + height + normals: geometric median %.1f ms, smooth median %.1f ms (%+.1f %%)\n",
                opt.size, opt.size, 1e3 * median(tFlat), 1e3 * median(tSmooth),
                100.0 * (median(tSmooth) / median(tFlat) - 1.0));
    return 0;
} catch (const std::exception& e) {
    std::fprintf(stderr, "bench_normals: %s\n", e.what());
    return 1;
}
