// Sweep "ao": SSAO (horizon and hemisphere; half resolution, the default, and
// full, and captured at reduced resolution then upsampled; surface and points
// geometry; LineAO, PointAO and SAO) and ray-traced AO at growing sample
// counts, the surface scenes also at 4 and 16 times their radius (horizon
// against SAO, scenes named "-R4x", "-R16x"), against the
// cosine-weighted AO of the same world radius: the scene's closed form where
// it has one (plane, corner), else reference::ambientOcclusion with many rays.
// Background is excluded from every statistic.
#include "ao_common.h"
#include "ao_point_list.h"
#include "harness.h"

#include <darkroom/error.h>
#include <darkroom/accuracy/metrics.h>
#include <darkroom/accuracy/reference.h>
#include <darkroom/accuracy/stress_scenes.h>

#include <algorithm>
#include <chrono>
#include <functional>
#include <cmath>
#include <iostream>
#include <limits>
#include <set>
#include <sstream>

namespace darkroom::accuracy {
namespace {

// RMSE (over the object's pixels) above which a setting counts as failing on
// a scene; the first knob value past it gets a picture. 0.05 is about the
// difference one sees between two AO images multiplied into a colour map.
constexpr double kFailRmse = 0.05;

// Seeds apart from the reference's (0), so the ray-traced curve is not the
// reference's own first samples.
constexpr std::uint32_t kCurveSeed = 7919;

std::vector<std::pair<std::string, std::vector<double>>> selectedScenes(bool quick,
                                                                       const std::vector<std::string>& only) {
    std::vector<std::string> wanted =
        quick ? std::vector<std::string>{"plane", "corner", "particles", "slabs"}
              : std::vector<std::string>{"plane",     "corner", "terrain",   "gyroid",      "staircase",
                                         "border",    "particles", "streamlines", "slabs", "grazing"};
    if (!only.empty()) wanted = only;
    const auto known = stress::families();
    std::vector<std::pair<std::string, std::vector<double>>> out;
    for (const auto& f : wanted) {
        if (std::find(known.begin(), known.end(), f) == known.end()) {
            std::cerr << "ao: stress family '" << f << "' does not exist, skipped\n";
            continue;
        }
        std::vector<double> knobs = stress::knobValues(f);
        if (quick && knobs.size() > 2) knobs = {knobs.front(), knobs.back()};
        // Lines wider than the family's sweep: where PointListAO's thin-line
        // model (r << distance) breaks down, its own failure rows.
        if (f == "streamlines" && !quick) knobs.insert(knobs.end(), {8.0, 16.0});
        out.emplace_back(f, knobs);
    }
    return out;
}

// Best of `repeats` wall times in ms per megapixel (the harness's routine
// with a repeat count of our choosing, for the expensive ray-traced points).
double timed(const std::function<void()>& work, std::size_t pixels, int repeats) {
    double best = std::numeric_limits<double>::infinity();
    for (int i = 0; i < std::max(1, repeats); ++i) {
        const auto t0 = std::chrono::steady_clock::now();
        work();
        best = std::min(best, std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count());
    }
    return best / (double(pixels) * 1e-6);
}

double maskedMean(const float* v, const std::vector<std::uint8_t>& mask) {
    double s = 0;
    std::size_t n = 0;
    for (std::size_t i = 0; i < mask.size(); ++i)
        if (mask[i] && std::isfinite(v[i])) s += v[i], ++n;
    return n ? s / double(n) : std::numeric_limits<double>::quiet_NaN();
}

struct SsaoSetting {
    std::string method, setting;
    double quality;
    std::map<std::string, Value> params;
    double scale = 1.0;  // capture and SSAO at this fraction of the size
};

std::vector<SsaoSetting> ssaoSettings(const std::string& family) {
    std::vector<SsaoSetting> s;
    // The pass as configured by default (resolution: half: the estimator at
    // even x and y on the full-resolution depth, the rest filled on the same
    // surface), at growing sample counts.
    for (auto [sl, st] : std::vector<std::pair<int, int>>{{1, 2}, {2, 4}, {4, 4}, {4, 8}, {8, 8}, {8, 16}, {16, 16}})
        s.push_back({"horizon", "slices=" + std::to_string(sl) + " steps=" + std::to_string(st), double(sl * st),
                     {{"method", Value("horizon")}, {"slices", Value(sl)}, {"steps", Value(st)}}});
    for (int n : {4, 8, 16, 32, 64, 128})
        s.push_back({"hemisphere", "samples=" + std::to_string(n), double(n),
                     {{"method", Value("hemisphere")}, {"samples", Value(n)}}});
    // The estimator at every pixel.
    for (auto [sl, st] : std::vector<std::pair<int, int>>{{4, 4}, {4, 8}, {8, 8}, {16, 16}})
        s.push_back({"horizon full resolution", "slices=" + std::to_string(sl) + " steps=" + std::to_string(st),
                     double(sl * st),
                     {{"method", Value("horizon")}, {"slices", Value(sl)}, {"steps", Value(st)},
                      {"resolution", Value("full")}}});
    for (int n : {16, 64})
        s.push_back({"hemisphere full resolution", "samples=" + std::to_string(n), double(n),
                     {{"method", Value("hemisphere")}, {"samples", Value(n)}, {"resolution", Value("full")}}});
    // Captured at a fraction of the size, the estimator at every pixel there,
    // then upsampled bilinearly.
    for (double scale : {0.5, 0.25}) {
        std::ostringstream name;
        name << "horizon at " << scale << "x";
        s.push_back({name.str(), "slices=4 steps=8", 32.0 * scale * scale,
                     {{"method", Value("horizon")}, {"slices", Value(4)}, {"steps", Value(8)},
                      {"resolution", Value("full")}},
                     scale});
    }
    // The captured normals instead of reconstructed ones: separates the
    // normal's share of the error from the occlusion estimate's.
    s.push_back({"horizon + captured normals", "slices=4 steps=8", 32.0,
                 {{"method", Value("horizon")}, {"slices", Value(4)}, {"steps", Value(8)}, {"useNormals", Value(true)}}});
    // The pyramid estimators (plugins/ssao/README.md): LineAO and PointAO at
    // growing points per level (3 levels), SAO at growing spiral taps.
    for (const char* method : {"lineao", "pointao"})
        for (int n : {8, 16, 32})
            s.push_back({method, "samples=" + std::to_string(n), double(3 * n),
                         {{"method", Value(method)}, {"samples", Value(n)}}});
    for (int n : {8, 16, 32, 64})
        s.push_back({"sao", "taps=" + std::to_string(n), double(n), {{"method", Value("sao")}, {"samples", Value(n)}}});
    if (family == "particles" || family == "streamlines") {
        s.push_back({"horizon points", "slices=4 steps=8", 32.0,
                     {{"method", Value("horizon")}, {"slices", Value(4)}, {"steps", Value(8)}, {"geometry", Value("points")}}});
        s.push_back({"hemisphere points", "samples=16", 16.0,
                     {{"method", Value("hemisphere")}, {"samples", Value(16)}, {"geometry", Value("points")}}});
    }
    return s;
}

// At a multiple of the scene's radius (surface scenes): horizon against SAO,
// whose cost should not grow with the radius.
std::vector<SsaoSetting> largeRadiusSettings() {
    std::vector<SsaoSetting> s;
    for (auto [sl, st] : std::vector<std::pair<int, int>>{{2, 4}, {4, 8}, {8, 16}})
        s.push_back({"horizon", "slices=" + std::to_string(sl) + " steps=" + std::to_string(st), double(sl * st),
                     {{"method", Value("horizon")}, {"slices", Value(sl)}, {"steps", Value(st)}}});
    s.push_back({"horizon full resolution", "slices=4 steps=8", 32.0,
                 {{"method", Value("horizon")}, {"slices", Value(4)}, {"steps", Value(8)}, {"resolution", Value("full")}}});
    for (int n : {8, 16, 32, 64})
        s.push_back({"sao", "taps=" + std::to_string(n), double(n), {{"method", Value("sao")}, {"samples", Value(n)}}});
    s.push_back({"sao full resolution", "taps=16", 16.0,
                 {{"method", Value("sao")}, {"samples", Value(16)}, {"resolution", Value("full")}}});
    return s;
}

// Surface families also swept at these multiples of their AO radius, as
// scenes of their own ("terrain-R4x", family "terrain-R4x").
const std::vector<int>& largeRadiusScales(const std::string& family, bool quick) {
    static const std::vector<int> none, scales{4, 16}, quickScales{4};
    if (family != "terrain" && family != "gyroid" && family != "corner") return none;
    return quick ? quickScales : scales;
}

bool picturedSetting(const SsaoSetting& s) {
    return (s.method == "horizon" && s.setting == "slices=4 steps=8") ||
           (s.method == "hemisphere" && s.setting == "samples=16");
}

// AO, reference and 4 x their difference side by side.
void writeFailurePicture(Harness& harness, int w, int h, const float* ao, const float* refAo, const float* z,
                         const std::string& name) {
    auto pic = ao::panel(w, h, 3, [&](int tile, int x, int y, float* rgb) {
        const std::size_t i = std::size_t(y) * w + x;
        float v = tile == 0 ? ao[i] : tile == 1 ? refAo[i] : 4.0f * std::fabs(ao[i] - refAo[i]);
        if (tile == 2 && !std::isfinite(z[i])) v = 0;
        rgb[0] = rgb[1] = rgb[2] = v;
    });
    harness.writePicture(*pic, {"R", "G", "B"}, name);
}

// Reference AO (cosine) of one scene at `radius`, and its rows; the
// uniform-weighted one too where asked.
std::vector<float> referenceAo(Harness& harness, Csv& csv, const stress::StressScene& scene, CaptureBackend& backend,
                               const Buffer& gbuffer, const ao::Regions& regions, double radius, const Row& base) {
    const Options& opt = harness.options();
    const int refSamples = opt.quick ? 256 : 1024;
    const Camera& cam = scene.camera;
    const int w = cam.width, h = cam.height;
    const std::size_t n = std::size_t(w) * h;
    const float* z = gbuffer.requireFloat("Z");
    Context& ctx = harness.context();
    std::vector<float> refAo(n, 1.0f);
    std::vector<float> uniformAo;
    const bool wantUniform = (base.family == "corner" || base.family == "terrain");
    std::string refSetting;
    if (scene.analyticAo) {
        refSetting = "analytic";
        if (wantUniform) uniformAo.assign(n, 1.0f);
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x) {
                const std::size_t i = std::size_t(y) * w + x;
                if (!std::isfinite(z[i])) continue;
                const Vec3 p = cam.worldPosition(x + 0.5, y + 0.5, z[i]);
                refAo[i] = float(scene.analyticAo(p, radius, reference::AoWeighting::Cosine));
                if (wantUniform) uniformAo[i] = float(scene.analyticAo(p, radius, reference::AoWeighting::Uniform));
            }
    } else {
        refSetting = "samples=" + std::to_string(refSamples);
        reference::AoOptions ro;
        ro.radius = radius;
        ro.samples = refSamples;
        const BufferPtr ref = reference::ambientOcclusion(backend, cam, ro, ctx);
        std::copy_n(ref->requireFloat("AO"), n, refAo.begin());
        Row r = base;
        r.method = "reference";
        r.setting = refSetting;
        r.quality = refSamples;
        r.metric = "stderr";
        r.value = maskedMean(ref->requireFloat("AO.stderr"), regions.all);
        csv.add(r);
        if (wantUniform) {
            ro.weighting = reference::AoWeighting::Uniform;
            const BufferPtr u = reference::ambientOcclusion(backend, cam, ro, ctx);
            uniformAo.assign(u->requireFloat("AO"), u->requireFloat("AO") + n);
        }
    }
    Row r = base;
    r.method = "reference";
    r.setting = refSetting;
    r.metric = "mean_ao";
    r.value = maskedMean(refAo.data(), regions.all);
    csv.add(r);
    if (!uniformAo.empty()) {
        r.method = "uniform vs cosine reference";
        r.metric = "rmse";
        r.value = metrics::rmse(uniformAo.data(), refAo.data(), n, regions.all.data()).value;
        csv.add(r);
        r.metric = "bias";
        r.value = metrics::bias(uniformAo.data(), refAo.data(), n, regions.all.data()).value;
        csv.add(r);
    }
    return refAo;
}

// Ray-traced AO as its own curve, at 1 to 256 rays per pixel: where it
// beats screen space. `emit` records one setting's rows.
using EmitFn = std::function<double(const std::string&, const std::string&, double, double, const float*)>;
void rayTracedCurve(Harness& harness, CaptureBackend& backend, const Camera& cam, double radius,
                    const std::string& scene, const EmitFn& emit) {
    const std::size_t n = std::size_t(cam.width) * cam.height;
    for (int samples = 1; samples <= 256; samples *= 2) {
        reference::AoOptions ro;
        ro.radius = radius;
        ro.samples = samples;
        ro.seed = kCurveSeed;
        BufferPtr out;
        const double ms = timed([&] { out = reference::ambientOcclusion(backend, cam, ro, harness.context()); }, n,
                                samples <= 16 ? harness.options().repeats : 1);
        const double e = emit("ray traced (cosine)", "samples=" + std::to_string(samples), samples, ms,
                              out->requireFloat("AO"));
        std::cerr << "ao " << scene << " ray traced " << samples << ": rmse " << e << ", " << ms << " ms/Mpix\n";
    }
}

// One scene at `radiusScale` times its AO radius: the reference, every SSAO
// setting, and ray-traced AO at growing ray counts.
void sweepScene(Harness& harness, Csv& csv, const std::string& family, const stress::StressScene& scene,
                int radiusScale, std::set<std::string>& pictured) {
    const Options& opt = harness.options();
    const Camera& cam = scene.camera;
    const int w = cam.width, h = cam.height;
    const std::size_t n = std::size_t(w) * h;
    auto backend = harness.backend(scene);
    Context& ctx = harness.context();
    CaptureRequest request;
    request.normals = true;
    request.objectId = true;
    const BufferPtr gbuffer = backend->render(cam, request, ctx);
    const ao::Regions regions = ao::regions(*gbuffer);
    const float* z = gbuffer->requireFloat("Z");
    const double radius = scene.aoRadius * radiusScale;
    const std::string suffix = radiusScale == 1 ? "" : "-R" + std::to_string(radiusScale) + "x";

    Row base;
    base.sweep = "ao";
    base.scene = scene.name + suffix;
    base.family = family + suffix;
    base.knob = scene.knob;
    base.knobValue = scene.knobValue;
    const std::vector<float> refAo = referenceAo(harness, csv, scene, *backend, *gbuffer, regions, radius, base);

    // One setting's rows; returns its RMSE over all object pixels.
    auto emit = [&](const std::string& method, const std::string& setting, double quality, double ms,
                    const float* ao) {
        Row r = base;
        r.method = method;
        r.setting = setting;
        r.quality = quality;
        r.msPerMpix = ms;
        double rmseAll = 0;
        for (const char* region : ao::kRegions) {
            r.region = region;
            r.metric = "rmse";
            r.value = metrics::rmse(ao, refAo.data(), n, regions.get(region)).value;
            if (r.region == "all") rmseAll = r.value;
            csv.add(r);
            r.metric = "bias";
            r.value = metrics::bias(ao, refAo.data(), n, regions.get(region)).value;
            csv.add(r);
        }
        r.region = "all";
        r.metric = "ssim";
        r.value = metrics::ssim(ao, refAo.data(), w, h, 1.0, regions.all.data()).value;
        csv.add(r);
        return rmseAll;
    };

    for (const SsaoSetting& s : radiusScale == 1 ? ssaoSettings(family) : largeRadiusSettings()) {
        auto params = s.params;
        params["radiusUnits"] = Value("world");
        params["radius"] = Value(radius);
        params["falloff"] = Value(0.0);
        params["blurRadius"] = Value(0);
        if (!params.count("geometry")) params["geometry"] = Value("surface");
        std::vector<float> ao(n);
        double ms;
        if (s.scale == 1.0) {
            BufferPtr out;
            ms = harness.msPerMpix([&] { out = harness.runPass("SSAO", gbuffer, params); }, n);
            std::copy_n(out->requireFloat("AO"), n, ao.begin());
        } else {
            Camera small = cam;
            small.width = std::max(1, int(std::lround(w * s.scale)));
            small.height = std::max(1, int(std::lround(h * s.scale)));
            const BufferPtr low = backend->render(small, CaptureRequest{}, ctx);
            BufferPtr up;
            ms = harness.msPerMpix(
                [&] { up = ao::upsampleBilinear(*harness.runPass("SSAO", low, params), "AO", w, h); }, n);
            std::copy_n(up->requireFloat("AO"), n, ao.begin());
        }
        const double e = emit(s.method, s.setting, s.quality, ms, ao.data());
        const std::string key = base.family + "/" + s.method;
        if (picturedSetting(s) && e > kFailRmse && !opt.imageDir.empty() && !pictured.count(key)) {
            pictured.insert(key);
            writeFailurePicture(harness, w, h, ao.data(), refAo.data(), z, "ao-" + base.scene + "-" + s.method);
        }
        std::cerr << "ao " << base.scene << " " << s.method << " " << s.setting << ": rmse " << e << ", " << ms
                  << " ms/Mpix\n";
    }

    // The particles or lines themselves, from the list a capture stores.
    if (ao::hasPointList(scene)) {
        std::vector<float> listAo;
        const double ms = ao::pointListAo(harness, scene, gbuffer, radius, listAo);
        const double e = emit("point list", "closed form", 1, ms, listAo.data());
        std::cerr << "ao " << base.scene << " point list: rmse " << e << ", " << ms << " ms/Mpix\n";
    }

    rayTracedCurve(harness, *backend, cam, radius, base.scene, emit);
}

void sweepAo(Harness& harness, Csv& csv) {
    const Options& opt = harness.options();
    std::set<std::string> pictured;  // family/method pairs that already have their picture
    for (const auto& [family, knobs] : selectedScenes(opt.quick, opt.families)) {
        for (double knob : knobs) {
            const stress::StressScene scene = stress::make(family, knob, {opt.size, opt.size});
            sweepScene(harness, csv, family, scene, 1, pictured);
            for (int scale : largeRadiusScales(family, opt.quick)) sweepScene(harness, csv, family, scene, scale, pictured);
        }
    }
}

DARKROOM_ACCURACY_SWEEP("ao", "SSAO horizon/hemisphere and ray-traced AO vs cosine-weighted reference AO", sweepAo);

}  // namespace
}  // namespace darkroom::accuracy
