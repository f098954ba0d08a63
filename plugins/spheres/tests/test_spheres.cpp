// Spheres: depth equal to the analytic ray-sphere intersection at every pixel
// centre (perspective and orthographic), the same picture as Embree's native
// sphere primitive, the binned cast equal to a brute-force one, fields and ids
// from CSV and PLY lists, the list found through the row, errors.
#include "../../capture-embree/tests/render_helpers.h"
#include "../src/sphere_raster.h"
#include "test_support.h"

#include <darkroom/error.h>
#include <darkroom/core/run_filter.h>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

using namespace darkroom;
using ::testing::HasSubstr;

namespace {

using Inputs = std::map<std::string, std::vector<Value>>;

Camera camera(int w, int h, bool perspective) {
    Camera c;
    c.width = w;
    c.height = h;
    c.position = {0.4, -0.3, 6.0};
    c.forward = normalize(Vec3{-0.06, 0.05, -1.0});
    c.up = {0, 1, 0};
    c.projection = perspective ? Camera::Projection::Perspective : Camera::Projection::Orthographic;
    c.fovYDegrees = 35;
    c.viewHeight = 4.0;
    return c;
}

BufferPtr cameraImage(const Camera& c) {
    auto b = test::makeImage(c.width, c.height, {"Z"}, [](int, int, int) { return 1.0f; });
    b->metadata().camera = c;
    return b;
}

FilterRunResult drawSpheres(const Camera& c, const std::string& points, Inputs extra = {}, int threads = 2) {
    auto f = test::pluginRegistry().createFilter("Spheres");
    extra["image"] = {Value(cameraImage(c))};
    extra["points"] = {Value(points)};
    FilterRunOptions o;
    o.threads = threads;
    return runFilter(*f, extra, o);
}

// The textbook intersection, in long double, independent of the node's code.
long double analyticDepth(const Camera& c, int x, int y, const Vec3& centre, double r) {
    Vec3 o, d;
    c.ray(x + 0.5, y + 0.5, o, d);
    const long double ox = o.x - centre.x, oy = o.y - centre.y, oz = o.z - centre.z;
    const long double a = (long double)d.x * d.x + (long double)d.y * d.y + (long double)d.z * d.z;
    const long double b = 2 * (d.x * ox + d.y * oy + d.z * oz);
    const long double k = ox * ox + oy * oy + oz * oz - (long double)r * r;
    const long double disc = b * b - 4 * a * k;
    if (disc < 0) return std::numeric_limits<long double>::infinity();
    return (-b - std::sqrt(disc)) / (2 * a);
}

}  // namespace

TEST(Spheres, DepthIsTheAnalyticIntersectionAtEveryPixelCentre) {
    test::TempDir dir;
    test::writeText(dir.file("one.csv"), "x,y,z,radius\n0.1,-0.2,0.3,0.9\n");
    for (const bool perspective : {true, false}) {
        const Camera c = camera(64, 48, perspective);
        const auto r = drawSpheres(c, dir.file("one.csv"));
        const BufferPtr g = r.outputs.at("image").asImage();
        ASSERT_EQ(g->metadata().camera, c);
        int hit = 0;
        for (int y = 0; y < 48; ++y)
            for (int x = 0; x < 64; ++x) {
                const long double want = analyticDepth(c, x, y, {0.1, -0.2, 0.3}, 0.9);
                const float z = g->hostFloat("Z")[std::size_t(y) * 64 + x];
                if (std::isinf(want)) {
                    ASSERT_TRUE(std::isinf(z) && z > 0) << x << "," << y;
                    ASSERT_TRUE(std::isnan(g->hostFloat("N.x")[std::size_t(y) * 64 + x]));
                    continue;
                }
                ++hit;
                ASSERT_NEAR(z, double(want), 1e-6 * double(want)) << x << "," << y;
                // The normal is the unit radius vector at the hit.
                Vec3 o, d;
                c.ray(x + 0.5, y + 0.5, o, d);
                const Vec3 n = (o + d * double(want) - Vec3{0.1, -0.2, 0.3}) * (1 / 0.9);
                ASSERT_NEAR(g->hostFloat("N.x")[std::size_t(y) * 64 + x], n.x, 1e-5);
                ASSERT_NEAR(g->hostFloat("N.z")[std::size_t(y) * 64 + x], n.z, 1e-5);
            }
        EXPECT_GT(hit, 200);
    }
}

TEST(Spheres, SameAsEmbreesNativeSpheres) {
    // A few overlapping spheres drawn by Embree (capture-embree's point
    // primitive) and by the node, same camera.
    const double pts[5][4] = {{0, 0, 0, 0.8}, {0.9, 0.3, 0.4, 0.5}, {-1.0, -0.6, -0.5, 0.6}, {0.2, 1.1, 1.0, 0.3},
                              {-0.4, 0.2, 1.4, 0.25}};
    test::TempDir dir;
    std::string csv = "x,y,z,radius\n";
    SceneObject o;
    o.name = "balls";
    o.representation = Representation::Points;
    for (const auto& p : pts) {
        csv += std::to_string(p[0]) + "," + std::to_string(p[1]) + "," + std::to_string(p[2]) + "," +
               std::to_string(p[3]) + "\n";
        for (double v : p) o.vertices.push_back(float(v));
    }
    test::writeText(dir.file("balls.csv"), csv);
    for (const bool perspective : {true, false}) {
        const Camera c = camera(96, 80, perspective);
        CaptureRequest req;
        req.normals = true;
        const BufferPtr embree = test::capture(test::sceneOf({o}), c, req);
        const BufferPtr ours = drawSpheres(c, dir.file("balls.csv")).outputs.at("image").asImage();
        int both = 0, differ = 0;
        for (std::size_t i = 0; i < ours->pixelCount(); ++i) {
            const float a = ours->hostFloat("Z")[i], b = embree->hostFloat("Z")[i];
            if (std::isinf(a) != std::isinf(b)) {
                ++differ;  // a ray grazing a silhouette: single precision decides
                continue;
            }
            if (std::isinf(a)) continue;
            ++both;
            ASSERT_NEAR(a, b, 2e-4 * b) << i;
            ASSERT_NEAR(ours->hostFloat("N.y")[i], embree->hostFloat("N.y")[i], 2e-3) << i;
        }
        EXPECT_GT(both, 1000);
        EXPECT_LE(differ, 3);
    }
}

TEST(Spheres, BinnedCastEqualsBruteForceAndDoesNotDependOnThreads) {
    // Many spheres, some partly outside the view, one around the eye's plane.
    std::vector<spheres::Sphere> balls;
    for (int i = 0; i < 300; ++i) {
        const double a = 0.37 * i, b = 0.11 * i;
        balls.push_back({{2.5 * std::sin(a), 2.0 * std::cos(1.3 * a), 3.0 * std::sin(b)}, 0.05 + 0.2 * ((i * 7) % 11) / 11.0});
    }
    balls.push_back({{0.4, -0.3, 6.2}, 0.5});  // contains the eye
    balls.push_back({{0.4, -0.3, 9.0}, 0.5});  // behind the eye
    FilterRunOptions one, four;
    one.threads = 1;
    four.threads = 4;
    auto c1 = makeStandaloneContext(one), c4 = makeStandaloneContext(four);
    for (const bool perspective : {true, false}) {
        Camera c = camera(120, 90, perspective);
        c.fovYDegrees = 80;
        const auto a = spheres::castSpheres(*c1, c, balls);
        const auto b = spheres::castSpheres(*c4, c, balls);
        EXPECT_EQ(a.depth, b.depth);
        EXPECT_EQ(a.index, b.index);
        for (int y = 0; y < c.height; ++y)
            for (int x = 0; x < c.width; ++x) {
                Vec3 o, d;
                c.ray(x + 0.5, y + 0.5, o, d);
                double best = std::numeric_limits<double>::infinity();
                int who = -1;
                for (std::size_t i = 0; i < balls.size(); ++i) {
                    const double t = spheres::intersect(o, d, balls[i]);
                    if (t > 0 && float(t) < float(best)) best = t, who = int(i);
                }
                ASSERT_EQ(a.index[std::size_t(y) * c.width + x], who) << x << "," << y << " " << perspective;
            }
    }
}

TEST(Spheres, FieldsIdsAndRadiiFromTheList) {
    test::TempDir dir;
    test::writeText(dir.file("p.csv"), "x,y,z,value,radius\n0,0,0,1.5,0.5\n1.2,0,0,-3,\nnan,0,0,7,1\n");
    const Camera c = camera(80, 60, true);
    const auto r = drawSpheres(c, dir.file("p.csv"), {{"radius", {Value(0.4)}}, {"radiusScale", {Value(1.5)}}});
    const BufferPtr g = r.outputs.at("image").asImage();
    ASSERT_EQ(r.warnings.size(), 1u);
    EXPECT_THAT(r.warnings[0], HasSubstr("p.csv:4: 1 point(s) without a finite x, y, z skipped"));
    EXPECT_EQ(g->channelNames(), (std::vector<std::string>{"Z", "N.x", "N.y", "N.z", "value", "pointId"}));
    std::size_t seen[2] = {0, 0};
    for (std::size_t i = 0; i < g->pixelCount(); ++i) {
        const std::uint32_t id = g->hostUInt("pointId")[i];
        const float v = g->hostFloat("value")[i];
        if (id == 0xffffffffu) {
            ASSERT_TRUE(std::isnan(v));
            continue;
        }
        ASSERT_LT(id, 2u);
        ASSERT_EQ(v, id == 0 ? 1.5f : -3.0f);
        ++seen[id];
    }
    EXPECT_GT(seen[0], 10u);
    EXPECT_GT(seen[1], 10u);
    // Radii: 0.5 * 1.5 from the file for the first, the fallback 0.4 * 1.5 for
    // the second: the nearest depth of each is its distance minus that radius.
    Vec3 right, up, f;
    c.basis(right, up, f);
    float nearest[2] = {std::numeric_limits<float>::infinity(), std::numeric_limits<float>::infinity()};
    for (std::size_t i = 0; i < g->pixelCount(); ++i) {
        const std::uint32_t id = g->hostUInt("pointId")[i];
        if (id < 2) nearest[id] = std::min(nearest[id], g->hostFloat("Z")[i]);
    }
    EXPECT_NEAR(nearest[0], dot(Vec3{0, 0, 0} - c.position, f) - 0.75, 0.01);
    EXPECT_NEAR(nearest[1], dot(Vec3{1.2, 0, 0} - c.position, f) - 0.6, 0.01);
}

TEST(Spheres, ReadsPlyVerticesAndFindsTheListThroughTheRow) {
    test::TempDir dir;
    test::writeText(dir.file("cloud.ply"),
                    "ply\nformat ascii 1.0\nelement vertex 2\nproperty float x\nproperty float y\nproperty float z\n"
                    "property float confidence\nend_header\n0 0 0 0.25\n0.8 0.2 0.1 0.75\n");
    const Camera c = camera(64, 48, false);
    const BufferPtr g = drawSpheres(c, "{FILE_cloud}", {{"row", {Value("phi=0, FILE_cloud=\"" + dir.file("cloud.ply") + "\"")}},
                                                       {"radius", {Value(0.3)}}})
                            .outputs.at("image")
                            .asImage();
    ASSERT_TRUE(g->hasChannel("confidence"));
    int found = 0;
    for (std::size_t i = 0; i < g->pixelCount(); ++i)
        if (g->hostUInt("pointId")[i] == 1) {
            ASSERT_EQ(g->hostFloat("confidence")[i], 0.75f);
            ++found;
        }
    EXPECT_GT(found, 20);
}

// Issue 26 L1: through a narrow camera a sphere just in front of the eye has
// pixel bounds near ±10^10, past any int; they overflowed (UBSan) and the
// sphere that fills the view was dropped.
TEST(Spheres, ASphereFillingANarrowViewIsDrawn) {
    test::TempDir dir;
    Camera c;
    c.width = 64;
    c.height = 48;
    c.position = {0, 0, 0};
    c.forward = {0, 0, -1};
    c.up = {0, 1, 0};
    c.projection = Camera::Projection::Perspective;
    c.fovYDegrees = 1e-3;  // the scene format's narrowest
    // Point lists keep radii in single precision: its surface 2^-23 from the eye.
    const double radius = double(1.9999999f), gap = 2 - radius;
    test::writeText(dir.file("near.csv"), "x,y,z,radius\n0,0,-2,1.9999999\n");
    double x0, y0, x1, y1;
    ASSERT_TRUE(spheres::screenBounds(c, {{0, 0, -2}, radius}, x0, y0, x1, y1));
    EXPECT_LT(x0, -1e9);  // the case: bounds far outside an int
    EXPECT_GT(x1, 1e9);
    const BufferPtr g = drawSpheres(c, dir.file("near.csv")).outputs.at("image").asImage();
    for (std::size_t i = 0; i < g->pixelCount(); ++i) {
        ASSERT_EQ(g->hostUInt("pointId")[i], 0u) << i;
        ASSERT_NEAR(g->hostFloat("Z")[i], gap, 1e-9) << i;
    }
}

TEST(Spheres, ErrorsNameTheFileAndWhatWasExpected) {
    test::TempDir dir;
    test::writeText(dir.file("bad.csv"), "a,b,c\n1,2,3\n");
    test::writeText(dir.file("text.csv"), "x,y,z\n1,2,oops\n");
    const Camera c = camera(16, 16, true);
    auto message = [&](const std::string& points, Inputs extra = {}) {
        try {
            drawSpheres(c, points, extra);
        } catch (const Error& e) {
            return std::string(e.what());
        }
        return std::string("no error");
    };
    EXPECT_THAT(message(dir.file("bad.csv")), HasSubstr("needs columns x, y and z"));
    EXPECT_THAT(message(dir.file("text.csv")), HasSubstr("text.csv:2: column 'z' holds 'oops'; expected a number"));
    EXPECT_THAT(message(dir.file("missing.csv")), HasSubstr("does not exist"));
    EXPECT_THAT(message("{FILE_x}"), HasSubstr("'row' is empty"));
    EXPECT_THAT(message(""), HasSubstr("no point list given"));
}
