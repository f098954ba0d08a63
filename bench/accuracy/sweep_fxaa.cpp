// Sweep "fxaa": FXAA's presets and k x k supersampling against the 16 x 16
// supersampled, per-sample colour-mapped reference, on the stress scenes where
// anti-aliasing matters (straight and curved silhouettes, grazing planes) and
// where FXAA is known to fail (stripes finer than two pixels, sub-pixel lines
// and points). Methods, as the CSV names them:
//   "capture 1 spp"  time only: render the G-buffer + ColorMapping + Background
//   "1 spp"          the aliased input, time 0 (its cost is the capture row)
//   "FXAA"           preset 10 ... 39 on the 1 spp image; time of FXAA alone
//   "SSAA"           k x k samples per pixel through reference::supersampled;
//                    time of that call (ray tracing and shading included)
//   "reference"      time only: the 16 x 16 (8 x 8 quick) reference itself
#include "aa_common.h"

#include <darkroom/accuracy/metrics.h>

#include <algorithm>
#include <iostream>
#include <string>
#include <utility>
#include <vector>

namespace darkroom::accuracy {
namespace {

const std::vector<int> kPresets = {10, 12, 15, 20, 23, 29, 39};
constexpr int kPicturePreset = 12;  // FXAA 3.11's default decides the failure pictures
// FXAA "fails" on a scene when its RMSE is not at least 10 % below the
// aliased input's, or above kFailRmse (twice the aliased error of the plain
// silhouettes of the border scene at 256 px, 0.011): what FXAA leaves is
// then more visible than no anti-aliasing at all on ordinary edges.
constexpr double kFailRatio = 0.9;
constexpr double kFailRmse = 0.02;

struct Case {
    std::string family;
    std::vector<double> knobs;  // in the order run: easy to hard for swept families
    bool picture = false;       // a failure panel at the first failing knob
};

std::vector<double> hardLast(std::vector<double> v) {
    // Stripes (period), streamlines (width) and particles (radius) get harder
    // as the knob shrinks: run them from large to small so the first failure
    // is the threshold.
    std::sort(v.begin(), v.end(), std::greater<>());
    return v;
}

double middle(const std::string& family) {
    const auto v = stress::knobValues(family);
    return v[v.size() / 2];
}

std::vector<Case> cases(bool quick) {
    auto ends = [](const std::string& f) {
        const auto v = hardLast(stress::knobValues(f));
        return v.size() > 1 ? std::vector<double>{v.front(), v.back()} : v;
    };
    if (quick) return {{"stripes", ends("stripes"), true}, {"streamlines", ends("streamlines"), true},
                       {"border", {middle("border")}, false}};
    return {{"stripes", hardLast(stress::knobValues("stripes")), true},
            {"streamlines", hardLast(stress::knobValues("streamlines")), true},
            {"particles", hardLast(stress::knobValues("particles")), true},
            {"border", {middle("border")}, false},
            {"gyroid", {middle("gyroid")}, false},
            {"staircase", {middle("staircase")}, false},
            {"grazing", {84.0, 89.0}, false}};
}

void sweepFxaa(Harness& harness, Csv& csv) {
    const Options& opt = harness.options();
    const int refN = opt.quick ? 8 : 16;
    stress::Options so;
    so.width = so.height = opt.size;
    const std::size_t pixels = std::size_t(opt.size) * std::size_t(opt.size);
    Context& ctx = harness.context();

    for (const Case& c : cases(opt.quick)) {
        bool pictured = false;
        for (double knob : c.knobs) {
            const stress::StressScene scene = stress::make(c.family, knob, so);
            auto backend = harness.backend(scene);
            const CaptureRequest withIds = aa::fieldRequest(scene, true);
            const CaptureRequest fieldOnly = aa::fieldRequest(scene, false);
            const auto shade = aa::sceneShader(scene);

            BufferPtr gbuffer, image;
            const double captureMs = harness.msPerMpix(
                [&] {
                    gbuffer = backend->render(scene.camera, withIds, ctx);
                    image = harness.colorize(scene, gbuffer);
                },
                pixels);
            const metrics::EdgeMasks masks = metrics::edgeMasks(*gbuffer);
            BufferPtr ref;
            const double refMs =
                aa::timeOnceMs([&] { ref = reference::supersampled(*backend, scene.camera, fieldOnly, shade, refN, ctx); });

            Row base;
            base.sweep = "fxaa";
            base.scene = scene.name;
            base.family = scene.family;
            base.knob = scene.knob;
            base.knobValue = scene.knobValue;

            Row r = base;
            r.method = "capture 1 spp";
            r.setting = "render + ColorMapping + Background";
            r.quality = 1;
            aa::addTimeRow(csv, r, captureMs);
            r.method = "reference";
            r.setting = std::to_string(refN) + "x" + std::to_string(refN);
            r.quality = refN * refN;
            aa::addTimeRow(csv, r, refMs / (double(pixels) * 1e-6));

            r = base;
            r.method = "1 spp";
            r.setting = "no AA";
            r.quality = 1;
            r.msPerMpix = 0;
            const double aliased = aa::addErrorRows(csv, r, *image, *ref, masks);

            double fxaaDefault = 0, best = 1e30;
            int bestPreset = 0;
            BufferPtr defaultOut;
            for (int preset : kPresets) {
                const std::map<std::string, Value> params = {{"preset", Value(std::to_string(preset))}};
                BufferPtr out;
                r = base;
                r.method = "FXAA";
                r.setting = "preset " + std::to_string(preset);
                r.quality = preset;
                r.msPerMpix = harness.msPerMpix([&] { out = harness.runPass("FXAA", image, params); }, pixels);
                const double e = aa::addErrorRows(csv, r, *out, *ref, masks);
                if (e < best) best = e, bestPreset = preset;
                if (preset == kPicturePreset) fxaaDefault = e, defaultOut = out;
            }

            double ssaa4 = 0;
            for (int k : {2, 3, 4}) {
                BufferPtr out;
                r = base;
                r.method = "SSAA";
                r.setting = std::to_string(k) + "x" + std::to_string(k);
                r.quality = k * k;
                r.msPerMpix = harness.msPerMpix(
                    [&] { out = reference::supersampled(*backend, scene.camera, fieldOnly, shade, k, ctx); }, pixels);
                ssaa4 = aa::addErrorRows(csv, r, *out, *ref, masks);
            }

            const bool fails = fxaaDefault > kFailRatio * aliased || fxaaDefault > kFailRmse;
            std::cout << "  fxaa " << scene.name << ": 1spp " << aliased << ", FXAA " << kPicturePreset << " "
                      << fxaaDefault << ", best FXAA " << bestPreset << " " << best << ", SSAA 4x4 " << ssaa4
                      << (fails ? "  (FXAA fails)" : "") << std::endl;
            if (c.picture && fails && !pictured) {
                const std::string path =
                    aa::writePanel(harness, {image.get(), defaultOut.get(), ref.get()}, "fxaa-" + c.family);
                if (!path.empty()) std::cout << "    picture " << path << " (1 spp | FXAA 12 | reference)\n";
                pictured = true;
            }
        }
    }
}

}  // namespace

DARKROOM_ACCURACY_SWEEP("fxaa", "FXAA presets and k x k supersampling vs the 16 x 16 supersampled reference",
                        sweepFxaa);

}  // namespace darkroom::accuracy
