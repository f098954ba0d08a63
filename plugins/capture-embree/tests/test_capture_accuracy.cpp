// Geometric accuracy of the embree backend against analytic intersections:
// depth is planar view depth, world positions reconstruct from depth and the
// stored camera, and points / lines are true spheres and round tubes.
#include "render_helpers.h"
#include "scene_builders.h"

#include <cmath>
#include <limits>

namespace darkroom::test {
namespace {

constexpr float kInf = std::numeric_limits<float>::infinity();

// Relative error of the world position reconstructed from Z against the true
// hit point, relative to the hit's distance from the camera.
double reconstructionError(const Camera& cam, int x, int y, float z, double tTrue) {
    Vec3 o, d;
    cam.ray(x + 0.5, y + 0.5, o, d);
    const Vec3 truth = o + d * tTrue;
    const Vec3 rec = cam.worldPosition(x + 0.5, y + 0.5, z);
    return length(rec - truth) / std::max(1e-12, length(truth - cam.position));
}

TEST(CaptureAccuracy, PlaneAtKnownDepthGivesThatDepthAndInfinityElsewhere) {
    // Square of side 2 facing the camera at planar depth 5.
    auto scene = sceneOf({makeQuad({-1, -1, -5}, {2, 0, 0}, {0, 2, 0})});
    for (auto cam : {perspectiveCamera({0, 0, 0}, {0, 0, -1}, 64, 48, 40.0),
                     orthographicCamera({0, 0, 0}, {0, 0, -1}, 64, 48, 3.0)}) {
        auto buf = capture(scene, cam, {});
        ASSERT_EQ(buf->width(), 64);
        ASSERT_EQ(buf->height(), 48);
        ASSERT_TRUE(buf->metadata().camera.has_value());
        EXPECT_EQ(*buf->metadata().camera, cam);
        const float* z = buf->requireFloat("Z");
        int inside = 0, outside = 0;
        for (int y = 0; y < 48; ++y)
            for (int x = 0; x < 64; ++x) {
                // Where the pixel centre's ray meets the plane z = -5.
                const Vec3 p = cam.worldPosition(x + 0.5, y + 0.5, 5.0);
                const double margin = 1e-3;
                const float zz = z[y * 64 + x];
                if (std::abs(p.x) < 1 - margin && std::abs(p.y) < 1 - margin) {
                    // Embree's float t: within 2 ulp of 5.
                    EXPECT_NEAR(zz, 5.0f, 2 * 4.77e-7f) << toString(cam.projection) << " pixel " << x << "," << y;
                    ++inside;
                } else if (std::abs(p.x) > 1 + margin || std::abs(p.y) > 1 + margin) {
                    EXPECT_EQ(zz, kInf) << toString(cam.projection) << " pixel " << x << "," << y;
                    ++outside;
                }
            }
        EXPECT_GT(inside, 100) << toString(cam.projection);
        EXPECT_GT(outside, 100) << toString(cam.projection);
    }
}

TEST(CaptureAccuracy, WorldPositionsFromDepthMatchHitsOnATiltedPlane) {
    const Vec3 p0{0.3, -0.2, -4.0};
    const Vec3 e1 = Vec3{3.0, 0.0, 1.5}, e2 = Vec3{0.0, 3.0, -1.0};
    const Vec3 n = cross(e1, e2);
    auto scene = sceneOf({makeQuad(p0 - (e1 + e2) * 0.5, e1, e2)});
    for (auto cam : {perspectiveCamera({0.5, 0.4, 2.0}, p0, 80, 60, 35.0),
                     orthographicCamera({0.5, 0.4, 2.0}, p0, 80, 60, 2.5)}) {
        auto buf = capture(scene, cam, {});
        const float* z = buf->requireFloat("Z");
        int checked = 0;
        double worst = 0;
        for (int y = 0; y < 60; ++y)
            for (int x = 0; x < 80; ++x) {
                if (!std::isfinite(z[y * 80 + x])) continue;
                Vec3 o, d;
                cam.ray(x + 0.5, y + 0.5, o, d);
                auto t = intersectPlane(o, d, p0, n);
                ASSERT_TRUE(t.has_value());
                worst = std::max(worst, reconstructionError(cam, x, y, z[y * 80 + x], *t));
                ++checked;
            }
        EXPECT_GT(checked, 1000) << toString(cam.projection);
        EXPECT_LT(worst, 1e-4) << toString(cam.projection);
    }
}

TEST(CaptureAccuracy, WorldPositionsFromDepthMatchHitsOnASphereMesh) {
    const Vec3 c{0.2, 0.1, -3.0};
    SceneObject mesh = makeSphereMesh(c, 1.0, 24, 48);
    auto scene = sceneOf({mesh});
    CaptureRequest req;
    req.primitiveId = true;
    for (auto cam : {perspectiveCamera({1.0, 1.5, 1.0}, c, 96, 80, 50.0),
                     orthographicCamera({1.0, 1.5, 1.0}, c, 96, 80, 2.4)}) {
        auto buf = capture(scene, cam, req);
        const float* z = buf->requireFloat("Z");
        const std::uint32_t* prim = buf->requireUInt("primitiveId");
        int checked = 0;
        double worst = 0;
        for (int y = 0; y < 80; ++y)
            for (int x = 0; x < 96; ++x) {
                const std::size_t i = std::size_t(y) * 96 + x;
                if (!std::isfinite(z[i])) continue;
                ASSERT_LT(prim[i], mesh.indices.size() / 3);
                Vec3 o, d;
                cam.ray(x + 0.5, y + 0.5, o, d);
                auto t = intersectTrianglePlane(o, d, mesh, prim[i]);
                ASSERT_TRUE(t.has_value());
                worst = std::max(worst, reconstructionError(cam, x, y, z[i], *t));
                ++checked;
            }
        EXPECT_GT(checked, 1000) << toString(cam.projection);
        EXPECT_LT(worst, 1e-4) << toString(cam.projection);
    }
}

TEST(CaptureAccuracy, PointsAreTrueSpheres) {
    const std::vector<Vec3> centers{{0, 0, -6}, {1.2, 0.6, -7}, {-1.0, -0.5, -5}};
    const double r = 0.5;
    auto scene = sceneOf({makePoints(centers, r)});
    CaptureRequest req;
    req.normals = true;
    req.primitiveId = true;
    for (auto cam : {perspectiveCamera({0, 0, 0}, {0, 0, -1}, 128, 96, 35.0),
                     orthographicCamera({0, 0, 0}, {0, 0, -1}, 128, 96, 3.5)}) {
        auto buf = capture(scene, cam, req);
        const float* z = buf->requireFloat("Z");
        const float* nx = buf->requireFloat("N.x");
        const float* ny = buf->requireFloat("N.y");
        const float* nz = buf->requireFloat("N.z");
        int hits = 0;
        for (int y = 0; y < 96; ++y)
            for (int x = 0; x < 128; ++x) {
                const std::size_t i = std::size_t(y) * 128 + x;
                Vec3 o, d;
                cam.ray(x + 0.5, y + 0.5, o, d);
                // Nearest analytic hit, and how far the ray passes from each
                // silhouette (pixels grazing an outline are ambiguous in float).
                std::optional<double> best;
                std::size_t which = 0;
                bool nearSilhouette = false;
                for (std::size_t s = 0; s < centers.size(); ++s) {
                    const Vec3 dn = normalize(d);
                    const Vec3 oc = centers[s] - o;
                    const double dist = length(oc - dn * dot(oc, dn));
                    if (std::abs(dist - r) < 1e-3) nearSilhouette = true;
                    auto t = intersectSphere(o, d, centers[s], r);
                    if (t && (!best || *t < *best)) best = t, which = s;
                }
                if (nearSilhouette) continue;
                if (!best) {
                    EXPECT_EQ(z[i], kInf) << "pixel " << x << "," << y;
                    continue;
                }
                ++hits;
                EXPECT_NEAR(z[i], *best, 1e-6 * *best) << toString(cam.projection) << " pixel " << x << "," << y;
                EXPECT_EQ(buf->hostUInt("primitiveId")[i], which);
                const Vec3 nTrue = normalize(o + d * *best - centers[which]);
                EXPECT_NEAR(nx[i], nTrue.x, 1e-3);
                EXPECT_NEAR(ny[i], nTrue.y, 1e-3);
                EXPECT_NEAR(nz[i], nTrue.z, 1e-3);
            }
        EXPECT_GT(hits, 300) << toString(cam.projection);
    }
}

TEST(CaptureAccuracy, LinesAreRoundTubes) {
    // A tilted straight tube made of several segments: its side is an exact
    // cylinder (the joints are spheres of the same radius, inside it).
    const Vec3 a{-3.0, -0.8, -7.0}, b{3.0, 0.7, -6.0};
    const double r = 0.35;
    auto scene = sceneOf({makeTube(a, b, r, 6)});
    CaptureRequest req;
    req.scalars = {"s", "line"};
    for (auto cam : {perspectiveCamera({0, 1.0, 0}, {0, 0, -6.5}, 160, 120, 40.0),
                     orthographicCamera({0, 1.0, 0}, {0, 0, -6.5}, 160, 120, 3.0)}) {
        auto buf = capture(scene, cam, req);
        const float* z = buf->requireFloat("Z");
        const float* s = buf->requireFloat("s");
        const float* line = buf->requireFloat("line");
        int side = 0;
        for (int y = 0; y < 120; ++y)
            for (int x = 0; x < 160; ++x) {
                const std::size_t i = std::size_t(y) * 160 + x;
                Vec3 o, d;
                cam.ray(x + 0.5, y + 0.5, o, d);
                double axial = 0;
                auto t = intersectCylinder(o, d, a, b, r, &axial);
                if (!t || axial < 0.15 || axial > 0.85) continue;  // the tube's side, away from its ends
                // Skip grazing pixels near the outline, ambiguous in float.
                auto tInner = intersectCylinder(o, d, a, b, r * 0.98);
                if (!tInner) continue;
                ++side;
                EXPECT_NEAR(z[i], *t, 1e-5 * *t) << toString(cam.projection) << " pixel " << x << "," << y;
                // Arc-length field interpolated along the segment.
                EXPECT_NEAR(s[i], axial, 0.03) << "pixel " << x << "," << y;
                EXPECT_EQ(line[i], 7.0f);
            }
        EXPECT_GT(side, 300) << toString(cam.projection);
    }
}

}  // namespace
}  // namespace darkroom::test
