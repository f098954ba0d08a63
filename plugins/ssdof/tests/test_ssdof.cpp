// Ssdof through the plugin registry: known answers for in-focus identity, the
// point-spread shape and size of both apertures, near/far bleeding rules, and
// robustness on degenerate input.
#include "../../normals/tests/simd_targets.h"
#include "test_support.h"

#include <darkroom/error.h>
#include <darkroom/core/run_filter.h>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

using namespace darkroom;
using ::testing::HasSubstr;

namespace {

using Inputs = std::map<std::string, std::vector<Value>>;
const float kInf = std::numeric_limits<float>::infinity();
const float kNaN = std::numeric_limits<float>::quiet_NaN();
const std::vector<std::string> kRgbaZ = {"R", "G", "B", "A", "Z"};

// 90 degree field of view: one pixel at depth z is 2 z / height wide.
Camera camera(int w, int h) {
    Camera c;
    c.width = w;
    c.height = h;
    c.fovYDegrees = 90.0;
    return c;
}

// Signed CoC radius from the cone geometry (not from the plugin's code): the
// cone through a lens of diameter A cuts the focal plane in a disc of diameter
// A |z - zf| / z, measured in pixels of that plane.
double cocRadius(const Camera& cam, double A, double zf, double z) {
    return A * (z - zf) / z / cam.pixelSizeAt(zf) / 2.0;
}

std::shared_ptr<WritableBuffer> scene(int w, int h, const std::function<float(int, int, int)>& fn) {
    auto b = test::makeImage(w, h, kRgbaZ, fn);
    b->metadata().camera = camera(w, h);
    return b;
}

BufferPtr dof(const BufferPtr& image, Inputs params, int threads = 2) {
    auto f = test::pluginRegistry().createFilter("SSDoF");
    params["image"] = {Value(image)};
    FilterRunOptions o;
    o.threads = threads;
    return runFilter(*f, params, o).outputs.at("image").asImage();
}

Inputs lens(double aperture, double focal, const std::string& method, double maxBlur = 32.0) {
    return {{"aperture", {Value(aperture)}},
            {"focalDistance", {Value(focal)}},
            {"method", {Value(method)}},
            {"maxBlur", {Value(maxBlur)}}};
}

float at(const Buffer& b, const char* c, int x, int y) { return b.hostFloat(c)[std::size_t(y) * b.width() + x]; }

// Support of a blurred dot: half-extents of its bounding box around the dot,
// largest distance from the dot, and the energy (sum of R).
struct Spread {
    double halfWidth = 0, halfHeight = 0, radius = 0, energy = 0;
};
Spread spread(const Buffer& b, int cx, int cy) {
    Spread s;
    for (int y = 0; y < b.height(); ++y)
        for (int x = 0; x < b.width(); ++x) {
            const float v = at(b, "R", x, y);
            s.energy += v;
            if (v <= 1e-6f) continue;
            s.halfWidth = std::max(s.halfWidth, double(std::abs(x - cx)));
            s.halfHeight = std::max(s.halfHeight, double(std::abs(y - cy)));
            s.radius = std::max(s.radius, std::hypot(double(x - cx), double(y - cy)));
        }
    return s;
}

// A black opaque plane at depth z with one white pixel at the centre.
BufferPtr dot(int size, float z) {
    return scene(size, size, [=](int x, int y, int c) -> float {
        if (c == 4) return z;
        if (c == 3) return 1.0f;
        return x == size / 2 && y == size / 2 ? 1.0f : 0.0f;
    });
}

}  // namespace

TEST(Ssdof, AWholePlaneAtTheFocalDistanceIsUnchanged) {
    const auto in = scene(23, 17, [](int x, int y, int c) -> float {
        return c == 4 ? 3.0f : 0.1f + 0.8f * float((x * 7 + y * 3 + c * 5) % 11) / 10.0f;
    });
    for (const char* m : {"disc", "hexagon"}) EXPECT_TRUE(identical(*dof(in, lens(1.0, 3.0, m)), *in)) << m;
}

TEST(Ssdof, ZeroApertureIsTheIdentity) {
    const auto in = scene(16, 12, [](int x, int y, int c) -> float {
        return c == 4 ? 1.0f + float(x + y) : 0.05f * float(x + c);
    });
    for (const char* m : {"disc", "hexagon"}) EXPECT_TRUE(identical(*dof(in, lens(0.0, 4.0, m)), *in)) << m;
}

TEST(Ssdof, DiscBlursAFarPointIntoADiscOfThePredictedRadius) {
    // zf = 2, z = 8, A = 1 on a 64-pixel 90-degree camera: radius 6 px.
    const double r = cocRadius(camera(64, 64), 1.0, 2.0, 8.0);
    ASSERT_NEAR(r, 6.0, 1e-9);
    auto p = lens(1.0, 2.0, "disc");
    p["samples"] = {Value(std::int64_t(256))};
    const Spread s = spread(*dof(dot(64, 8.0f), p), 32, 32);
    EXPECT_NEAR(s.radius, r, 1.0);
    EXPECT_NEAR(s.halfWidth, r, 1.0);
    EXPECT_NEAR(s.halfHeight, r, 1.0);
    EXPECT_NEAR(s.energy, 1.0, 0.03);
}

TEST(Ssdof, DiscBlursANearPointIntoADiscOfThePredictedRadius) {
    const double r = cocRadius(camera(64, 64), 1.0, 2.0, 0.8);  // -12 px
    ASSERT_NEAR(r, -12.0, 1e-9);
    auto p = lens(1.0, 2.0, "disc");
    p["samples"] = {Value(std::int64_t(512))};
    const Spread s = spread(*dof(dot(64, 0.8f), p), 32, 32);
    EXPECT_NEAR(s.radius, 12.0, 1.0);
    EXPECT_NEAR(s.halfWidth, 12.0, 1.0);
    EXPECT_NEAR(s.halfHeight, 12.0, 1.0);
    EXPECT_NEAR(s.energy, 1.0, 0.03);
}

TEST(Ssdof, HexagonBlursAPointIntoAHexagonWithCornersUp) {
    // Far (A = 2, z = 8: +12 px) and near (A = 1, z = 0.8: -12 px) points.
    for (const auto& [A, z] : {std::pair{2.0, 8.0f}, std::pair{1.0, 0.8f}}) {
        const double r = std::fabs(cocRadius(camera(64, 64), A, 2.0, z));
        ASSERT_NEAR(r, 12.0, 1e-5);
        const Spread s = spread(*dof(dot(64, z), lens(A, 2.0, "hexagon")), 32, 32);
        // Corner to corner vertically, flat to flat horizontally.
        EXPECT_NEAR(s.halfHeight, r, 1.0) << z;
        EXPECT_NEAR(s.halfWidth, r * std::cos(std::numbers::pi / 6), 1.0) << z;
        EXPECT_NEAR(s.halfWidth / s.halfHeight, std::cos(std::numbers::pi / 6), 0.06) << z;
        EXPECT_NEAR(s.energy, 1.0, 0.03) << z;
    }
}

TEST(Ssdof, HexagonRotatedByThirtyDegreesHasCornersSideways) {
    auto p = lens(2.0, 2.0, "hexagon");
    p["rotation"] = {Value(30.0)};
    const Spread s = spread(*dof(dot(64, 8.0f), p), 32, 32);
    EXPECT_NEAR(s.halfWidth, 12.0, 1.0);
    EXPECT_NEAR(s.halfHeight, 12.0 * std::cos(std::numbers::pi / 6), 1.0);
}

namespace {
// In-focus checkerboard of greys at z = 2 with a red square [24, 40)^2 at z.
BufferPtr squareOverPlane(float squareZ, float planeZ) {
    return scene(64, 64, [=](int x, int y, int c) -> float {
        const bool square = x >= 24 && x < 40 && y >= 24 && y < 40;
        if (c == 4) return square ? squareZ : planeZ;
        if (c == 3) return 1.0f;
        if (square) return c == 0 ? 1.0f : 0.0f;
        return (x + y) % 2 ? 0.8f : 0.2f;
    });
}
}  // namespace

TEST(Ssdof, NearSquareBleedsOverTheSharpPlaneBehindIt) {
    // Square at z = 1: CoC -8 px; plane at the focal distance 2.
    ASSERT_NEAR(cocRadius(camera(64, 64), 1.0, 2.0, 1.0), -8.0, 1e-9);
    const BufferPtr in = squareOverPlane(1.0f, 2.0f);
    for (const char* m : {"disc", "hexagon"}) {
        const BufferPtr out = dof(in, lens(1.0, 2.0, m));
        // ScenePlane pixels more than 8 px (+1 rounding) from the square keep their bits.
        for (int y = 0; y < 64; ++y)
            for (int x = 0; x < 64; ++x) {
                const int dx = std::max({24 - x, 0, x - 39}), dy = std::max({24 - y, 0, y - 39});
                if (dx * dx + dy * dy <= 81) continue;
                for (const char* c : {"R", "G", "B", "A"})
                    ASSERT_EQ(at(*out, c, x, y), at(*in, c, x, y)) << m << " " << c << " " << x << "," << y;
            }
        // Just outside the square's right edge the plane shows a blend of the
        // red square over it: green (0 in the square) is lost in proportion to
        // the square's coverage, which falls with distance.
        double previous = 1.0;
        for (int x = 40; x <= 46; x += 2) {
            const double coverage = 1.0 - at(*out, "G", x, 32) / at(*in, "G", x, 32);
            EXPECT_LT(coverage, previous) << m << " x=" << x;
            previous = coverage;
            if (x == 40) {
                EXPECT_NEAR(coverage, 0.5, 0.2) << m << ": half the near disc covers the edge";
            }
        }
        EXPECT_GT(at(*out, "R", 41, 32) - at(*out, "G", 41, 32), 0.1) << m << ": red over grey";
        // Deep inside, the square is its own colour.
        EXPECT_NEAR(at(*out, "R", 32, 32), 1.0f, 1e-5) << m;
        EXPECT_NEAR(at(*out, "G", 32, 32), 0.0f, 1e-5) << m;
    }
}

TEST(Ssdof, FarPlaneNeverBleedsOverANearerSharpSquare) {
    // ScenePlane at infinity (far-field CoC 16 px), square in focus at 2.
    const BufferPtr in = scene(64, 64, [](int x, int y, int c) -> float {
        const bool square = x >= 24 && x < 40 && y >= 24 && y < 40;
        if (c == 4) return square ? 2.0f : kInf;
        if (c == 3) return 1.0f;
        if (square) return 0.1f * float(c + 1);  // (0.1, 0.2, 0.3): not grey
        return (x / 3 + y / 3) % 2 ? 0.9f : 0.1f;
    });
    for (const char* m : {"disc", "hexagon"}) {
        const BufferPtr out = dof(in, lens(1.0, 2.0, m));
        int changed = 0;
        for (int y = 0; y < 64; ++y)
            for (int x = 0; x < 64; ++x) {
                const bool square = x >= 24 && x < 40 && y >= 24 && y < 40;
                if (square) {
                    for (const char* c : {"R", "G", "B", "A"})
                        ASSERT_EQ(at(*out, c, x, y), at(*in, c, x, y)) << m << " square " << x << "," << y;
                    continue;
                }
                // The sharp square's light does not spread: the background stays grey.
                ASSERT_NEAR(at(*out, "R", x, y), at(*out, "G", x, y), 1e-5f) << m << " " << x << "," << y;
                ASSERT_NEAR(at(*out, "G", x, y), at(*out, "B", x, y), 1e-5f) << m << " " << x << "," << y;
                changed += at(*out, "R", x, y) != at(*in, "R", x, y);
            }
        EXPECT_GT(changed, 64 * 64 / 2) << m << ": the far plane is blurred";
    }
}

TEST(Ssdof, AutoFocusKeepsTheCentreSharp) {
    const BufferPtr in = scene(32, 32, [](int x, int y, int c) -> float {
        if (c == 4) return x < 8 ? 9.0f : 3.0f;
        return 0.1f + 0.8f * float((x * 5 + y * 3 + c) % 7) / 6.0f;
    });
    const BufferPtr out = dof(in, lens(0.5, 0.0, "disc"));
    EXPECT_EQ(at(*out, "R", 20, 16), at(*in, "R", 20, 16));
    EXPECT_EQ(at(*out, "G", 31, 0), at(*in, "G", 31, 0));
    EXPECT_NE(at(*out, "R", 2, 16), at(*in, "R", 2, 16)) << "the far strip is blurred";
}

TEST(Ssdof, PassesOtherChannelsAndTheCameraThrough) {
    auto in = test::makeImage(12, 10, {"Z", "R", "G", "B", "value"}, [](int x, int y, int c) -> float {
        return c == 0 ? 1.0f + 0.5f * float(x) : 0.3f + 0.01f * float(x * y + c);
    });
    in->metadata().camera = camera(12, 10);
    const BufferPtr out = dof(in, lens(1.0, 2.0, "disc"));
    EXPECT_EQ(out->channelNames(), in->channelNames()) << "no alpha is invented";
    EXPECT_EQ(out->metadata(), in->metadata());
    for (std::size_t i = 0; i < in->pixelCount(); ++i) {
        EXPECT_EQ(out->hostFloat("value")[i], in->hostFloat("value")[i]);
        EXPECT_EQ(out->hostFloat("Z")[i], in->hostFloat("Z")[i]);
    }
}

TEST(Ssdof, DegenerateInputsGiveFiniteColourWithinTheInputRange) {
    auto withBackground = [](int w, int h, bool nanColour) {
        return scene(w, h, [=](int x, int y, int c) -> float {
            const bool bg = (x + y) % 3 == 0;
            if (c == 4) return bg ? ((x % 2) ? kInf : kNaN) : (x == 1 ? -kInf : 0.5f + float(y));
            if (c == 3) return bg ? 0.0f : 1.0f;
            return bg && nanColour ? kNaN : 0.25f + 0.05f * float((x + c) % 5);
        });
    };
    const std::vector<BufferPtr> inputs = {
        scene(7, 5, [](int, int, int c) { return c == 4 ? kInf : (c == 3 ? 0.0f : 0.0f); }),  // all background
        scene(1, 1, [](int, int, int c) { return c == 4 ? 2.0f : 0.5f; }),
        withBackground(9, 8, true),
        withBackground(40, 30, false),
    };
    for (const char* m : {"disc", "hexagon"})
        for (double A : {0.5, 1e6})  // huge aperture: clamped by maxBlur
            for (double zf : {0.0, 1.5})
                for (const BufferPtr& in : inputs) {
                    const BufferPtr out = dof(in, lens(A, zf, m, 8.0));
                    for (const char* c : {"R", "G", "B", "A"})
                        for (std::size_t i = 0; i < out->pixelCount(); ++i) {
                            const float v = out->hostFloat(c)[i];
                            ASSERT_TRUE(std::isfinite(v) || std::isnan(in->hostFloat(c)[i]))
                                << m << " " << c << " " << i << " " << in->width() << "x" << in->height();
                            if (std::isfinite(v)) {
                                ASSERT_GE(v, 0.0f) << m << " " << c;
                                ASSERT_LE(v, 1.0f + 1e-6f) << m << " " << c;
                            }
                        }
                }
}

TEST(Ssdof, OneAndFourThreadsGiveIdenticalImages) {
    const BufferPtr in = scene(97, 61, [](int x, int y, int c) -> float {
        if (c == 4) return x < 30 ? 0.9f : (y < 20 ? kInf : 2.0f + 0.05f * float(x));
        if (c == 3) return x > 80 ? 0.5f : 1.0f;
        return 0.5f + 0.5f * std::sin(0.3f * float(x * (c + 1)) + 0.2f * float(y));
    });
    for (const char* m : {"disc", "hexagon"})
        EXPECT_TRUE(identical(*dof(in, lens(0.4, 2.0, m), 1), *dof(in, lens(0.4, 2.0, m), 4))) << m;
}

// Both gathers run vectors of pixels with the best SIMD instructions of the
// CPU (the near field's taps as plain loads, the far field's as gathers):
// every instruction set gives the same bits, with near and far fields,
// background, transparent pixels, a width that is no multiple of a vector
// and a rotated hexagon.
TEST(Ssdof, ResultDoesNotDependOnTheSimdInstructionSet) {
    const BufferPtr in = scene(83, 47, [](int x, int y, int c) -> float {
        if (c == 4) return x < 25 ? 0.9f : (y < 15 ? kInf : 2.0f + 0.05f * float(x));
        if (c == 3) return x > 70 ? 0.5f : ((x + y) % 19 == 0 ? 0.0f : 1.0f);
        return 0.5f + 0.5f * std::sin(0.3f * float(x * (c + 1)) + 0.2f * float(y));
    });
    for (const char* m : {"disc", "hexagon"}) {
        auto p = lens(0.4, 2.0, m, 12.0);
        p["samples"] = {Value(std::int64_t(23))};
        p["rotation"] = {Value(17.0)};
        const auto results = test::resultsPerSimdTarget([&] { return dof(in, p); });
        for (const auto& [target, out] : results)
            EXPECT_TRUE(identical(*out, *results.front().second)) << m << ": " << target << " differs from "
                                                                  << results.front().first;
    }
}

// Without a camera: image space (docs/cameras.md); without Z: an error.
TEST(Ssdof, RefusesAnImageWithoutDepthButNotWithoutCamera) {
    auto noCamera = test::makeImage(4, 4, kRgbaZ, [](int, int, int) { return 1.0f; });
    EXPECT_NO_THROW(dof(noCamera, lens(1.0, 2.0, "disc")));
    auto noDepth = test::makeImage(4, 4, {"R", "G", "B"}, [](int, int, int) { return 1.0f; });
    noDepth->metadata().camera = camera(4, 4);
    try {
        dof(noDepth, lens(1.0, 2.0, "disc"));
        FAIL() << "expected an error";
    } catch (const Error& e) {
        EXPECT_THAT(e.what(), HasSubstr("Z"));
    }
}
