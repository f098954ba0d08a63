// Times reading a volume and drawing it as boundary, isosurface and slice,
// the median of --reps runs each, and prints RESULT lines that
// run_volume_bench.sh compares with VTK's readers and filters (vtk_volume_peer.py).
//   bench_volume FILE.vtu|FILE.vti --field NAME --value V [--reps N]
#include <darkroom/scene/volume.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <string>
#include <vector>

using namespace darkroom;

namespace {

double medianMs(int reps, const std::function<void()>& f) {
    std::vector<double> t;
    for (int i = 0; i < reps; ++i) {
        const auto a = std::chrono::steady_clock::now();
        f();
        t.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - a).count());
    }
    std::sort(t.begin(), t.end());
    return t[t.size() / 2];
}

}  // namespace

int main(int argc, char** argv) {
    std::string path, field = "field";
    double value = 0.5;
    int reps = 5;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        if (a == "--field" && i + 1 < argc) field = argv[++i];
        else if (a == "--value" && i + 1 < argc) value = std::atof(argv[++i]);
        else if (a == "--reps" && i + 1 < argc) reps = std::atoi(argv[++i]);
        else path = a;
    }
    if (path.empty()) {
        std::fprintf(stderr, "usage: bench_volume FILE.vtu|FILE.vti [--field NAME] [--value V] [--reps N]\n");
        return 2;
    }
    VolumeMesh v;
    const double readMs = medianMs(reps, [&] { v = readVolume(path); });
    const Bounds b = [&] {
        Bounds x;
        for (std::size_t i = 0; i < v.pointCount(); ++i) {
            const Vec3 p = v.point(i);
            x.lo = {std::min(x.lo.x, p.x), std::min(x.lo.y, p.y), std::min(x.lo.z, p.z)};
            x.hi = {std::max(x.hi.x, p.x), std::max(x.hi.y, p.y), std::max(x.hi.z, p.z)};
        }
        return x;
    }();
    VolumeRepresentation boundary, iso, slice;
    iso.kind = VolumeRepresentation::Kind::Isosurface;
    iso.contourBy = field;
    iso.isovalues = {value};
    slice.kind = VolumeRepresentation::Kind::Slice;
    // Off the grid layers (a plane through grid faces is a special case): 1.3 % above the centre.
    slice.planes = {{b.center() + Vec3{0, 0, 0.013 * (b.hi.z - b.lo.z)}, {0, 0, 1}}};
    std::size_t tb = 0, ti = 0, ts = 0;
    const double boundaryMs = medianMs(reps, [&] { tb = volumeSurface(v, boundary, "b").primitiveCount(); });
    const double isoMs = medianMs(reps, [&] { ti = volumeSurface(v, iso, "i").primitiveCount(); });
    const double sliceMs = medianMs(reps, [&] { ts = volumeSurface(v, slice, "s").primitiveCount(); });
    std::printf("%s: %zu points, %zu cells (%zu 3D)\n", path.c_str(), v.pointCount(), v.cellCount(),
                v.volumeCellCount());
    std::printf("RESULT read_ms=%.2f boundary_ms=%.2f isosurface_ms=%.2f slice_ms=%.2f\n", readMs, boundaryMs, isoMs,
                sliceMs);
    std::printf("TRIANGLES boundary=%zu isosurface=%zu slice=%zu\n", tb, ti, ts);
    return 0;
}
