// Sweep "transparency" (issue 30): opacity chosen after capture. A capture of
// the K nearest crossings per pixel (K = 1, 2, 4, 8), colour-mapped with
// opacity by ColorMapping (layers blended front to back) over the harness's
// background, against reference::transparent — every crossing in exact depth
// order with the same colours and opacities. Scenes: nested shells (the inner
// one opaque), a stack of sheets and the streamline bundle, whose depth
// complexity exceeds the small K: the failure rows. Also the bytes per pixel
// of each K's G-buffer as a zip-compressed EXR (the storage cost).
#include "harness.h"

#include <darkroom/colormap.h>
#include <darkroom/error.h>
#include <darkroom/accuracy/metrics.h>
#include <darkroom/accuracy/reference.h>
#include <darkroom/accuracy/stress_scenes.h>
#include <darkroom/data/image_io.h>

#include <cmath>
#include <filesystem>
#include <iostream>
#include <unistd.h>

namespace darkroom::accuracy {
namespace {

constexpr float kOpacity = 0.4f;
const int kLayers[] = {1, 2, 4, 8};

struct Case {
    std::string family;
    double knob;
};

std::vector<Case> cases(bool quick) {
    if (quick) return {{"shells", 2}, {"sheets", 8}};
    return {{"shells", 1}, {"shells", 2}, {"shells", 3}, {"shells", 4}, {"sheets", 2}, {"sheets", 4},
            {"sheets", 8}, {"sheets", 16}, {"streamlines", 2}, {"streamlines", 4}};
}

// The shells' innermost object (id 0) is opaque, everything else kOpacity:
// translucent outer shells over an opaque core, as in the gallery figure.
float opacityOf(const stress::StressScene& s, std::uint32_t objectId) {
    return s.family == "shells" && objectId == 0 ? 1.0f : kOpacity;
}

// ColorMapping's parameters giving the same: opacity 1 with the translucent
// objects listed, or kOpacity for all.
std::map<std::string, Value> colorMapping(const stress::StressScene& s) {
    std::map<std::string, Value> p{{"channel", Value(s.colorField)},  {"colormap", Value("viridis")},
                                   {"range", Value("manual")},         {"minimum", Value(s.fieldMin)},
                                   {"maximum", Value(s.fieldMax)}};
    if (s.family == "shells") {
        std::string list;
        for (std::size_t id = 1; id < s.scene->objects.size(); ++id)
            list += (list.empty() ? "" : ", ") + std::to_string(id) + ": " + std::to_string(kOpacity);
        p["opacity"] = Value(1.0);
        p["objectOpacity"] = Value(list);
    } else {
        p["opacity"] = Value(double(kOpacity));
    }
    return p;
}

reference::SampleShader crossingShader(const stress::StressScene& s) {
    static const ColorMapData viridis = loadColorMap("viridis");
    return [&s](const Buffer& hits, std::size_t i, float rgba[4]) {
        const float v = hits.requireFloat(s.colorField)[i];
        const Color c = std::isnan(v) ? viridis.nanColor : viridis.sample((double(v) - s.fieldMin) / (s.fieldMax - s.fieldMin));
        rgba[0] = c.r, rgba[1] = c.g, rgba[2] = c.b;
        rgba[3] = opacityOf(s, hits.requireUInt("objectId")[i]);
    };
}

// Size of `g` written as a zip-compressed EXR, in bytes.
double exrBytes(const Buffer& g, const std::string& name) {
    const auto path = std::filesystem::temp_directory_path() / ("darkroom-layers-" + std::to_string(::getpid()) + "-" + name + ".exr");
    writeImage(g, path.string());
    const double bytes = double(std::filesystem::file_size(path));
    std::filesystem::remove(path);
    return bytes;
}

void sweepCase(Harness& harness, Csv& csv, const stress::StressScene& scene) {
    auto backend = harness.backend(scene);
    Context& ctx = harness.context();
    const Camera& cam = scene.camera;
    const std::size_t n = std::size_t(cam.width) * cam.height;
    CaptureRequest request;
    request.scalars = {scene.colorField};
    request.objectId = true;
    const Color bg{Harness::kBackground[0], Harness::kBackground[1], Harness::kBackground[2], 1.0f};
    const BufferPtr ref = reference::transparent(*backend, cam, request, crossingShader(scene), bg, 256, ctx);
    const float* crossings = ref->requireFloat("crossings");
    std::vector<std::uint8_t> covered(n), beyond(n);
    double maxCrossings = 0;
    for (std::size_t i = 0; i < n; ++i) {
        covered[i] = crossings[i] > 0;
        maxCrossings = std::max(maxCrossings, double(crossings[i]));
    }
    Row base;
    base.sweep = "transparency";
    base.scene = scene.name;
    base.family = scene.family;
    base.knob = scene.knob;
    base.knobValue = scene.knobValue;
    {
        Row r = base;
        r.method = "reference";
        r.setting = "every crossing";
        r.metric = "max_crossings";
        r.value = maxCrossings;
        csv.add(r);
    }
    for (const int K : kLayers) {
        CaptureRequest layered = request;
        layered.layers = K;
        BufferPtr g;
        const double captureMs = harness.msPerMpix([&] { g = backend->render(cam, layered, ctx); }, n);
        BufferPtr shaded;
        const double shadeMs = harness.msPerMpix(
            [&] {
                shaded = harness.runPass("Background",
                                         harness.runPass("ColorMapping", g, colorMapping(scene)),
                                         {{"mode", Value("color")},
                                          {"color", Value(Color{bg.r, bg.g, bg.b, 1.0f})}});
            },
            n);
        for (std::size_t i = 0; i < n; ++i) beyond[i] = crossings[i] > float(K);
        Row r = base;
        r.method = "layers + ColorMapping";
        r.setting = "K=" + std::to_string(K);
        r.quality = K;
        r.msPerMpix = captureMs + shadeMs;
        const char* channels[3] = {"R", "G", "B"};
        for (const auto& [region, mask] : {std::pair<const char*, const std::uint8_t*>{"all", covered.data()},
                                           {"beyond K", beyond.data()}}) {
            double sum = 0;
            std::size_t count = 0;
            for (int c = 0; c < 3; ++c) {
                const float* got = shaded->requireFloat(channels[c]);
                const float* want = ref->requireFloat(channels[c]);
                for (std::size_t i = 0; i < n; ++i)
                    if (mask[i]) sum += double(got[i] - want[i]) * double(got[i] - want[i]), ++count;
            }
            r.region = region;
            r.metric = "rmse";
            r.value = count ? std::sqrt(sum / double(count)) : 0.0;
            csv.add(r);
        }
        r.region = "all";
        r.metric = "capture_ms_per_mpix";
        r.value = captureMs;
        csv.add(r);
        r.metric = "bytes_per_pixel";
        r.value = exrBytes(*g, scene.name + "-" + std::to_string(K)) / double(n);
        csv.add(r);
        std::cerr << "transparency " << scene.name << " K=" << K << ": capture " << captureMs << " + shade " << shadeMs
                  << " ms/Mpix, " << r.value << " B/px\n";
    }
}

void sweepTransparency(Harness& harness, Csv& csv) {
    for (const Case& c : cases(harness.options().quick))
        sweepCase(harness, csv, stress::make(c.family, c.knob, {harness.options().size, harness.options().size}));
}

}  // namespace

DARKROOM_ACCURACY_SWEEP("transparency",
                        "K captured layers + ColorMapping opacity vs every crossing composited in depth order",
                        sweepTransparency);

}  // namespace darkroom::accuracy
