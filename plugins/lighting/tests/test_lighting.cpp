// Lighting against analytic answers on planes: a light straight on the plane
// gives albedo * diffuse * intensity, a light at angle θ the Lambert cosine,
// the Blinn-Phong highlight its closed form, AO only the ambient share; the
// same with normals reconstructed from depth; background left alone.
#include "../../normals/tests/depth_scenes.h"

#include <darkroom/error.h>

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <numbers>

using namespace darkroom;
using namespace darkroom::test;
using ::testing::HasSubstr;

namespace {

const double kPi = std::numbers::pi;

// A plane seen by `cam`, albedo (0.8, 0.5, 0.2), optionally with its captured
// world normal in N.x/N.y/N.z.
std::shared_ptr<WritableBuffer> planeImage(const Camera& cam, const ScenePlane& plane, bool normals) {
    std::vector<std::string> extra{"R", "G", "B"};
    if (normals) extra.insert(extra.end(), {"N.x", "N.y", "N.z"});
    auto img = depthImage(cam, [&](int x, int y) { return planeDepth(cam, plane, x, y); }, extra);
    const float albedo[3] = {0.8f, 0.5f, 0.2f};
    for (int c = 0; c < 3; ++c) {
        float* p = img->writeFloat(extra[std::size_t(c)]);
        std::fill(p, p + img->pixelCount(), albedo[c]);
    }
    if (normals) {
        const double n[3] = {plane.normal.x, plane.normal.y, plane.normal.z};
        for (int c = 0; c < 3; ++c) {
            float* p = img->writeFloat(extra[std::size_t(3 + c)]);
            std::fill(p, p + img->pixelCount(), float(n[c]));
        }
    }
    return img;
}

// Pixels at least two away from the border (reconstructed normals use neighbours).
template <class F>
void forInterior(const Buffer& b, F&& f) {
    for (int y = 2; y < b.height() - 2; ++y)
        for (int x = 2; x < b.width() - 2; ++x) f(std::size_t(y) * b.width() + x);
}

Inputs lambertOnly(const Vec3& towardsLight, const char* normals) {
    return {{"mode", {Value("directional")}},  {"space", {Value("world")}},  {"direction1", {Value(towardsLight)}},
            {"ambient", {Value(0.0)}},         {"specular", {Value(0.0)}},   {"diffuse", {Value(1.0)}},
            {"intensity1", {Value(0.9)}},      {"normals", {Value(normals)}}};
}

}  // namespace

TEST(Lighting, LightStraightOnAPlaneGivesAlbedoTimesIntensity) {
    const ScenePlane plane{{0, 0, 0}, normalize(Vec3{0.3, -0.2, 1.0})};
    for (const bool perspective : {true, false})
        for (const char* normals : {"captured", "reconstructed"}) {
            const Camera cam = viewCamera(40, 30, perspective);
            const BufferPtr out = runPass("Lighting", planeImage(cam, plane, true), lambertOnly(plane.normal, normals));
            forInterior(*out, [&](std::size_t i) {
                ASSERT_NEAR(out->hostFloat("R")[i], 0.8 * 0.9, 1e-4) << normals << " " << i;
                ASSERT_NEAR(out->hostFloat("G")[i], 0.5 * 0.9, 1e-4) << normals;
                ASSERT_NEAR(out->hostFloat("B")[i], 0.2 * 0.9, 1e-4) << normals;
            });
        }
}

TEST(Lighting, LambertCosineAtAnAngleAndNothingFromBehind) {
    const ScenePlane plane{{0, 0, 0}, {0, 0, 1}};
    const Camera cam = viewCamera(40, 30, true);
    for (const double degrees : {0.0, 30.0, 60.0, 89.0, 120.0}) {
        const double a = degrees * kPi / 180;
        const Vec3 light{std::sin(a), 0, std::cos(a)};
        const BufferPtr out = runPass("Lighting", planeImage(cam, plane, true), lambertOnly(light, "captured"));
        const double want = 0.8 * 0.9 * std::max(0.0, std::cos(a));
        forInterior(*out, [&](std::size_t i) { ASSERT_NEAR(out->hostFloat("R")[i], want, 1e-5) << degrees; });
    }
}

TEST(Lighting, HeadlightOnATiltedPlaneIsTheCosineOfTheTilt) {
    // Orthographic view straight down -z onto a plane tilted by 40 degrees.
    Camera cam = viewCamera(32, 32, false);
    cam.forward = {0, 0, -1};
    const double tilt = 40 * kPi / 180;
    const ScenePlane plane{{0, 0, 0}, {std::sin(tilt), 0, std::cos(tilt)}};
    for (const char* normals : {"captured", "reconstructed"}) {
        const BufferPtr out = runPass("Lighting", planeImage(cam, plane, true),
                                      {{"ambient", {Value(0.0)}}, {"specular", {Value(0.0)}},
                                       {"diffuse", {Value(1.0)}}, {"normals", {Value(normals)}}});
        forInterior(*out, [&](std::size_t i) { ASSERT_NEAR(out->hostFloat("R")[i], 0.8 * std::cos(tilt), 1e-4) << normals; });
    }
}

TEST(Lighting, BlinnPhongHighlightHasItsClosedForm) {
    // Orthographic: V = +z everywhere; plane normal +z; light at 50 degrees.
    Camera cam = viewCamera(24, 24, false);
    cam.forward = {0, 0, -1};
    const ScenePlane plane{{0, 0, 0}, {0, 0, 1}};
    const double a = 50 * kPi / 180;
    const Vec3 L{std::sin(a), 0, std::cos(a)};
    const Vec3 H = normalize(L + Vec3{0, 0, 1});
    const double shininess = 20, spec = 0.7;
    const BufferPtr out = runPass("Lighting", planeImage(cam, plane, true),
                                  {{"mode", {Value("directional")}}, {"space", {Value("world")}},
                                   {"direction1", {Value(L)}}, {"ambient", {Value(0.1)}},
                                   {"diffuse", {Value(0.6)}}, {"specular", {Value(spec)}},
                                   {"shininess", {Value(shininess)}},
                                   {"specularColor", {Value(Color{1.0f, 0.5f, 0.0f, 1.0f})}}});
    const double kd = 0.1 + 0.6 * std::cos(a);
    const double ks = spec * std::pow(H.z, shininess);
    forInterior(*out, [&](std::size_t i) {
        ASSERT_NEAR(out->hostFloat("R")[i], 0.8 * kd + 1.0 * ks, 1e-5);
        ASSERT_NEAR(out->hostFloat("G")[i], 0.5 * kd + 0.5 * ks, 1e-5);
        ASSERT_NEAR(out->hostFloat("B")[i], 0.2 * kd, 1e-5);
    });
}

TEST(Lighting, AoMultipliesOnlyTheAmbientPart) {
    const Camera cam = viewCamera(20, 16, true);
    const ScenePlane plane{{0, 0, 0}, normalize(Vec3{0.1, 0.2, 1.0})};
    const BufferPtr img = planeImage(cam, plane, true);
    const auto ao = makeImage(20, 16, {"AO"}, [](int x, int, int) { return x < 10 ? 0.5f : 1.0f; });
    Inputs in = lambertOnly(plane.normal, "captured");
    in["ambient"] = {Value(0.3)};
    in["ao"] = {Value(BufferPtr(ao))};
    const BufferPtr out = runPass("Lighting", img, in);
    forInterior(*out, [&](std::size_t i) {
        const double occlusion = (i % 20) < 10 ? 0.5 : 1.0;
        ASSERT_NEAR(out->hostFloat("R")[i], 0.8 * (0.3 * occlusion + 0.9), 1e-5);
    });
}

TEST(Lighting, ViewSpaceLightTowardsTheViewerIsTheHeadlight) {
    const Camera cam = viewCamera(30, 20, true);
    const BufferPtr img = planeImage(cam, {{0, 0, 0}, normalize(Vec3{0.4, 0.1, 1.0})}, true);
    const BufferPtr head = runPass("Lighting", img, {});
    const BufferPtr view = runPass("Lighting", img, {{"mode", {Value("directional")}},
                                                     {"direction1", {Value(Vec3{0, 0, 2})}}});
    for (std::size_t i = 0; i < head->pixelCount(); ++i) ASSERT_NEAR(head->hostFloat("R")[i], view->hostFloat("R")[i], 1e-6);
}

TEST(Lighting, BackgroundAndBackFacesAreHandled) {
    const Camera cam = viewCamera(20, 10, true);
    // Captured normals facing away from the camera light like the front face.
    const ScenePlane plane{{0, 0, 0}, {0, 0, 1}};
    const ScenePlane flipped{{0, 0, 0}, {0, 0, -1}};
    auto front = runPass("Lighting", planeImage(cam, plane, true), {});
    auto back = runPass("Lighting", planeImage(cam, flipped, true), {});
    for (std::size_t i = 0; i < front->pixelCount(); ++i) ASSERT_FLOAT_EQ(front->hostFloat("R")[i], back->hostFloat("R")[i]);
    // Background keeps its colour bit for bit.
    auto img = planeImage(cam, plane, false);
    img->writeFloat("Z")[3] = std::numeric_limits<float>::infinity();
    img->writeFloat("R")[3] = 0.123f;
    EXPECT_EQ(runPass("Lighting", img, {})->hostFloat("R")[3], 0.123f);
}

TEST(Lighting, ErrorsAreClear) {
    const Camera cam = viewCamera(8, 8, true);
    try {
        runPass("Lighting", planeImage(cam, {{0, 0, 0}, {0, 0, 1}}, false), {{"normals", {Value("captured")}}});
        FAIL();
    } catch (const Error& e) {
        EXPECT_THAT(e.what(), HasSubstr("captured needs N.x, N.y and N.z"));
    }
    try {
        runPass("Lighting", planeImage(cam, {{0, 0, 0}, {0, 0, 1}}, false),
                {{"mode", {Value("directional")}}, {"direction1", {Value(Vec3{0, 0, 0})}}});
        FAIL();
    } catch (const Error& e) {
        EXPECT_THAT(e.what(), HasSubstr("direction1 is not a direction"));
    }
}

TEST(Lighting, CapturedNormalsFromTheGeometryInput) {
    // Colour without normals (as ColorMapping writes it) lit with the normals of
    // the G-buffer it came from.
    const ScenePlane plane{{0, 0, 0}, normalize(Vec3{0.5, 0.2, 1.0})};
    const Camera cam = viewCamera(24, 18, true);
    const BufferPtr gbuffer = planeImage(cam, plane, true);
    const BufferPtr colour = planeImage(cam, plane, false);
    Inputs in = lambertOnly(Vec3{0, 0, 1}, "captured");
    in["geometry"] = {Value(gbuffer)};
    const BufferPtr out = runPass("Lighting", colour, in);
    for (std::size_t i = 0; i < out->pixelCount(); ++i)
        ASSERT_NEAR(out->hostFloat("R")[i], 0.8 * 0.9 * plane.normal.z, 1e-5) << i;  // every pixel: no border effect
}
