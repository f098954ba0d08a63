// Hits at exactly the same distance go to the lowest (object id, primitive
// id), whatever else the scene holds and whatever order Embree's BVH visits
// them in (src/nearest_hit_rule.h). Without the rule a capture's ids and
// normals on such pixels depend on unrelated geometry, and a scene split
// over MPI ranks cannot reproduce the single-process capture.
#include "render_helpers.h"
#include "scene_builders.h"

#include <gtest/gtest.h>

#include <cmath>

namespace darkroom::test {
namespace {

CaptureRequest ids() {
    CaptureRequest r;
    r.objectId = r.primitiveId = true;
    r.normals = true;
    return r;
}

const Camera kCamera = orthographicCamera({0, 0, 5}, {0, 0, 0}, 32, 32, 3.0);

std::vector<Vec3> grid(int n) {
    std::vector<Vec3> c;
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) c.push_back({-1.0 + 2.0 * i / (n - 1), -1.0 + 2.0 * j / (n - 1), 0.0});
    return c;
}

TEST(TieRule, CoincidentSpheresGoToTheLowerObjectWhicheverComesFirst) {
    const auto centers = grid(4);
    SceneObject a = makePoints(centers, 0.3), b = makePoints(centers, 0.3);
    // Object 1 holds the same spheres in reverse order, so that its ids differ.
    SceneObject reversed = makePoints(std::vector<Vec3>(centers.rbegin(), centers.rend()), 0.3);
    for (const auto& objects : {std::vector<SceneObject>{a, b}, std::vector<SceneObject>{a, reversed}}) {
        const BufferPtr g = capture(sceneOf(objects), kCamera, ids());
        const std::uint32_t* object = g->hostUInt("objectId");
        std::size_t hits = 0;
        for (std::size_t i = 0; i < g->pixelCount(); ++i) {
            if (object[i] == ~0u) continue;
            ++hits;
            ASSERT_EQ(object[i], 0u) << "pixel " << i;
        }
        EXPECT_GT(hits, g->pixelCount() / 4);
    }
}

TEST(TieRule, TheSameSphereTwiceInOneObjectGoesToTheLowerPrimitive) {
    // Spheres 0 and 2 coincide; 1 lies elsewhere.
    const SceneObject o = makePoints({{0.5, 0, 0}, {-1, -1, 0}, {0.5, 0, 0}}, 0.4);
    const BufferPtr g = capture(sceneOf({o}), kCamera, ids());
    const std::uint32_t* primitive = g->hostUInt("primitiveId");
    bool sawSphere0 = false;
    for (std::size_t i = 0; i < g->pixelCount(); ++i) {
        EXPECT_NE(primitive[i], 2u) << "pixel " << i;
        sawSphere0 |= primitive[i] == 0u;
    }
    EXPECT_TRUE(sawSphere0);
}

TEST(TieRule, WinnersDoNotDependOnOtherGeometry) {
    // Two identical quads (objects 0 and 1) tie everywhere; a cloud of
    // unrelated spheres far behind changes Embree's BVH but not the winners.
    const SceneObject quad = makeQuad({-1, -1, 0}, {2, 0, 0}, {0, 2, 0});
    std::vector<Vec3> far;
    for (int i = 0; i < 400; ++i) far.push_back({std::sin(i * 1.7) * 3, std::cos(i * 2.3) * 3, -4.0 - i * 0.01});
    const BufferPtr alone = capture(sceneOf({quad, quad}), kCamera, ids());
    const BufferPtr crowded = capture(sceneOf({quad, quad, makePoints(far, 0.05)}), kCamera, ids());
    const std::uint32_t* a = alone->hostUInt("objectId");
    const std::uint32_t* b = crowded->hostUInt("objectId");
    const std::uint32_t* pa = alone->hostUInt("primitiveId");
    const std::uint32_t* pb = crowded->hostUInt("primitiveId");
    std::size_t onQuad = 0;
    for (std::size_t i = 0; i < alone->pixelCount(); ++i) {
        if (a[i] == ~0u) continue;
        ++onQuad;
        EXPECT_EQ(a[i], 0u);
        EXPECT_EQ(b[i], 0u);
        EXPECT_EQ(pa[i], pb[i]);
    }
    EXPECT_GT(onQuad, 100u);
}

}  // namespace
}  // namespace darkroom::test
