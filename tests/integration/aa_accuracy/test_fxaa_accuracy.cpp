// FXAA against the 16 x 16 supersampled reference: on long straight edges
// (where it is meant to work) it must remove a measured share of the
// aliasing error; on the stress regimes where it is known to fail (stripes
// finer than two pixels, sub-pixel lines and points) it must still give
// finite colours in range.
#include "aa_test_scenes.h"

#include <darkroom/accuracy/stress_scenes.h>

#include <cstdio>

using namespace darkroom;
using namespace darkroom::aatest;

namespace {

constexpr int kSize = 96;

BufferPtr fxaa(const BufferPtr& image, int preset) {
    return runPass("FXAA", image, {{"preset", {Value(std::to_string(preset))}}});
}

}  // namespace

// Two planes at different depths with slanted edges (slopes 0.35 and -2.5)
// over the background: object-background and object-object edges. Measured
// at 96 px, RMSE vs 16 x 16: 1 spp 0.0106; FXAA 12 0.0049 (47 % of it left),
// 29 0.0050 (47 %), 39 0.0044 (42 %).
TEST(FxaaAccuracy, RemovesPartOfTheAliasingErrorOnStraightEdges) {
    HalfPlane back;
    back.a = 1.0;
    back.b = 0.35;
    back.c = 0.6;
    back.depth = 6.0;
    back.value = 0.85f;
    HalfPlane front;
    front.a = -1.0;
    front.b = -2.5;
    front.c = 0.3;
    front.depth = 3.0;
    front.value = 0.15f;
    const Camera cam = frontCamera(kSize);
    auto backend = embree(halfPlaneScene({back, front}));
    ASSERT_TRUE(backend);
    auto ctx = context();
    const BufferPtr image = colorize(backend->render(cam, request("value"), *ctx), "value", 0.0, 1.0);
    const BufferPtr ref = reference::supersampled(*backend, cam, request("value"), shader("value", 0.0, 1.0), 16, *ctx);

    const double aliased = rgbRmse(*image, *ref);
    ASSERT_GT(aliased, 0.005) << "the scene must have aliasing to remove";
    for (int preset : {12, 29, 39}) {
        const double filtered = rgbRmse(*fxaa(image, preset), *ref);
        std::printf("FXAA %d: RMSE %.5f -> %.5f (%.1f %%)\n", preset, aliased, filtered, 100.0 * filtered / aliased);
        // At least half of the measured improvement (53-58 %).
        EXPECT_LT(filtered, 0.75 * aliased) << "preset " << preset;
    }
}

TEST(FxaaAccuracy, KnownFailureRegimesStayFiniteAndInRange) {
    stress::Options so;
    so.width = so.height = 64;
    auto ctx = context();
    for (const auto& [family, knob] : std::vector<std::pair<std::string, double>>{
             {"stripes", 1.5}, {"streamlines", 0.25}, {"particles", 0.5}}) {
        const stress::StressScene s = stress::make(family, knob, so);
        auto backend = embree(s.scene);
        ASSERT_TRUE(backend);
        const BufferPtr image =
            colorize(backend->render(s.camera, request(s.colorField), *ctx), s.colorField, s.fieldMin, s.fieldMax);
        for (int preset : {10, 12, 39}) expectFiniteUnit(*fxaa(image, preset), s.name + " FXAA " + std::to_string(preset));
        const BufferPtr ref = reference::supersampled(*backend, s.camera, request(s.colorField),
                                                      shader(s.colorField, s.fieldMin, s.fieldMax), 4, *ctx);
        expectFiniteUnit(*ref, s.name + " 4x4 reference");
    }
}
