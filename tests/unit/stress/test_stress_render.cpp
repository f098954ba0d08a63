// Every stress scene captured by the Embree backend (skipped when this build
// has no capture-embree plugin): the share of pixels with geometry lies in
// the family's bounds, and the colour field reaches the image. With
// DARKROOM_STRESS_DUMP=<folder> it also writes a shaded PNG of every scene of
// every sweep (size DARKROOM_STRESS_DUMP_SIZE, default 256) for inspection.
#include <darkroom/capture_backend.h>
#include <darkroom/error.h>
#include <darkroom/data/image_io.h>
#include <darkroom/core/registry.h>
#include <darkroom/core/run_filter.h>
#include <darkroom/accuracy/stress_scenes.h>

#include <gtest/gtest.h>

#include "test_support.h"

#include <cmath>
#include <cstdlib>
#include <map>

using namespace darkroom;

namespace {

std::unique_ptr<CaptureBackend> embree() {
    try {
        return test::pluginRegistry().createBackend("embree");
    } catch (const Error&) {
        return nullptr;
    }
}

BufferPtr capture(CaptureBackend& backend, const stress::StressScene& s) {
    backend.setScene(s.scene);
    CaptureRequest request;
    request.scalars = {s.colorField};
    request.normals = true;
    FilterRunOptions options;
    options.threads = 2;
    auto ctx = makeStandaloneContext(options, "stress-test");
    return backend.render(s.camera, request, *ctx);
}

// A blue-to-orange ramp of the field, lit by the view direction.
void writeShaded(const stress::StressScene& s, const Buffer& g, const std::string& path) {
    const int w = g.width(), h = g.height();
    auto img = makeCpuBuffer(w, h, {{"R"}, {"G"}, {"B"}, {"A"}});
    const float *z = g.requireFloat("Z"), *f = g.requireFloat(s.colorField);
    const float *nx = g.requireFloat("N.x"), *ny = g.requireFloat("N.y"), *nz = g.requireFloat("N.z");
    float *r = img->writeFloat("R"), *gg = img->writeFloat("G"), *b = img->writeFloat("B"),
          *a = img->writeFloat("A");
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const std::size_t i = std::size_t(y) * w + x;
            a[i] = 1;
            if (!std::isfinite(z[i])) {
                r[i] = gg[i] = b[i] = 0.02f;
                continue;
            }
            Vec3 o, d;
            s.camera.ray(x + 0.5, y + 0.5, o, d);
            const double light = 0.25 + 0.75 * std::abs(dot(normalize(d), Vec3{nx[i], ny[i], nz[i]}));
            const double t = std::clamp((f[i] - s.fieldMin) / (s.fieldMax - s.fieldMin), 0.0, 1.0);
            r[i] = float(light * (0.1 + 0.9 * t));
            gg[i] = float(light * (0.3 + 0.3 * t));
            b[i] = float(light * (0.9 - 0.8 * t));
        }
    writeImage(*img, path);
}

// Share of pixels with finite depth.
double coverage(const Buffer& g) {
    const float* z = g.requireFloat("Z");
    std::size_t n = 0;
    for (std::size_t i = 0; i < g.pixelCount(); ++i) n += std::isfinite(z[i]) ? 1 : 0;
    return double(n) / double(g.pixelCount());
}

TEST(StressRender, EveryFamilyCoversItsShareOfTheImage) {
    auto backend = embree();
    if (!backend) GTEST_SKIP() << "no embree capture backend in this build";
    const std::map<std::string, std::pair<double, double>> bounds = {
        {"grazing", {0.6, 0.8}}, {"border", {0.15, 0.6}}, {"gyroid", {0.35, 0.95}},
        {"shells", {0.4, 0.7}},  {"sheets", {0.5, 0.95}}};
    stress::Options o;
    o.width = 64;
    o.height = 64;
    for (const auto& family : stress::families()) {
        const auto s = stress::make(family, stress::knobValues(family).front(), o);
        const BufferPtr g = capture(*backend, s);
        const auto it = bounds.find(family);
        const auto [lo, hi] = it == bounds.end() ? std::pair{1.0, 1.0} : it->second;
        const double c = coverage(*g);
        EXPECT_GE(c, lo) << family;
        EXPECT_LE(c, hi) << family;
        // The colour field is present wherever there is geometry, in range.
        const float *z = g->requireFloat("Z"), *f = g->requireFloat(s.colorField);
        for (std::size_t i = 0; i < g->pixelCount(); ++i)
            if (std::isfinite(z[i])) {
                ASSERT_FALSE(std::isnan(f[i])) << family;
                ASSERT_GE(f[i], s.fieldMin - 1e-6) << family;
                ASSERT_LE(f[i], s.fieldMax + 1e-6) << family;
            }
    }
}

TEST(StressRender, DumpImagesWhenAsked) {
    const char* dir = std::getenv("DARKROOM_STRESS_DUMP");
    if (!dir) GTEST_SKIP() << "set DARKROOM_STRESS_DUMP=<folder> to write the scenes' images";
    auto backend = embree();
    if (!backend) GTEST_SKIP() << "no embree capture backend in this build";
    const char* sizeText = std::getenv("DARKROOM_STRESS_DUMP_SIZE");
    stress::Options o;
    o.width = o.height = sizeText ? std::atoi(sizeText) : 256;
    for (const auto& family : stress::families())
        for (const auto& s : stress::sweep(family, o)) {
            const BufferPtr g = capture(*backend, s);
            writeShaded(s, *g, std::string(dir) + "/" + s.name + ".png");
            std::size_t primitives = 0;
            for (const auto& obj : s.scene->objects) primitives += obj.primitiveCount();
            std::printf("%-22s coverage %.3f  primitives %zu\n", s.name.c_str(), coverage(*g), primitives);
        }
}

}  // namespace
