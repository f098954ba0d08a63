// TTK .vti images: a round trip through writeVti/readVti in every encoding
// with a known camera, TTK's depth normalisation and its linear angle model.
#include "test_support.h"

#include <darkroom/error.h>
#include <darkroom/data/formats/vti.h>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

using namespace darkroom;
using ::testing::HasSubstr;

namespace {

constexpr double kPi = 3.14159265358979323846;
const float kInf = std::numeric_limits<float>::infinity();

// 6 x 4 image: Z rises to the right and downwards, background in the top-left
// pixel; Elevation encodes the pixel position so row flips show.
std::shared_ptr<WritableBuffer> sample() {
    auto img = test::makeImage(6, 4, {"Z", "Elevation"}, [](int x, int y, int c) {
        if (c == 0) return (x == 0 && y == 0) ? kInf : float(2.0 + 0.5 * x + 0.25 * y);
        return float(10 * y + x);
    });
    return img;
}

TtkCamera perspective() {
    TtkCamera c;
    c.position = {1, 2, 10};
    c.direction = {0, 0, -2};
    c.up = {0, 1, 0};
    c.orthographic = false;
    c.angle = 40;
    c.nearPlane = 1;
    c.farPlane = 9;
    c.width = 6;
    c.height = 4;
    return c;
}

}  // namespace

TEST(Vti, RoundTripInEveryEncodingRecoversChannelsDepthAndCamera) {
    test::TempDir dir;
    const auto img = sample();
    for (bool base64 : {false, true})
        for (bool zlib : {false, true}) {
            const std::string path = dir.file("i.vti");
            writeVti(path, *img, perspective(), {base64, zlib});
            const VtiImage back = readVti(path);
            SCOPED_TRACE(testing::Message() << "base64 " << base64 << " zlib " << zlib);
            ASSERT_EQ(back.buffer->width(), 6);
            ASSERT_EQ(back.buffer->height(), 4);
            const float* z = back.buffer->requireFloat("Z");
            const float* e = back.buffer->requireFloat("Elevation");
            const float* z0 = img->hostFloat("Z");
            for (int i = 0; i < 24; ++i) {
                EXPECT_EQ(e[i], img->hostFloat("Elevation")[i]) << "pixel " << i;  // top-left origin kept
                if (std::isinf(z0[i])) EXPECT_EQ(z[i], kInf);
                else EXPECT_NEAR(z[i], z0[i], 1e-5) << "pixel " << i;  // through TTK's [0,1] normalisation
            }
            ASSERT_TRUE(back.ttkCamera);
            EXPECT_EQ(back.ttkCamera->nearPlane, 1);
            EXPECT_EQ(back.ttkCamera->farPlane, 9);
            ASSERT_TRUE(back.buffer->metadata().camera);
            const Camera& cam = *back.buffer->metadata().camera;
            EXPECT_EQ(cam.projection, Camera::Projection::Perspective);
            EXPECT_EQ(cam.position, (Vec3{1, 2, 10}));
            EXPECT_NEAR(cam.forward.z, -1, 1e-12);
            EXPECT_EQ(cam.width, 6);
            EXPECT_EQ(cam.height, 4);
            EXPECT_TRUE(back.warnings.empty());
        }
}

TEST(Vti, TtkLinearAngleBecomesTheEquivalentPinholeFieldOfView) {
    TtkCamera t = perspective();
    t.width = 200;
    t.height = 100;
    t.angle = 60;
    const Camera c = toDarkroomCamera(t);
    // TTK: the image plane at unit distance is angle_rad wide; height = width * H / W.
    const double halfHeight = 0.5 * (60 * kPi / 180) * 0.5;
    EXPECT_NEAR(c.fovYDegrees, 2 * std::atan(halfHeight) * 180 / kPi, 1e-12);
    // A TTK ray through pixel column x (u = (x - W/2) * angle/W) meets the plane
    // at unit depth where Darkroom's ray through the same pixel corner does.
    Vec3 o, d;
    c.ray(150.0, 50.0, o, d);  // Darkroom continuous coordinate = TTK's corner
    const double u = (150 - 100) * (60 * kPi / 180) / 200;
    EXPECT_NEAR(d.x, u, 1e-12);  // right = +x for forward -z, up +y
    t.orthographic = true;
    t.viewHeight = 3.5;
    const Camera o2 = toDarkroomCamera(t);
    EXPECT_EQ(o2.projection, Camera::Projection::Orthographic);
    EXPECT_EQ(o2.viewHeight, 3.5);
}

TEST(Vti, DepthWithoutNearFarKeepsPlanarValuesAndNaNBecomesInfinity) {
    EXPECT_EQ(ttkDepthToPlanar(std::numeric_limits<float>::quiet_NaN(), 0, 0), kInf);
    EXPECT_EQ(ttkDepthToPlanar(3.5f, 0, 0), 3.5f);
    EXPECT_EQ(ttkDepthToPlanar(1.0f, 2, 4), kInf);
    EXPECT_FLOAT_EQ(ttkDepthToPlanar(0.25f, 2, 4), 2.5f);
    test::TempDir dir;
    const auto img = sample();
    TtkCamera t = perspective();
    t.nearPlane = t.farPlane = 0;  // TTK then writes planar depth, NaN for no hit
    writeVti(dir.file("p.vti"), *img, t);
    const auto back = readVti(dir.file("p.vti"));
    EXPECT_EQ(back.buffer->requireFloat("Z")[0], kInf);
    EXPECT_FLOAT_EQ(back.buffer->requireFloat("Z")[5], img->hostFloat("Z")[5]);
}

TEST(Vti, MalformedFilesAreErrorsNamingTheFile) {
    test::TempDir dir;
    const auto message = [](const std::string& path) {
        try {
            readVti(path);
        } catch (const Error& e) {
            return std::string(e.what());
        }
        return std::string("no error");
    };
    const std::string poly = dir.file("poly.vti");
    test::writeText(poly, "<VTKFile type=\"PolyData\"><PolyData/></VTKFile>");
    EXPECT_THAT(message(poly), HasSubstr(poly + ":1: dataset type is 'PolyData'; expected ImageData"));
    const std::string volume = dir.file("volume.vti");
    test::writeText(volume, "<VTKFile type=\"ImageData\"><ImageData WholeExtent=\"0 1 0 1 0 3\"/></VTKFile>");
    EXPECT_THAT(message(volume), HasSubstr("not a 2-D image"));
    // Truncated appended data: the shared decoder names file, line and array.
    writeVti(dir.file("ok.vti"), *sample(), perspective());
    std::string text = test::readText(dir.file("ok.vti"));
    const std::string cut = dir.file("cut.vti");
    test::writeText(cut, text.substr(0, text.size() - 200));
    EXPECT_THAT(message(cut), HasSubstr(cut));
}
