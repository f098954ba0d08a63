// The embree backend's channels: scalars (point data interpolated, cell data
// per primitive, NaN where missing), normals, ids, determinism across thread
// counts, and the edge cases (empty scene, 1x1, bad input).
#include "render_helpers.h"
#include "scene_builders.h"

#include <darkroom/error.h>

#include <cmath>
#include <cstring>
#include <limits>

namespace darkroom::test {
namespace {

constexpr std::uint32_t kNoId = 0xFFFFFFFFu;

TEST(CaptureEmbree, IsRegistered) {
    const auto* info = pluginRegistry().backend("embree");
    ASSERT_NE(info, nullptr);
    EXPECT_FALSE(info->info.doc.empty());
}

TEST(CaptureEmbree, ChannelsAreThoseRequestedInOrder) {
    CaptureRequest req;
    req.scalars = {"X", "C"};
    req.normals = req.objectId = req.primitiveId = true;
    auto buf = capture(sceneOf({makeQuad({-1, -1, -5}, {2, 0, 0}, {0, 2, 0})}),
                       perspectiveCamera({0, 0, 0}, {0, 0, -1}, 8, 8), req);
    const std::vector<std::string> expected{"Z", "X", "C", "N.x", "N.y", "N.z", "objectId", "primitiveId"};
    EXPECT_EQ(buf->channelNames(), expected);
    EXPECT_EQ(buf->channelType("objectId"), ChannelType::UInt32);
    EXPECT_EQ(buf->channelType("N.y"), ChannelType::Float32);

    auto depthOnly = capture(sceneOf({makeQuad({-1, -1, -5}, {2, 0, 0}, {0, 2, 0})}),
                             perspectiveCamera({0, 0, 0}, {0, 0, -1}, 8, 8), {});
    EXPECT_EQ(depthOnly->channelNames(), std::vector<std::string>{"Z"});
}

TEST(CaptureEmbree, PointDataInterpolatesLinearlyAcrossTriangles) {
    // Field X equals the vertex x coordinate, so at every hit it must equal the
    // x of the world position reconstructed from depth.
    const Vec3 c{0, 0, -4};
    auto scene = sceneOf({makeQuad({-2, -1.5, -5}, {4, 0, 1.5}, {0, 3, 0}), makeSphereMesh(c, 0.8, 16, 32)});
    CaptureRequest req;
    req.scalars = {"X"};
    const Camera cam = perspectiveCamera({0.5, 0.5, 1}, c, 96, 72, 45.0);
    auto buf = capture(scene, cam, req);
    const float* z = buf->requireFloat("Z");
    const float* x = buf->requireFloat("X");
    int hits = 0;
    for (int py = 0; py < 72; ++py)
        for (int px = 0; px < 96; ++px) {
            const std::size_t i = std::size_t(py) * 96 + px;
            if (!std::isfinite(z[i])) {
                EXPECT_TRUE(std::isnan(x[i])) << "background must be NaN";
                continue;
            }
            ++hits;
            EXPECT_NEAR(x[i], cam.worldPosition(px + 0.5, py + 0.5, z[i]).x, 1e-4) << px << "," << py;
        }
    EXPECT_GT(hits, 2000);
}

TEST(CaptureEmbree, CellDataIsConstantPerPrimitiveAndMissingFieldsAreNaN) {
    SceneObject quad = makeQuad({-2, -1, -5}, {2, 0, 0}, {0, 2, 0});  // left half, has C
    SceneObject other = makeQuad({0, -1, -5}, {2, 0, 0}, {0, 2, 0});  // right half, no C
    other.fields.clear();
    CaptureRequest req;
    req.scalars = {"C", "X"};
    req.objectId = true;
    req.primitiveId = true;
    auto buf = capture(sceneOf({quad, other}), orthographicCamera({0, 0, 0}, {0, 0, -1}, 64, 32, 2.5), req);
    const float* cField = buf->requireFloat("C");
    const float* xField = buf->requireFloat("X");
    const std::uint32_t* obj = buf->requireUInt("objectId");
    const std::uint32_t* prim = buf->requireUInt("primitiveId");
    int left = 0, right = 0;
    for (std::size_t i = 0; i < buf->pixelCount(); ++i) {
        if (obj[i] == 0) {
            ASSERT_LT(prim[i], 2u);
            EXPECT_EQ(cField[i], prim[i] == 0 ? 10.0f : 20.0f);
            EXPECT_FALSE(std::isnan(xField[i]));
            ++left;
        } else if (obj[i] == 1) {
            EXPECT_TRUE(std::isnan(cField[i]));
            EXPECT_TRUE(std::isnan(xField[i]));
            ++right;
        } else {
            EXPECT_EQ(obj[i], kNoId);
            EXPECT_EQ(prim[i], kNoId);
            EXPECT_TRUE(std::isnan(cField[i]));
        }
    }
    EXPECT_GT(left, 300);
    EXPECT_GT(right, 300);
}

TEST(CaptureEmbree, IdsNameTheObjectAndPrimitiveHit) {
    // Left quad = object 0, right quad = object 1; in each quad triangle 0 is
    // below the diagonal from its lower-left to its upper-right corner.
    auto scene = sceneOf({makeQuad({-2, -1, -5}, {2, 0, 0}, {0, 2, 0}), makeQuad({0, -1, -5}, {2, 0, 0}, {0, 2, 0})});
    CaptureRequest req;
    req.objectId = req.primitiveId = true;
    const Camera cam = orthographicCamera({0, 0, 0}, {0, 0, -1}, 100, 50, 2.5);
    auto buf = capture(scene, cam, req);
    const std::uint32_t* obj = buf->requireUInt("objectId");
    const std::uint32_t* prim = buf->requireUInt("primitiveId");
    int checked = 0;
    for (int y = 0; y < 50; ++y)
        for (int x = 0; x < 100; ++x) {
            const Vec3 p = cam.worldPosition(x + 0.5, y + 0.5, 5.0);
            const std::size_t i = std::size_t(y) * 100 + x;
            if (std::abs(p.y) > 1.01 || std::abs(p.x) > 2.01) {
                EXPECT_EQ(obj[i], kNoId);
                EXPECT_EQ(prim[i], kNoId);
                continue;
            }
            const double lx = p.x < 0 ? p.x + 2 : p.x;  // position inside the quad, 0..2
            const double ly = p.y + 1;
            if (std::abs(p.y) > 0.99 || std::abs(p.x) < 0.01 || std::abs(p.x) > 1.99 || std::abs(lx - ly) < 0.01)
                continue;  // on an edge
            EXPECT_EQ(obj[i], p.x < 0 ? 0u : 1u) << x << "," << y;
            EXPECT_EQ(prim[i], lx > ly ? 0u : 1u) << x << "," << y;
            ++checked;
        }
    EXPECT_GT(checked, 2000);
}

TEST(CaptureEmbree, NormalsAreUnitWorldSpaceAndFaceTheCamera) {
    // Both windings of the same quad: whichever way Embree's geometric normal
    // points, the output faces the camera.
    for (auto quad : {makeQuad({-1, -1, -5}, {0, 2, 0}, {2, 0, 0}), makeQuad({-1, -1, -5}, {2, 0, 0}, {0, 2, 0})}) {
        CaptureRequest req;
        req.normals = true;
        auto buf = capture(sceneOf({quad}), perspectiveCamera({0, 0, 0}, {0, 0, -1}, 32, 32, 30.0), req);
        const float* z = buf->requireFloat("Z");
        int hits = 0;
        for (std::size_t i = 0; i < buf->pixelCount(); ++i) {
            if (!std::isfinite(z[i])) {
                EXPECT_TRUE(std::isnan(buf->hostFloat("N.x")[i]));
                continue;
            }
            ++hits;
            EXPECT_FLOAT_EQ(buf->hostFloat("N.x")[i], 0.0f);
            EXPECT_FLOAT_EQ(buf->hostFloat("N.y")[i], 0.0f);
            EXPECT_FLOAT_EQ(buf->hostFloat("N.z")[i], 1.0f);
        }
        EXPECT_GT(hits, 100);
    }
}

std::shared_ptr<const Scene> mixedScene() {
    std::vector<Vec3> centers;
    for (int i = 0; i < 40; ++i) centers.push_back({-2 + 0.1 * i, std::sin(i * 0.7), -6 + std::cos(i * 1.3)});
    return sceneOf({makeSphereMesh({0.5, 0, -5}, 1.2, 20, 40), makePoints(centers, 0.15),
                    makeTube({-3, -1, -7}, {3, 1, -4}, 0.2, 9), makeQuad({-4, -3, -9}, {8, 0, 0}, {0, 6, 0})});
}

TEST(CaptureEmbree, OutputIsIdenticalForOneAndManyThreads) {
    CaptureRequest req;
    req.scalars = {"X", "pointValue", "s", "line", "C"};
    req.normals = req.objectId = req.primitiveId = true;
    // 203x117: not a multiple of the tile or packet size, so edge tiles run too.
    const Camera cam = perspectiveCamera({0.3, 0.5, 2}, {0, 0, -5}, 203, 117, 50.0);
    auto one = capture(mixedScene(), cam, req, 1);
    auto many = capture(mixedScene(), cam, req, 4);
    EXPECT_TRUE(identical(*one, *many));
    // Something was actually drawn of every kind.
    const std::uint32_t* obj = one->requireUInt("objectId");
    std::vector<int> seen(4, 0);
    for (std::size_t i = 0; i < one->pixelCount(); ++i)
        if (obj[i] < 4) ++seen[obj[i]];
    for (int k = 0; k < 4; ++k) EXPECT_GT(seen[k], 10) << "object " << k;
}

TEST(CaptureEmbree, EmptySceneIsAllBackground) {
    CaptureRequest req;
    req.scalars = {"X"};
    req.normals = req.objectId = true;
    for (auto scene : {sceneOf({}), std::shared_ptr<const Scene>()}) {
        auto buf = capture(scene, perspectiveCamera({0, 0, 0}, {0, 0, -1}, 17, 9), req);
        for (std::size_t i = 0; i < buf->pixelCount(); ++i) {
            EXPECT_EQ(buf->hostFloat("Z")[i], std::numeric_limits<float>::infinity());
            EXPECT_TRUE(std::isnan(buf->hostFloat("X")[i]));
            EXPECT_TRUE(std::isnan(buf->hostFloat("N.z")[i]));
            EXPECT_EQ(buf->hostUInt("objectId")[i], kNoId);
        }
    }
}

TEST(CaptureEmbree, OnePixelImage) {
    auto scene = sceneOf({makeQuad({-1, -1, -5}, {2, 0, 0}, {0, 2, 0})});
    auto buf = capture(scene, perspectiveCamera({0, 0, 0}, {0, 0, -1}, 1, 1), {});
    ASSERT_EQ(buf->pixelCount(), 1u);
    EXPECT_NEAR(buf->hostFloat("Z")[0], 5.0f, 1e-5f);
    auto miss = capture(scene, perspectiveCamera({0, 0, 0}, {0, 0, 1}, 1, 1), {});
    EXPECT_EQ(miss->hostFloat("Z")[0], std::numeric_limits<float>::infinity());
}

TEST(CaptureEmbree, ObjectsWithoutPrimitivesAreSkipped) {
    SceneObject empty;
    empty.name = "nothing";
    auto buf = capture(sceneOf({empty, makeQuad({-1, -1, -5}, {2, 0, 0}, {0, 2, 0})}),
                       perspectiveCamera({0, 0, 0}, {0, 0, -1}, 4, 4),
                       CaptureRequest{{}, false, true, false});
    // Geometry IDs stay object indices even when an object before it is empty.
    EXPECT_EQ(buf->hostUInt("objectId")[5], 1u);
}

TEST(CaptureEmbree, BadInputGivesClearErrors) {
    auto backend = embreeBackend();
    auto ctx = makeStandaloneContext({});
    const Camera cam = perspectiveCamera({0, 0, 0}, {0, 0, -1}, 4, 4);
    try {
        backend->render(cam, {}, *ctx);
        FAIL() << "render before setScene must throw";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("setScene"), std::string::npos) << e.what();
    }

    SceneObject bad = makeQuad({-1, -1, -5}, {2, 0, 0}, {0, 2, 0});
    bad.name = "broken";
    bad.indices[4] = 99;
    try {
        backend->setScene(sceneOf({bad}));
        FAIL() << "an out-of-range index must throw";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("broken"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("99"), std::string::npos) << e.what();
    }

    SceneObject shortField = makeQuad({-1, -1, -5}, {2, 0, 0}, {0, 2, 0});
    shortField.fields[0].values.pop_back();
    EXPECT_THROW(backend->setScene(sceneOf({shortField})), Error);

    backend->setScene(sceneOf({makeQuad({-1, -1, -5}, {2, 0, 0}, {0, 2, 0})}));
    Camera zero = cam;
    zero.width = 0;
    EXPECT_THROW(backend->render(zero, {}, *ctx), Error);
    CaptureRequest clash;
    clash.scalars = {"Z"};
    EXPECT_THROW(backend->render(cam, clash, *ctx), Error);
    // After the errors the backend still works.
    EXPECT_NEAR(backend->render(cam, {}, *ctx)->hostFloat("Z")[5], 5.0f, 1e-5f);
}

}  // namespace
}  // namespace darkroom::test
