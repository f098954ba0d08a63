// Supersampling and the thin lens: their degenerate settings reproduce a
// plain render shaded per pixel.
#include "reference_fixture.h"

#include <darkroom/colormap.h>
#include <darkroom/error.h>
#include <darkroom/accuracy/reference.h>
#include <gmock/gmock.h>

#include <cmath>

namespace darkroom::test {
namespace {

const Color kBackground{0.2f, 0.3f, 0.4f, 1.0f};

std::shared_ptr<const Scene> tiltedQuads() {
    auto s = std::make_shared<Scene>();
    s->objects.push_back(quad({-1, -1, 0}, {2, 0, 0.5}, {0, 2, 0}));
    s->objects.push_back(quad({-0.3, -0.4, 0.8}, {0.5, 0, 0}, {0.1, 0.6, 0}));
    return s;
}

reference::SampleShader shader() {
    return reference::colorMapShader("u", loadColorMap("viridis"), 0.0, 1.0, kBackground);
}

CaptureRequest request() {
    CaptureRequest r;
    r.scalars = {"u"};
    return r;
}

// A quad whose field is constant, so its colour is the same everywhere.
SceneObject flatQuad(Vec3 c, Vec3 e1, Vec3 e2) {
    SceneObject q = quad(c, e1, e2);
    q.fields[0].values.assign(4, 0.8f);
    return q;
}

TEST(ReferenceShading, OneSamplePerPixelEqualsTheRenderShaded) {
    Embree e(tiltedQuads());
    const Camera cam = lookAt({0.2, 0.1, 4}, {0, 0, 0}, 40, 30);
    const BufferPtr ss = reference::supersampled(*e.backend, cam, request(), shader(), 1, *e.ctx);
    const BufferPtr gb = e.backend->render(cam, request(), *e.ctx);
    const auto shade = shader();
    std::size_t background = 0;
    for (std::size_t i = 0; i < gb->pixelCount(); ++i) {
        float c[4];
        shade(*gb, i, c);
        background += std::isinf(gb->requireFloat("Z")[i]);
        EXPECT_NEAR(ss->requireFloat("R")[i], c[0], 1e-5f) << i;
        EXPECT_NEAR(ss->requireFloat("G")[i], c[1], 1e-5f) << i;
        EXPECT_NEAR(ss->requireFloat("B")[i], c[2], 1e-5f) << i;
        EXPECT_EQ(ss->requireFloat("A")[i], 1.0f);
    }
    EXPECT_GT(background, 0u);
    EXPECT_LT(background, gb->pixelCount());
}

TEST(ReferenceShading, SupersamplingAveragesSubPixelSamples) {
    // A vertical boundary between the quad and the background exactly at a
    // third of a pixel: 3 x 3 samples give coverage 1/3 in that column.
    auto s = std::make_shared<Scene>();
    s->objects.push_back(flatQuad({-10, -10, 0}, {10, 0, 0}, {0, 20, 0}));  // x in [-10, 0]
    Embree e(s);
    Camera cam;
    cam.projection = Camera::Projection::Orthographic;
    cam.position = {0, 0, 5};
    cam.forward = {0, 0, -1};
    cam.viewHeight = 9.0;  // 9 px high: 1 world unit per pixel
    cam.width = cam.height = 9;
    // Shift the view so x = 0 falls a third of the way into column 4.
    cam.position.x = 0.5 - 1.0 / 3.0;
    const BufferPtr ss = reference::supersampled(*e.backend, cam, request(), shader(), 3, *e.ctx);
    float quadColour[4];
    {
        const BufferPtr gb = e.backend->render(cam, request(), *e.ctx);
        shader()(*gb, 0, quadColour);  // column 0 is on the quad
    }
    const float* r = ss->requireFloat("R");
    for (int y = 0; y < 9; ++y) {
        EXPECT_NEAR(r[y * 9 + 4], (1.0f / 3.0f) * quadColour[0] + (2.0f / 3.0f) * kBackground.r, 0.01f) << y;
        EXPECT_NEAR(r[y * 9 + 6], kBackground.r, 1e-6f);
    }
}

TEST(ReferenceShading, PinholeThinLensEqualsOneSamplePerPixel) {
    Embree e(tiltedQuads());
    const Camera cam = lookAt({0.2, 0.1, 4}, {0, 0, 0}, 32, 24);
    reference::ThinLens lens;
    lens.aperture = 0.0;
    lens.focalDistance = 4.0;
    lens.lensSamples = 3;
    lens.pixelJitter = false;
    const BufferPtr tl = reference::thinLens(*e.backend, cam, request(), shader(), lens, *e.ctx);
    const BufferPtr ss = reference::supersampled(*e.backend, cam, request(), shader(), 1, *e.ctx);
    for (const char* c : {"R", "G", "B", "A"})
        for (std::size_t i = 0; i < ss->pixelCount(); ++i)
            ASSERT_NEAR(tl->requireFloat(c)[i], ss->requireFloat(c)[i], 1e-4f) << c << " " << i;
}

TEST(ReferenceShading, DefocusBlursAnEdgeByTheCircleOfConfusion) {
    // A vertical edge of a plane at depth 4 with the lens focused at 2: a
    // point spreads over a disc of diameter c = A |z - zf| / z on the focal
    // plane, i.e. c / (pixel size at zf) pixels. The derivative of the edge
    // profile is the disc's chord-length distribution, whose standard
    // deviation is c / 4; pixel jitter adds a 1 px box (variance 1/12).
    auto s = std::make_shared<Scene>();
    s->objects.push_back(flatQuad({-10, -10, 0}, {10, 0, 0}, {0, 20, 0}));
    Embree e(s);
    const Camera cam = lookAt({0, 0, 4}, {0, 0, 0}, 64, 16, 10.0);
    reference::ThinLens lens;
    lens.aperture = 0.4;
    lens.focalDistance = 2.0;
    lens.lensSamples = 1024;
    const BufferPtr tl = reference::thinLens(*e.backend, cam, request(), shader(), lens, *e.ctx);
    const double cocPx = lens.aperture * (4.0 - 2.0) / 4.0 / cam.pixelSizeAt(2.0);
    ASSERT_GT(cocPx, 6.0);
    float quadColour[4];
    const BufferPtr gb = e.backend->render(cam, request(), *e.ctx);
    shader()(*gb, 8 * 64 + 2, quadColour);
    const float* r = tl->requireFloat("R");
    const float span = quadColour[0] - kBackground.r;
    std::vector<double> t(64);
    for (int x = 0; x < 64; ++x) t[x] = (r[8 * 64 + x] - kBackground.r) / span;
    ASSERT_NEAR(t[2], 1.0, 1e-3);
    ASSERT_NEAR(t[61], 0.0, 1e-3);
    double mass = 0, mean = 0, second = 0;
    for (int x = 1; x < 64; ++x) {
        const double w = t[x - 1] - t[x], pos = x;  // the boundary between columns x-1 and x
        mass += w;
        mean += w * pos;
        second += w * pos * pos;
    }
    mean /= mass;
    const double variance = second / mass - mean * mean;
    EXPECT_NEAR(mass, 1.0, 0.01);
    EXPECT_NEAR(4.0 * std::sqrt(variance - 1.0 / 12.0), cocPx, 0.1 * cocPx) << "CoC " << cocPx << " px";
}

TEST(ReferenceShading, BadInputIsAnError) {
    Embree e(tiltedQuads());
    Camera cam = lookAt({0.2, 0.1, 4}, {0, 0, 0}, 8, 8);
    EXPECT_THAT([&] { reference::supersampled(*e.backend, cam, request(), shader(), 0, *e.ctx); },
                ::testing::ThrowsMessage<Error>(::testing::HasSubstr("1 to 64")));
    reference::ThinLens lens;
    lens.focalDistance = 0;
    EXPECT_THAT([&] { reference::thinLens(*e.backend, cam, request(), shader(), lens, *e.ctx); },
                ::testing::ThrowsMessage<Error>(::testing::HasSubstr("focal distance")));
    cam.projection = Camera::Projection::Orthographic;
    lens.focalDistance = 1;
    EXPECT_THAT([&] { reference::thinLens(*e.backend, cam, request(), shader(), lens, *e.ctx); },
                ::testing::ThrowsMessage<Error>(::testing::HasSubstr("orthographic")));
    EXPECT_THAT([] { reference::colorMapShader("u", loadColorMap("viridis"), 1.0, 1.0, kBackground); },
                ::testing::ThrowsMessage<Error>(::testing::HasSubstr("range")));
}

}  // namespace
}  // namespace darkroom::test
