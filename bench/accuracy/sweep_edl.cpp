// Sweep "edl": EyeDomeLighting on the AO stress scenes, scored against the same
// cosine-weighted ray-traced ambient occlusion of the scene's AO radius as
// SSAO (sweep "ao"), so its rows carry sweep = "ao" and the report draws EDL on
// the AO charts and in the AO failure map, next to SSAO. EDL is not an AO
// estimator (it shades slopes and depth steps, in pixels, with a free gain);
// the question is how well it stands in for AO, especially on particles and
// thin lines, where SSAO's surface assumption breaks. The reference is
// computed here as in sweep "ao" (closed form where the scene has one, else
// reference::ambientOcclusion with many rays), background excluded.
#include "ao_common.h"
#include "harness.h"

#include <darkroom/accuracy/metrics.h>
#include <darkroom/accuracy/reference.h>
#include <darkroom/accuracy/stress_scenes.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <set>

namespace darkroom::accuracy {
namespace {

// As sweep "ao": RMSE above which a setting fails; the first failing scene of
// a family gets a picture.
constexpr double kFailRmse = 0.05;

struct EdlSetting {
    std::string method, setting;
    double radius;
    int scales;
    double strength;
};

std::vector<EdlSetting> edlSettings() {
    std::vector<EdlSetting> s;
    // The node's default (the look ParaView and Potree users know) and a tenth
    // of it, closer to AO's magnitude on these scenes.
    for (double strength : {1.0, 0.1}) {
        const std::string method = strength == 1.0 ? "EDL" : "EDL (strength 0.1)";
        for (auto [radius, scales] : std::vector<std::pair<double, int>>{{1, 1}, {1, 2}, {2, 2}, {1, 3}, {2, 3}, {4, 3}})
            s.push_back({method, "radius=" + std::to_string(int(radius)) + " scales=" + std::to_string(scales), radius,
                         scales, strength});
    }
    return s;
}

// The settings equal to the node's defaults (radius 1, 2 scales) get pictures.
bool pictured(const EdlSetting& s) { return s.radius == 1 && s.scales == 2; }

void sweepEdl(Harness& harness, Csv& csv) {
    const Options& opt = harness.options();
    const int refSamples = opt.quick ? 256 : 1024;
    const std::vector<std::string> wanted =
        opt.quick ? std::vector<std::string>{"plane", "corner", "particles", "streamlines"}
                  : std::vector<std::string>{"plane",  "corner",    "terrain",     "gyroid", "staircase",
                                             "border", "particles", "streamlines", "slabs",  "grazing"};
    const auto known = stress::families();
    std::set<std::string> picturedFamilies;
    for (const std::string& family : wanted) {
        if (std::find(known.begin(), known.end(), family) == known.end()) {
            std::cerr << "edl: stress family '" << family << "' does not exist, skipped\n";
            continue;
        }
        std::vector<double> knobs = stress::knobValues(family);
        if (opt.quick && knobs.size() > 2) knobs = {knobs.front(), knobs.back()};
        for (double knob : knobs) {
            const stress::StressScene scene = stress::make(family, knob, {opt.size, opt.size});
            const Camera& cam = scene.camera;
            const int w = cam.width, h = cam.height;
            const std::size_t n = std::size_t(w) * h;
            auto backend = harness.backend(scene);
            Context& ctx = harness.context();
            const BufferPtr gbuffer = backend->render(cam, CaptureRequest{}, ctx);
            const ao::Regions regions = ao::regions(*gbuffer);
            const float* z = gbuffer->requireFloat("Z");

            std::vector<float> refAo(n, 1.0f);
            if (scene.analyticAo) {
                for (int y = 0; y < h; ++y)
                    for (int x = 0; x < w; ++x) {
                        const std::size_t i = std::size_t(y) * w + x;
                        if (!std::isfinite(z[i])) continue;
                        const Vec3 p = cam.worldPosition(x + 0.5, y + 0.5, z[i]);
                        refAo[i] = float(scene.analyticAo(p, scene.aoRadius, reference::AoWeighting::Cosine));
                    }
            } else {
                reference::AoOptions ro;
                ro.radius = scene.aoRadius;
                ro.samples = refSamples;
                const BufferPtr ref = reference::ambientOcclusion(*backend, cam, ro, ctx);
                std::copy_n(ref->requireFloat("AO"), n, refAo.begin());
            }

            Row base;
            base.sweep = "ao";  // drawn with SSAO: same scenes, same reference
            base.scene = scene.name;
            base.family = family;
            base.knob = scene.knob;
            base.knobValue = scene.knobValue;
            {
                // The error of shading nothing (AO = 1): the scale against
                // which a shading's error is worth reading. Untimed, so not
                // on the speed charts; it shows in the region table.
                const std::vector<float> open(n, 1.0f);
                Row r = base;
                r.method = "no shading (AO = 1)";
                r.setting = "";
                for (const char* region : ao::kRegions) {
                    r.region = region;
                    r.metric = "rmse";
                    r.value = metrics::rmse(open.data(), refAo.data(), n, regions.get(region)).value;
                    csv.add(r);
                }
            }
            for (const EdlSetting& s : edlSettings()) {
                BufferPtr out;
                const double ms = harness.msPerMpix(
                    [&] {
                        out = harness.runPass("EyeDomeLighting", gbuffer,
                                              {{"radius", Value(s.radius)},
                                               {"scales", Value(s.scales)},
                                               {"strength", Value(s.strength)}});
                    },
                    n);
                const float* edl = out->requireFloat("EDL");
                Row r = base;
                r.method = s.method;
                r.setting = s.setting;
                r.quality = 8.0 * s.scales + s.radius;  // taps per pixel, then reach
                r.msPerMpix = ms;
                double rmseAll = 0;
                for (const char* region : ao::kRegions) {
                    r.region = region;
                    r.metric = "rmse";
                    r.value = metrics::rmse(edl, refAo.data(), n, regions.get(region)).value;
                    if (r.region == "all") rmseAll = r.value;
                    csv.add(r);
                    r.metric = "bias";
                    r.value = metrics::bias(edl, refAo.data(), n, regions.get(region)).value;
                    csv.add(r);
                }
                r.region = "all";
                r.metric = "ssim";
                r.value = metrics::ssim(edl, refAo.data(), w, h, 1.0, regions.all.data()).value;
                csv.add(r);
                const std::string key = family + "/" + s.method;
                if (pictured(s) && s.method == "EDL" && rmseAll > kFailRmse && !opt.imageDir.empty() &&
                    !picturedFamilies.count(key)) {
                    picturedFamilies.insert(key);
                    auto pic = ao::panel(w, h, 3, [&](int tile, int x, int y, float* rgb) {
                        const std::size_t i = std::size_t(y) * w + x;
                        float v = tile == 0 ? edl[i] : tile == 1 ? refAo[i] : 4.0f * std::fabs(edl[i] - refAo[i]);
                        if (tile == 2 && !std::isfinite(z[i])) v = 0;
                        rgb[0] = rgb[1] = rgb[2] = v;
                    });
                    harness.writePicture(*pic, {"R", "G", "B"}, "ao-" + scene.name + "-edl");
                }
                std::cerr << "edl " << scene.name << " " << s.method << " " << s.setting << ": rmse " << rmseAll << ", "
                          << ms << " ms/Mpix\n";
            }
        }
    }
}

DARKROOM_ACCURACY_SWEEP("edl", "EyeDomeLighting against the cosine-weighted reference AO of sweep ao (rows in sweep ao)",
                        sweepEdl);

}  // namespace
}  // namespace darkroom::accuracy
