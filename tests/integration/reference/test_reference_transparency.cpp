// The transparency reference (issue 30): every crossing in depth order,
// composited front to back. Known answers: two translucent quads of known
// colours over a background; the crossing count of the nested shells and the
// sheet stack equals their knob's depth complexity; opaque crossings give the
// nearest hit's colour.
#include "reference_fixture.h"

#include <darkroom/accuracy/reference.h>
#include <darkroom/accuracy/stress_scenes.h>

#include <gtest/gtest.h>

using namespace darkroom;

namespace {

// Colour by field `u` (a quad's own constant here) at opacity `alpha`.
reference::SampleShader byU(float alpha) {
    return [alpha](const Buffer& s, std::size_t i, float rgba[4]) {
        const float u = s.requireFloat("u")[i];
        rgba[0] = u, rgba[1] = 1 - u, rgba[2] = 0.25f, rgba[3] = alpha;
    };
}

SceneObject constantQuad(Vec3 c, Vec3 e1, Vec3 e2, float u) {
    SceneObject q = test::quad(c, e1, e2);
    q.fields[0].values.assign(4, u);
    return q;
}

}  // namespace

TEST(ReferenceTransparency, TwoTranslucentQuadsGiveTheAnalyticColour) {
    auto scene = std::make_shared<Scene>();
    scene->objects.push_back(constantQuad({-1, -1, 0}, {2, 0, 0}, {0, 2, 0}, 0.9f));   // near
    scene->objects.push_back(constantQuad({-1, -1, -1}, {2, 0, 0}, {0, 2, 0}, 0.2f));  // far
    test::Embree e(scene);
    const Camera cam = test::lookAt({0, 0, 5}, {0, 0, 0}, 16, 16, 10.0);  // both quads fill the view
    CaptureRequest request;
    request.scalars = {"u"};
    const Color bg{0.1f, 0.2f, 0.3f, 1.0f};
    const BufferPtr out = reference::transparent(*e.backend, cam, request, byU(0.4f), bg, 16, *e.ctx);
    const float near[3] = {0.9f, 0.1f, 0.25f}, far[3] = {0.2f, 0.8f, 0.25f}, back[3] = {bg.r, bg.g, bg.b};
    const char* names[3] = {"R", "G", "B"};
    for (std::size_t i = 0; i < out->pixelCount(); ++i) {
        ASSERT_EQ(out->requireFloat("crossings")[i], 2.0f) << i;
        for (int k = 0; k < 3; ++k) {
            const float want = 0.4f * near[k] + 0.6f * 0.4f * far[k] + 0.6f * 0.6f * back[k];
            EXPECT_NEAR(out->requireFloat(names[k])[i], want, 1e-6f) << i;
        }
    }
    // Opaque crossings: the nearest quad's colour.
    const BufferPtr opaque = reference::transparent(*e.backend, cam, request, byU(1.0f), bg, 16, *e.ctx);
    EXPECT_NEAR(opaque->requireFloat("R")[0], 0.9f, 1e-6f);
    EXPECT_EQ(opaque->requireFloat("crossings")[0], 1.0f);  // stopped: nothing behind can show
}

TEST(ReferenceTransparency, DepthComplexityOfTheLayerScenesIsTheirKnob) {
    // A clear shader (opacity 0) goes through everything: the count is the
    // number of surfaces the centre ray crosses.
    const reference::SampleShader clear = [](const Buffer&, std::size_t, float rgba[4]) {
        rgba[0] = rgba[1] = rgba[2] = 0, rgba[3] = 0;
    };
    for (const auto& [family, knob, want] :
         std::vector<std::tuple<std::string, double, float>>{{"shells", 1, 2}, {"shells", 3, 6}, {"sheets", 8, 8}}) {
        const stress::StressScene s = stress::make(family, knob, {33, 33});
        test::Embree e(s.scene);
        CaptureRequest request;
        const BufferPtr out = reference::transparent(*e.backend, s.camera, request, clear, {0, 0, 0, 1}, 64, *e.ctx);
        EXPECT_EQ(out->requireFloat("crossings")[16 * 33 + 16], want) << s.name;
    }
}
