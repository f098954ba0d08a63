// The anti-aliasing reference (reference::supersampled) against what is known
// without it: at one sample per pixel it must shade exactly like the pass path
// (ColorMapping then Background on a captured G-buffer), and on a straight
// edge its 16 x 16 pixels must be the coverage-weighted blend of the two sides.
#include "aa_test_scenes.h"

#include <darkroom/accuracy/stress_scenes.h>

using namespace darkroom;
using namespace darkroom::aatest;

namespace {

constexpr int kSize = 64;

// Returns how many pixels are background (the caller checks that its scene
// shows both background and geometry somewhere).
std::size_t expectPassPathEqualsReference(const std::shared_ptr<const Scene>& scene, const Camera& cam,
                                   const std::string& field, double lo, double hi, const std::string& what) {
    auto backend = embree(scene);
    EXPECT_TRUE(backend) << "the embree backend is not built";
    if (!backend) return 0;
    auto ctx = context();
    const BufferPtr gbuffer = backend->render(cam, request(field), *ctx);
    const BufferPtr pass = colorize(gbuffer, field, lo, hi);
    const BufferPtr ref = reference::supersampled(*backend, cam, request(field), shader(field, lo, hi), 1, *ctx);
    EXPECT_EQ(ref->width(), cam.width);
    EXPECT_EQ(ref->height(), cam.height);
    if (ref->width() != cam.width || ref->height() != cam.height) return 0;
    EXPECT_LE(maxAbsDiff(*pass, *ref, {"R", "G", "B"}), 1e-4) << what;
    std::size_t background = 0;
    const float* z = gbuffer->requireFloat("Z");
    for (std::size_t i = 0; i < gbuffer->pixelCount(); ++i) background += std::isinf(z[i]) ? 1 : 0;
    return background;
}

}  // namespace

TEST(AaReference, OneSamplePerPixelShadesLikeThePassPath) {
    HalfPlane h;
    h.a = 1.0;
    h.b = 0.35;
    h.c = 0.05;
    h.gradient = 0.2f;
    const std::size_t background =
        expectPassPathEqualsReference(halfPlaneScene({h}), frontCamera(kSize), "value", -0.5, 1.5, "half-plane");
    // Both the miss (background) and the hit shading were compared.
    EXPECT_GT(background, std::size_t(kSize));
    EXPECT_LT(background, std::size_t(kSize * kSize - kSize));
    stress::Options so;
    so.width = so.height = kSize;
    for (const auto& [family, knob] : std::vector<std::pair<std::string, double>>{
             {"gyroid", stress::knobValues("gyroid").front()},
             {"streamlines", 1.0},
             {"particles", 2.0}}) {
        const stress::StressScene s = stress::make(family, knob, so);
        expectPassPathEqualsReference(s.scene, s.camera, s.colorField, s.fieldMin, s.fieldMax, s.name);
    }
}

// A slanted straight edge between a plane of one colour and the background:
// each reference pixel is (covered samples / 256) of the object's colour plus
// the rest of the background. Counting which of the 16 x 16 sub-pixel centres
// fall on the plane (from the camera's rays, not the ray tracer) must agree
// up to one sample; the exact area of the pixel square on the plane's side
// agrees up to the grid's discretisation (half a sample per grid column).
TEST(AaReference, SupersampledEdgeIsTheCoverageWeightedBlend) {
    HalfPlane h;
    h.a = 1.0;
    h.b = 0.35;  // not axis-aligned: the edge crosses pixels at every phase
    h.c = 0.05;
    h.depth = 4.0;
    h.value = 0.7f;
    const Camera cam = frontCamera(kSize);
    auto backend = embree(halfPlaneScene({h}));
    ASSERT_TRUE(backend);
    auto ctx = context();
    constexpr int n = 16;
    const BufferPtr ref = reference::supersampled(*backend, cam, request("value"), shader("value", 0.0, 1.0), n, *ctx);

    const Color object = loadColorMap("viridis").sample(h.value);
    const float bg[3] = {kBackground.r, kBackground.g, kBackground.b};
    const float fg[3] = {object.r, object.g, object.b};
    const char* channels[3] = {"R", "G", "B"};

    // The pixel -> plane map is affine for a fronto-parallel plane, so the
    // edge is a line alpha px + beta py = gamma in pixel coordinates.
    double x00, y00, x10, y10, x01, y01;
    onPlane(cam, 0, 0, h.depth, x00, y00);
    onPlane(cam, 1, 0, h.depth, x10, y10);
    onPlane(cam, 0, 1, h.depth, x01, y01);
    const double alpha = h.a * (x10 - x00) + h.b * (y10 - y00);
    const double beta = h.a * (x01 - x00) + h.b * (y01 - y00);
    const double gamma = h.c - h.a * x00 - h.b * y00;

    int partial = 0;
    for (int y = 0; y < kSize; ++y)
        for (int x = 0; x < kSize; ++x) {
            int covered = 0;
            for (int j = 0; j < n; ++j)
                for (int i = 0; i < n; ++i) {
                    double wx, wy;
                    onPlane(cam, x + (i + 0.5) / n, y + (j + 0.5) / n, h.depth, wx, wy);
                    covered += h.inside(wx, wy) ? 1 : 0;
                }
            const double counted = covered / double(n * n);
            const double area = squareCoverage(alpha, beta, gamma, x, y);
            if (area > 0 && area < 1) ++partial;
            for (int c = 0; c < 3; ++c) {
                const double got = at(*ref, channels[c], x, y);
                const double contrast = std::abs(fg[c] - bg[c]);
                const double byCount = counted * fg[c] + (1 - counted) * bg[c];
                const double byArea = area * fg[c] + (1 - area) * bg[c];
                ASSERT_NEAR(got, byCount, contrast / (n * n) + 1e-3) << channels[c] << " at " << x << "," << y;
                ASSERT_NEAR(got, byArea, contrast / (2.0 * n) + 1e-3) << channels[c] << " at " << x << "," << y;
            }
        }
    // About one partly covered pixel per row: the test looked at the edge.
    EXPECT_GE(partial, kSize);
}
