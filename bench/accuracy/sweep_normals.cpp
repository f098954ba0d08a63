// Sweep "normals": the Normals pass's depth-based reconstruction, each method,
// against the geometric normals the embree capture writes. Both are world-space
// unit normals facing the camera (plugins/normals/README.md), so they are
// compared directly. The pass gets only Z and the camera, as from a database
// that stores no normals.
#include "ao_common.h"
#include "harness.h"

#include <darkroom/accuracy/metrics.h>
#include <darkroom/accuracy/stress_scenes.h>

#include <cmath>
#include <iostream>
#include <set>

namespace darkroom::accuracy {
namespace {

// A method fails on a scene when its interior median exceeds 5 degrees or its
// p95 exceeds 30 degrees in the interior or over all geometry (features a
// pixel or two wide have no interior pixels at all); the first such knob
// value gets a picture.
constexpr double kFailMedian = 5.0, kFailP95 = 30.0;
// Angular error shown white in the error tile.
constexpr double kErrorWhite = 45.0;

BufferPtr depthOnly(const Buffer& gbuffer) {
    auto out = makeCpuBuffer(gbuffer.width(), gbuffer.height(), {{"Z", ChannelType::Float32}});
    std::copy_n(gbuffer.requireFloat("Z"), gbuffer.pixelCount(), out->writeFloat("Z"));
    out->metadata() = gbuffer.metadata();
    return out;
}

void sweepNormals(Harness& harness, Csv& csv) {
    const Options& opt = harness.options();
    std::set<std::string> pictured;
    for (const std::string& family : stress::families()) {
        std::vector<double> knobs = stress::knobValues(family);
        if (opt.quick && knobs.size() > 2) knobs = {knobs.front(), knobs.back()};
        for (double knob : knobs) {
            const stress::StressScene scene = stress::make(family, knob, {opt.size, opt.size});
            const int w = scene.camera.width, h = scene.camera.height;
            const std::size_t n = std::size_t(w) * h;
            auto backend = harness.backend(scene);
            CaptureRequest request;
            request.normals = true;
            request.objectId = true;
            const BufferPtr captured = backend->render(scene.camera, request, harness.context());
            const BufferPtr input = depthOnly(*captured);
            const ao::Regions regions = ao::regions(*captured);
            const float* z = captured->requireFloat("Z");

            for (const char* method : {"central", "nearest", "extrapolated"}) {
                BufferPtr out;
                const double ms = harness.msPerMpix(
                    [&] { out = harness.runPass("Normals", input, {{"method", Value(method)}}); }, n);
                Row r;
                r.sweep = "normals";
                r.scene = scene.name;
                r.family = family;
                r.knob = scene.knob;
                r.knobValue = scene.knobValue;
                r.method = method;
                r.setting = "default";
                r.msPerMpix = ms;
                metrics::AngularStats interior, all;
                for (const char* region : ao::kRegions) {
                    const metrics::AngularStats s = metrics::angularError(*out, *captured, {"N.x", "N.y", "N.z"},
                                                                          regions.get(region));
                    if (std::string(region) == "interior") interior = s;
                    if (std::string(region) == "all") all = s;
                    r.region = region;
                    for (auto [metric, value] : {std::pair<const char*, double>{"angle_mean", s.mean},
                                                 {"angle_median", s.median},
                                                 {"angle_p95", s.p95},
                                                 {"share_above_5", s.shareAbove5}}) {
                        r.metric = metric;
                        r.value = s.count ? value : std::nan("");
                        csv.add(r);
                    }
                }
                std::cerr << "normals " << scene.name << " " << method << ": interior median " << interior.median
                          << ", p95 " << interior.p95 << "; all p95 " << all.p95 << ", " << ms << " ms/Mpix\n";
                const bool fails = (interior.count && (interior.median > kFailMedian || interior.p95 > kFailP95)) ||
                                   (all.count && all.p95 > kFailP95);
                const std::string key = family + "/" + method;
                if (fails && !opt.imageDir.empty() && !pictured.count(key)) {
                    pictured.insert(key);
                    const float* pn[3] = {out->requireFloat("N.x"), out->requireFloat("N.y"), out->requireFloat("N.z")};
                    const float* cn[3] = {captured->requireFloat("N.x"), captured->requireFloat("N.y"),
                                          captured->requireFloat("N.z")};
                    auto pic = ao::panel(w, h, 3, [&](int tile, int x, int y, float* rgb) {
                        const std::size_t i = std::size_t(y) * w + x;
                        rgb[0] = rgb[1] = rgb[2] = 0.0f;
                        if (!std::isfinite(z[i])) return;
                        if (tile < 2) {
                            const float* const* v = tile == 0 ? pn : cn;
                            for (int k = 0; k < 3; ++k) rgb[k] = 0.5f + 0.5f * v[k][i];
                            return;
                        }
                        const Vec3 a{pn[0][i], pn[1][i], pn[2][i]}, b{cn[0][i], cn[1][i], cn[2][i]};
                        const double deg = std::atan2(length(cross(a, b)), dot(a, b)) * 180.0 / 3.14159265358979323846;
                        rgb[0] = rgb[1] = rgb[2] = float(std::isfinite(deg) ? deg / kErrorWhite : 1.0);
                    });
                    harness.writePicture(*pic, {"R", "G", "B"}, "normals-" + scene.name + "-" + method);
                }
            }
        }
    }
}

DARKROOM_ACCURACY_SWEEP("normals", "Normals pass (central, nearest, extrapolated) vs captured geometric normals",
                        sweepNormals);

}  // namespace
}  // namespace darkroom::accuracy
