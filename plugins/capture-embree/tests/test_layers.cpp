// Layered captures (CaptureRequest::layers, darkroom/layers.h): the K
// nearest surface crossings per pixel. Known answers: parallel quads at
// known depths, the front and back of a sphere; layer 0 is the one-layer
// capture bit for bit; both ways of finding the crossings (one traversal
// with a filter, one traversal per layer) give the same buffer.
#include "embree_backend.h"
#include "embree_scene.h"
#include "render_helpers.h"
#include "scene_builders.h"

#include <darkroom/layers.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <utility>

namespace darkroom::test {
namespace {

BufferPtr captureWith(std::shared_ptr<const Scene> scene, const Camera& camera, const CaptureRequest& request,
                      embree::LayerMethod method, int threads = 1) {
    const embree::SceneBvh bvh(std::make_shared<embree::Device>(), std::move(scene));
    FilterRunOptions options;
    options.threads = threads;
    auto ctx = makeStandaloneContext(options, "layers-test");
    return embree::renderGBuffer(bvh, camera, request, *ctx, method);
}

CaptureRequest everything(int layers) {
    CaptureRequest r;
    r.scalars = {"X"};
    r.normals = r.objectId = r.primitiveId = true;
    r.layers = layers;
    return r;
}

// Channel `name` of a and b hold the same bytes.
bool samePlane(const Buffer& a, const std::string& name, const Buffer& b) {
    const void* pa = a.channelType(name) == ChannelType::UInt32 ? static_cast<const void*>(a.hostUInt(name))
                                                                 : static_cast<const void*>(a.hostFloat(name));
    const void* pb = b.channelType(name) == ChannelType::UInt32 ? static_cast<const void*>(b.hostUInt(name))
                                                                 : static_cast<const void*>(b.hostFloat(name));
    return pa && pb && a.pixelCount() == b.pixelCount() && std::memcmp(pa, pb, 4 * a.pixelCount()) == 0;
}

// Three 4x4 quads facing +z at z = 0, -1, -2.5 seen from z = 5.
std::shared_ptr<const Scene> threeQuads() {
    std::vector<SceneObject> quads;
    for (double z : {0.0, -1.0, -2.5}) quads.push_back(makeQuad({-2, -2, z}, {4, 0, 0}, {0, 4, 0}));
    return sceneOf(std::move(quads));
}

TEST(Layers, ChannelsAreNamedAsLayersHSays) {
    const Camera cam = orthographicCamera({0, 0, 5}, {0, 0, 0}, 8, 8, 2.0);
    const BufferPtr g = captureWith(threeQuads(), cam, everything(3), embree::LayerMethod::Filter);
    EXPECT_EQ(layers::count(*g), 3);
    for (const char* n : {"Z", "X", "N.x", "N.y", "N.z", "objectId", "primitiveId"})
        for (int k = 0; k < 3; ++k) EXPECT_TRUE(g->hasChannel(layers::channel(n, k))) << layers::channel(n, k);
    EXPECT_FALSE(g->hasChannel("layer3.Z"));
}

TEST(Layers, ParallelQuadsGiveTheirDepthsFrontToBackAndMissingLayersAreEmpty) {
    const Camera cam = orthographicCamera({0, 0, 5}, {0, 0, 0}, 8, 8, 2.0);
    for (const auto method : {embree::LayerMethod::Filter, embree::LayerMethod::Repeat}) {
        const BufferPtr g = captureWith(threeQuads(), cam, everything(4), method);
        const float* z[4] = {g->hostFloat("Z"), g->hostFloat("layer1.Z"), g->hostFloat("layer2.Z"),
                             g->hostFloat("layer3.Z")};
        const std::uint32_t* id[4] = {g->hostUInt("objectId"), g->hostUInt("layer1.objectId"),
                                      g->hostUInt("layer2.objectId"), g->hostUInt("layer3.objectId")};
        for (std::size_t i = 0; i < g->pixelCount(); ++i) {
            EXPECT_FLOAT_EQ(z[0][i], 5.0f);
            EXPECT_FLOAT_EQ(z[1][i], 6.0f);
            EXPECT_FLOAT_EQ(z[2][i], 7.5f);
            EXPECT_EQ(z[3][i], std::numeric_limits<float>::infinity());
            for (std::uint32_t k = 0; k < 3; ++k) EXPECT_EQ(id[k][i], k);
            EXPECT_EQ(id[3][i], 0xFFFFFFFFu);
            EXPECT_TRUE(std::isnan(g->hostFloat("layer3.N.x")[i]));
            EXPECT_TRUE(std::isnan(g->hostFloat("layer3.X")[i]));
            // Every layer's normal faces the camera.
            EXPECT_FLOAT_EQ(g->hostFloat("layer2.N.z")[i], 1.0f);
        }
    }
}

// A closed surface: each ray through the sphere crosses its front and its
// back. The centre ray passes exactly through the UV sphere's pole, where
// 24 triangles meet: that must be one crossing, not 24.
TEST(Layers, ASphereGivesItsFrontAndBackEvenThroughAVertexManyTrianglesShare) {
    const Vec3 centre{0, 0, 0};
    const double r = 1.0;
    SceneObject sphere = makeSphereMesh(centre, r, 32, 24);
    for (std::size_t i = 0; i < sphere.vertices.size(); i += 4) std::swap(sphere.vertices[i + 1], sphere.vertices[i + 2]);
    const auto scene = sceneOf({sphere});                                     // poles on the z axis now
    const Camera cam = orthographicCamera({0, 0, 5}, centre, 33, 33, 2.4);  // looks down the pole axis
    for (const auto method : {embree::LayerMethod::Filter, embree::LayerMethod::Repeat}) {
        const BufferPtr g = captureWith(scene, cam, everything(3), method);
        const std::size_t mid = 16 * 33 + 16;
        EXPECT_FLOAT_EQ(g->hostFloat("Z")[mid], 4.0f);
        EXPECT_FLOAT_EQ(g->hostFloat("layer1.Z")[mid], 6.0f);
        EXPECT_EQ(g->hostFloat("layer2.Z")[mid], std::numeric_limits<float>::infinity());
        // Away from the pole, front and back against the tessellated sphere
        // (within its sagitta) and nothing behind.
        const float* z0 = g->hostFloat("Z");
        const float* z1 = g->hostFloat("layer1.Z");
        const float* z2 = g->hostFloat("layer2.Z");
        int both = 0;
        for (std::size_t i = 0; i < g->pixelCount(); ++i) {
            EXPECT_EQ(z2[i], std::numeric_limits<float>::infinity()) << "pixel " << i;
            if (!std::isfinite(z0[i])) {
                EXPECT_EQ(z1[i], std::numeric_limits<float>::infinity()) << "pixel " << i;
                continue;
            }
            ASSERT_TRUE(std::isfinite(z1[i])) << "pixel " << i << " has a front but no back";
            EXPECT_GT(z1[i], z0[i]);
            // Symmetric about the centre plane z = 0, which lies at depth 5.
            EXPECT_NEAR(0.5 * (z0[i] + z1[i]), 5.0, 0.02) << "pixel " << i;
            ++both;
        }
        EXPECT_GT(both, 33 * 33 / 2);
    }
}

TEST(Layers, LayerZeroIsTheOneLayerCaptureBitForBit) {
    const auto scene = sceneOf({makeSphereMesh({0, 0, 0}, 1.0, 20, 17), makeQuad({-2, -2, -0.5}, {4, 0, 0}, {0, 4, 0}),
                                makePoints({{0.3, 0.2, 1.2}, {-0.5, 0.1, 0.8}}, 0.25)});
    const Camera cam = perspectiveCamera({0.3, 0.4, 4}, {0, 0, 0}, 45, 37);
    const BufferPtr one = capture(scene, cam, everything(1));
    for (const auto method : {embree::LayerMethod::Filter, embree::LayerMethod::Repeat}) {
        const BufferPtr many = captureWith(scene, cam, everything(4), method, 3);
        for (const auto& ch : one->channels())
            EXPECT_TRUE(samePlane(*one, ch.name, *many)) << ch.name;
    }
}

TEST(Layers, BothMethodsGiveTheSameLayers) {
    const auto scene = sceneOf({makeSphereMesh({0, 0, 0}, 1.0, 20, 17), makeSphereMesh({0.2, 0, 0}, 0.5, 11, 9),
                                makeQuad({-2, -2, -0.5}, {4, 0, 0}, {0, 4, 0})});
    const Camera cam = perspectiveCamera({0.3, 0.4, 4}, {0, 0, 0}, 40, 40);
    const BufferPtr filter = captureWith(scene, cam, everything(6), embree::LayerMethod::Filter);
    const BufferPtr repeat = captureWith(scene, cam, everything(6), embree::LayerMethod::Repeat);
    int deep = 0;
    for (const auto& ch : filter->channels()) EXPECT_TRUE(samePlane(*filter, ch.name, *repeat)) << ch.name;
    for (std::size_t i = 0; i < filter->pixelCount(); ++i) deep += std::isfinite(filter->hostFloat("layer4.Z")[i]);
    EXPECT_GT(deep, 0) << "some rays cross all five surfaces";
}

TEST(Layers, OutOfRangeCountsAndClashingNamesAreRefused) {
    const Camera cam = orthographicCamera({0, 0, 5}, {0, 0, 0}, 4, 4, 2.0);
    for (int bad : {0, 17}) {
        CaptureRequest r;
        r.layers = bad;
        EXPECT_THROW(capture(threeQuads(), cam, r), Error) << bad;
    }
    CaptureRequest clash;
    clash.layers = 2;
    clash.scalars = {"layer1.X"};
    EXPECT_THROW(capture(threeQuads(), cam, clash), Error);
}

}  // namespace
}  // namespace darkroom::test
