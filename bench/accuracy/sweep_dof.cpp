// Sweep "dof": SSDoF (disc with 8 ... 256 taps, hexagon) on the 1-spp
// colour-mapped capture against a thin-lens ray-traced reference with the same
// lens (many lens samples per pixel, jittered sub-pixel positions). Focus at
// the scene's focal distance; the aperture is chosen per scene so that the
// largest circle of confusion on its geometry is kMaxCocRadius pixels, by
// SSDoF's own formula s(z) = A / (2h) (1/z_f - 1/z), h = pixelSizeAt(1).
// Methods, as the CSV names them:
//   "capture 1 spp"   time only: render + ColorMapping + Background
//   "sharp"           the pinhole input itself (what no DoF at all costs in error)
//   "SSDoF disc"      samples 8 ... 256; time of SSDoF alone
//   "SSDoF hexagon"   its own cost (grows with the CoC, not with samples)
//   "reference"       time only: the thin lens
//   "lens only"       the thin lens without pixel jitter (a quarter of the lens
//                     samples) against the reference: what is left when the
//                     defocus is exact but each pixel still sees one point of
//                     the focal plane, i.e. the aliasing no pass on a 1-spp
//                     capture removes. A floor for SSDoF's error.
// The aperture used is written as metric "aperture" of method "reference".
#include "aa_common.h"

#include <darkroom/accuracy/metrics.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <limits>
#include <string>
#include <vector>

namespace darkroom::accuracy {
namespace {

constexpr double kMaxCocRadius = 8.0;  // pixels, SSDoF's signed radius |s|
const std::vector<int> kDiscSamples = {8, 16, 32, 64, 128, 256};
constexpr int kPictureSamples = 64;
// A failure picture when SSDoF (disc, 64 taps) removes less than half of the
// error it could remove (the sharp input's RMSE minus the "lens only" floor)
// and is more than kFailMargin above that floor, or when its RMSE exceeds
// kFailRmse: it then misses much of what the lens does.
constexpr double kFailRatio = 0.5;
constexpr double kFailMargin = 0.005;
constexpr double kFailRmse = 0.03;

struct Case {
    std::string family;
    std::vector<double> knobs;
};

std::vector<double> pick(const std::string& family, int count) {
    const auto v = stress::knobValues(family);
    if (int(v.size()) <= count) return v;
    std::vector<double> out;
    for (int i = 0; i < count; ++i) out.push_back(v[std::size_t(i) * (v.size() - 1) / std::size_t(count - 1)]);
    return out;
}

std::vector<Case> cases(bool quick) {
    const auto all = [](const std::string& f) { return stress::knobValues(f); };
    const auto mid = [&](const std::string& f) {
        const auto v = all(f);
        return std::vector<double>{v[v.size() / 2]};
    };
    if (quick) return {{"staircase", pick("staircase", 1)}, {"slabs", pick("slabs", 1)}, {"border", mid("border")}};
    return {{"staircase", all("staircase")}, {"slabs", all("slabs")},  {"particles", pick("particles", 3)},
            {"streamlines", pick("streamlines", 3)}, {"border", mid("border")}, {"gyroid", mid("gyroid")},
            {"terrain", mid("terrain")}};
}

// The aperture whose largest |CoC radius| over the finite depths of `gbuffer`
// is kMaxCocRadius (background excluded: it is a flat colour). When every
// depth is at the focal distance, the radius is reached at twice it.
double apertureFor(const stress::StressScene& s, const Buffer& gbuffer) {
    const double zf = s.focalDistance, h = s.camera.pixelSizeAt(1.0);
    const float* z = gbuffer.requireFloat("Z");
    double worst = 0;
    for (std::size_t i = 0; i < gbuffer.pixelCount(); ++i)
        if (std::isfinite(z[i]) && z[i] > 0) worst = std::max(worst, std::abs(1.0 / zf - 1.0 / z[i]));
    if (worst < 1e-9) worst = 0.5 / zf;
    return kMaxCocRadius * 2.0 * h / worst;
}

void sweepDof(Harness& harness, Csv& csv) {
    const Options& opt = harness.options();
    const int lensSamples = opt.quick ? 256 : 1024;
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

            BufferPtr gbuffer, image;
            const double captureMs = harness.msPerMpix(
                [&] {
                    gbuffer = backend->render(scene.camera, withIds, ctx);
                    image = harness.colorize(scene, gbuffer);
                },
                pixels);
            const metrics::EdgeMasks masks = metrics::edgeMasks(*gbuffer);
            const double aperture = apertureFor(scene, *gbuffer);

            reference::ThinLens lens;
            lens.aperture = aperture;
            lens.focalDistance = scene.focalDistance;
            lens.lensSamples = lensSamples;
            lens.pixelJitter = true;
            BufferPtr ref;
            const double refMs = aa::timeOnceMs(
                [&] { ref = reference::thinLens(*backend, scene.camera, fieldOnly, aa::sceneShader(scene), lens, ctx); });

            Row base;
            base.sweep = "dof";
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
            r.setting = "thin lens, " + std::to_string(lensSamples) + " lens samples, jittered";
            r.quality = lensSamples;
            aa::addTimeRow(csv, r, refMs / (double(pixels) * 1e-6));
            std::string line;
            double floorErr = 0;
            r.metric = "aperture";
            r.value = aperture;
            r.region = "all";
            csv.add(r);

            {
                reference::ThinLens still = lens;
                still.pixelJitter = false;
                still.lensSamples = std::max(16, lensSamples / 4);
                BufferPtr floor;
                r = base;
                r.method = "lens only";
                r.setting = "thin lens, " + std::to_string(still.lensSamples) + " lens samples, no pixel jitter";
                r.quality = still.lensSamples;
                r.msPerMpix = aa::timeOnceMs([&] {
                    floor = reference::thinLens(*backend, scene.camera, fieldOnly, aa::sceneShader(scene), still, ctx);
                }) / (double(pixels) * 1e-6);
                floorErr = aa::addErrorRows(csv, r, *floor, *ref, masks);
                line += " lens-only " + std::to_string(floorErr) + ",";
            }

            r = base;
            r.method = "sharp";
            r.setting = "pinhole input";
            r.quality = 0;
            r.msPerMpix = 0;
            const double sharp = aa::addErrorRows(csv, r, *image, *ref, masks);

            const std::map<std::string, Value> lensParams = {{"aperture", Value(aperture)},
                                                             {"focalDistance", Value(scene.focalDistance)},
                                                             {"maxBlur", Value(2.0 * kMaxCocRadius)}};
            double pictureErr = 0;
            BufferPtr pictureOut;
            for (int samples : kDiscSamples) {
                auto params = lensParams;
                params["method"] = Value(std::string("disc"));
                params["samples"] = Value(samples);
                BufferPtr out;
                r = base;
                r.method = "SSDoF disc";
                r.setting = "samples " + std::to_string(samples);
                r.quality = samples;
                r.msPerMpix = harness.msPerMpix([&] { out = harness.runPass("SSDoF", image, params); }, pixels);
                const double e = aa::addErrorRows(csv, r, *out, *ref, masks);
                line += " disc" + std::to_string(samples) + " " + std::to_string(e);
                if (samples == kPictureSamples) pictureErr = e, pictureOut = out;
            }
            {
                auto params = lensParams;
                params["method"] = Value(std::string("hexagon"));
                BufferPtr out;
                r = base;
                r.method = "SSDoF hexagon";
                r.setting = "hexagon";
                r.quality = 0;
                r.msPerMpix = harness.msPerMpix([&] { out = harness.runPass("SSDoF", image, params); }, pixels);
                line += " hexagon " + std::to_string(aa::addErrorRows(csv, r, *out, *ref, masks));
            }

            const double above = pictureErr - floorErr;
            const bool fails =
                (above > kFailRatio * (sharp - floorErr) && above > kFailMargin) || pictureErr > kFailRmse;
            std::cout << "  dof " << scene.name << ": aperture " << aperture << ", sharp " << sharp << "," << line
                      << (fails ? "  (SSDoF fails)" : "") << std::endl;
            if (fails && !pictured) {
                const auto err = aa::errorImage(*pictureOut, *ref, 4.0f);
                const std::string path =
                    aa::writePanel(harness, {pictureOut.get(), ref.get(), err.get()}, "dof-" + scene.name);
                if (!path.empty()) std::cout << "    picture " << path << " (SSDoF disc 64 | reference | 4 x error)\n";
                pictured = true;
            }
        }
    }
}

}  // namespace

DARKROOM_ACCURACY_SWEEP("dof", "SSDoF (disc samples, hexagon) vs a thin-lens ray-traced reference", sweepDof);

}  // namespace darkroom::accuracy
