// PointListAO as a node: the textbook value under a sphere, reconstructed
// normals equal to captured ones on a plane, lines joined by the `line`
// column, an AO already present multiplied in, the same output for any
// thread count, and the errors a user meets.
#include "test_support.h"

#include <darkroom/error.h>
#include <darkroom/core/run_filter.h>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>

using namespace darkroom;
using ::testing::HasSubstr;

namespace {

using Inputs = std::map<std::string, std::vector<Value>>;
constexpr int kSize = 33;  // odd: the centre pixel's ray passes through the origin

// Orthographic camera 10 units above the plane z = 0, looking down, 4 units
// across: pixel centre (16.5, 16.5) sees (0, 0, 0).
Camera topCamera() {
    Camera c;
    c.width = c.height = kSize;
    c.position = {0, 0, 10};
    c.forward = {0, 0, -1};
    c.up = {0, 1, 0};
    c.projection = Camera::Projection::Orthographic;
    c.viewHeight = 4.0;
    return c;
}

// The plane z = 0 as a G-buffer, with or without its normals, optionally
// carrying an AO channel of constant value.
BufferPtr plane(bool normals, float existingAo = -1) {
    std::vector<std::string> channels{"Z"};
    if (normals) channels.insert(channels.end(), {"N.x", "N.y", "N.z"});
    if (existingAo >= 0) channels.push_back("AO");
    auto b = test::makeImage(kSize, kSize, channels, [&](int, int, int c) {
        if (c == 0) return 10.0f;
        if (existingAo >= 0 && c == int(channels.size()) - 1) return existingAo;
        return c == 3 ? 1.0f : 0.0f;
    });
    b->metadata().camera = topCamera();
    return b;
}

BufferPtr listAo(const BufferPtr& image, const std::string& points, Inputs extra = {}, int threads = 2) {
    auto f = test::pluginRegistry().createFilter("PointListAO");
    extra["image"] = {Value(image)};
    extra["points"] = {Value(points)};
    if (!extra.count("radiusUnits")) extra["radiusUnits"] = {Value("world")};
    if (!extra.count("radius")) extra["radius"] = {Value(5.0)};
    FilterRunOptions o;
    o.threads = threads;
    return runFilter(*f, extra, o).outputs.at("image").asImage();
}

float at(const BufferPtr& b, int x, int y) { return b->hostFloat("AO")[std::size_t(y) * kSize + std::size_t(x)]; }

}  // namespace

TEST(PointListAO, UnderASphereTheOcclusionIsRadiusOverDistanceSquared) {
    test::TempDir dir;
    test::writeText(dir.file("one.csv"), "x,y,z,radius\n0,0,1,0.5\n");
    for (const bool normals : {true, false}) {
        const BufferPtr ao = listAo(plane(normals), dir.file("one.csv"));
        // (r / d)^2 = 0.25 straight below the centre, on the normal.
        EXPECT_NEAR(at(ao, 16, 16), 0.75f, 1e-5f) << "normals " << normals;
        // A sphere 1.5 units away along the plane is beyond R = 1.2.
        const BufferPtr near = listAo(plane(normals), dir.file("one.csv"), {{"radius", {Value(1.2)}}});
        EXPECT_EQ(at(near, 16 + 12, 16), 1.0f) << "normals " << normals;  // 12 px = 1.45 units
        EXPECT_LT(at(near, 16, 16), 1.0f);
    }
}

TEST(PointListAO, ConsecutiveRowsOfOneLineAreJoinedIntoARoundLine) {
    test::TempDir dir;
    // Three points 0.6 apart at height 0.5: as a line they cover the gaps
    // between them, as spheres of radius 0.05 they do not.
    const std::string rows = "-0.6,0,0.5,0.05,{}\n0,0,0.5,0.05,{}\n0.6,0,0.5,0.05,{}\n";
    auto fill = [&](const char* v) {
        std::string s = rows;
        for (std::size_t p; (p = s.find("{}")) != std::string::npos;) s.replace(p, 2, v);
        return s;
    };
    test::writeText(dir.file("line.csv"), "x,y,z,radius,line\n" + fill("7"));
    test::writeText(dir.file("balls.csv"), "x,y,z,radius,line\n" + fill(""));
    const BufferPtr line = listAo(plane(true), dir.file("line.csv"), {{"radius", {Value(1.0)}}});
    const BufferPtr balls = listAo(plane(true), dir.file("balls.csv"), {{"radius", {Value(1.0)}}});
    // Under a gap (pixel 18: x0 = 2 * 4 / 33): the line occludes, the
    // spheres barely. A thin line along x at height h covers
    // (1/pi) * integral of 2 r h^2 / (s^2 + h^2)^2 ds of the cosine-weighted
    // hemisphere, s along the line from the foot of the normal: here from
    // -0.6 - x0 to 0.6 - x0.
    const double h = 0.5, r = 0.05, x0 = 2.0 * 4.0 / 33.0;
    auto G = [&](double s) { return s / (2 * h * h * (s * s + h * h)) + std::atan(s / h) / (2 * h * h * h); };
    const double want = 2 * r * h * h * (G(0.6 - x0) - G(-0.6 - x0)) / 3.14159265358979;
    const float underLine = at(line, 18, 16), underBalls = at(balls, 18, 16);
    EXPECT_LT(underLine, underBalls - 0.03f);
    EXPECT_NEAR(1.0 - underLine, want, 0.05 * want);
}

TEST(PointListAO, AnAoAlreadyPresentIsMultipliedOrReplaced) {
    test::TempDir dir;
    test::writeText(dir.file("one.csv"), "x,y,z,radius\n0,0,1,0.5\n");
    EXPECT_NEAR(at(listAo(plane(true, 0.5f), dir.file("one.csv")), 16, 16), 0.375f, 1e-5f);
    EXPECT_NEAR(at(listAo(plane(true, 0.5f), dir.file("one.csv"), {{"existingAO", {Value("replace")}}}), 16, 16),
                0.75f, 1e-5f);
}

TEST(PointListAO, TheSameForAnyThreadCount) {
    test::TempDir dir;
    std::string csv = "x,y,z,radius\n";
    for (int i = 0; i < 300; ++i)
        csv += std::to_string(std::sin(i * 1.7) * 1.8) + "," + std::to_string(std::cos(i * 2.3) * 1.8) + "," +
               std::to_string(0.2 + 0.3 * std::fabs(std::sin(i * 0.9))) + ",0.04\n";
    test::writeText(dir.file("cloud.csv"), csv);
    const BufferPtr one = listAo(plane(false), dir.file("cloud.csv"), {{"radius", {Value(0.5)}}}, 1);
    const BufferPtr three = listAo(plane(false), dir.file("cloud.csv"), {{"radius", {Value(0.5)}}}, 3);
    int occluded = 0;
    for (int y = 0; y < kSize; ++y)
        for (int x = 0; x < kSize; ++x) {
            ASSERT_EQ(at(one, x, y), at(three, x, y)) << x << "," << y;
            occluded += at(one, x, y) < 1.0f;
        }
    EXPECT_GT(occluded, kSize * kSize / 2);
}

TEST(PointListAO, ErrorsNameWhatIsMissing) {
    test::TempDir dir;
    try {
        listAo(plane(true), dir.file("absent.csv"));
        FAIL() << "no error for a missing list";
    } catch (const std::exception& e) {
        EXPECT_THAT(e.what(), HasSubstr("absent.csv"));
    }
    try {
        listAo(plane(true), "");
        FAIL() << "no error for an empty 'points'";
    } catch (const std::exception& e) {
        EXPECT_THAT(e.what(), HasSubstr("no point list given"));
    }
    test::writeText(dir.file("one.csv"), "x,y,z\n0,0,1\n");
    auto noCamera = test::makeImage(8, 8, {"Z"}, [](int, int, int) { return 1.0f; });
    try {
        listAo(noCamera, dir.file("one.csv"));
        FAIL() << "no error without a camera";
    } catch (const std::exception& e) {
        EXPECT_THAT(e.what(), HasSubstr("camera"));
    }
    try {
        listAo(plane(true), "{FILE_particles}");
        FAIL() << "no error for placeholders without a row";
    } catch (const std::exception& e) {
        EXPECT_THAT(e.what(), HasSubstr("row"));
    }
}
