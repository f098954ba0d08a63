// FXAA against a supersampled reference: a colour-mapped isosurface rendered
// by the embree backend at 4x4 the resolution and box-filtered down. FXAA on
// the 1x render must come closer to it than the 1x render itself.
#include "fxaa_helpers.h"

#include <darkroom/capture_backend.h>
#include <darkroom/core/registry.h>
#include <darkroom/scene/generators.h>
#include <darkroom/scene/scene_file.h>
#include <darkroom/srgb.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>

using namespace darkroom;
using namespace darkroom::test;

namespace {

constexpr int kSize = 160;
constexpr int kFactor = 4;

// Renders `height` of the isosurface at size x size, maps it to colour with a
// fixed range (so both resolutions use the same map) and composites it over
// an opaque grey background: the silhouettes are edges FXAA may smooth.
BufferPtr renderColour(int size) {
    auto scene = std::make_shared<Scene>();
    scene->objects = generate("isosurface", {});
    const Bounds b = scene->bounds();
    Camera proto;
    proto.width = proto.height = size;
    proto.fovYDegrees = 30.0;
    const Camera cam = orbitCamera(proto, b.center(), 1.05 * fittingDistance(proto, b.radius()), 30.0, 20.0,
                                   Vec3{0, 0, 1});

    auto backend = pluginRegistry().createBackend("embree");
    EXPECT_TRUE(backend);
    backend->setScene(scene);
    FilterRunOptions options;
    options.threads = 2;
    auto ctx = makeStandaloneContext(options, "fxaa-reference");
    CaptureRequest request;
    request.scalars = {"height"};
    const BufferPtr gbuffer = backend->render(cam, request, *ctx);

    auto map = pluginRegistry().createFilter("ColorMapping");
    const BufferPtr mapped =
        runFilter(*map, {{"image", {Value(gbuffer)}},
                         {"channel", {Value("height")}},
                         {"colormap", {Value("viridis")}},
                         {"range", {Value("manual")}},
                         {"minimum", {Value(b.lo.z)}},
                         {"maximum", {Value(b.hi.z)}}},
                  options)
            .outputs.at("image")
            .asImage();
    const float grey = 0.8f;
    return makeImage(size, size, {"R", "G", "B", "A"}, [&](int x, int y, int c) {
        const std::size_t i = std::size_t(y) * std::size_t(size) + std::size_t(x);
        if (c == 3) return 1.0f;
        const char* names[] = {"R", "G", "B"};
        const float a = mapped->hostFloat("A")[i];
        return a * mapped->hostFloat(names[c])[i] + (1.0f - a) * grey;
    });
}

// Mean of each factor x factor block (linear light: what a pixel integrates).
BufferPtr boxDown(const Buffer& big, int factor) {
    const int w = big.width() / factor, h = big.height() / factor;
    return makeImage(w, h, {"R", "G", "B", "A"}, [&](int x, int y, int c) {
        if (c == 3) return 1.0f;
        const char* names[] = {"R", "G", "B"};
        double sum = 0.0;
        for (int j = 0; j < factor; ++j)
            for (int i = 0; i < factor; ++i) sum += at(big, names[c], x * factor + i, y * factor + j);
        return float(sum / (factor * factor));
    });
}

struct Errors {
    double linear = 0.0;   // RMSE of linear R, G, B
    double encoded = 0.0;  // RMSE of sRGB-encoded R, G, B (what a viewer sees)
};

Errors rmse(const Buffer& a, const Buffer& b) {
    double lin = 0.0, enc = 0.0;
    for (const char* c : {"R", "G", "B"})
        for (std::size_t i = 0; i < a.pixelCount(); ++i) {
            const float x = a.hostFloat(c)[i], y = b.hostFloat(c)[i];
            lin += double(x - y) * double(x - y);
            const double d = linearToSrgb(std::clamp(x, 0.0f, 1.0f)) - linearToSrgb(std::clamp(y, 0.0f, 1.0f));
            enc += d * d;
        }
    const double n = 3.0 * double(a.pixelCount());
    return {std::sqrt(lin / n), std::sqrt(enc / n)};
}

}  // namespace

TEST(FxaaReference, ComesCloserToA4x4SupersampledRenderThanTheAliasedOne) {
    const BufferPtr reference = boxDown(*renderColour(kSize * kFactor), kFactor);
    const BufferPtr aliased = renderColour(kSize);
    const Errors raw = rmse(*aliased, *reference);
    std::printf("[ reference ] isosurface %dx%d vs 4x4 box-filtered: aliased RMSE linear %.5f sRGB %.5f\n", kSize,
                kSize, raw.linear, raw.encoded);
    for (const char* preset : {"10", "12", "29", "39"}) {
        const Errors fx = rmse(*runFxaa(aliased, {{"preset", {Value(preset)}}}), *reference);
        std::printf("[ reference ] FXAA preset %s: RMSE linear %.5f sRGB %.5f (%.0f%% / %.0f%% of aliased)\n", preset,
                    fx.linear, fx.encoded, 100.0 * fx.linear / raw.linear, 100.0 * fx.encoded / raw.encoded);
        EXPECT_LT(fx.linear, 0.9 * raw.linear) << "preset " << preset;
        EXPECT_LT(fx.encoded, 0.9 * raw.encoded) << "preset " << preset;
    }
}
