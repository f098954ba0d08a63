// The image-space camera of sdk/depth_input.h, as docs/cameras.md states it:
// pixel centres and depth map to world positions by the documented formula,
// and Automatic reads depth within [0, 1] as normalised, other depth as raw
// distances with a view as high as their range.
#include "test_support.h"

#include <darkroom/depth_input.h>
#include <darkroom/error.h>
#include <gtest/gtest.h>

#include <filesystem>

#include <limits>
#include <vector>

using namespace darkroom;

namespace {
const float kInf = std::numeric_limits<float>::infinity();
}

TEST(ImageSpaceCamera, MapsPixelCentresAndDepthAsDocumented) {
    const int w = 8, h = 4;
    const double H = 2.0;
    const Camera c = imageSpaceCamera(w, h, H);
    EXPECT_EQ(c.projection, Camera::Projection::Orthographic);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const double z = 0.25 + 0.1 * x;
            const Vec3 p = c.worldPosition(x + 0.5, y + 0.5, z);
            EXPECT_NEAR(p.x, (x + 0.5 - w / 2.0) * H / h, 1e-12);
            EXPECT_NEAR(p.y, (h / 2.0 - y - 0.5) * H / h, 1e-12);
            EXPECT_NEAR(p.z, -z, 1e-12);
            EXPECT_NEAR(c.depthOf(p), z, 1e-12);
        }
    EXPECT_NEAR(c.pixelSizeAt(123.0), H / h, 1e-12);
}

TEST(ImageSpaceCamera, AutomaticTellsNormalisedFromRawDepth) {
    const std::vector<float> normalised{0.2f, 0.7f, kInf, 0.4f};
    const ImageSpaceView n = assumeImageSpace(normalised.data(), 2, 2, DepthWithoutCamera::Automatic);
    EXPECT_TRUE(n.normalised);
    EXPECT_DOUBLE_EQ(n.camera.viewHeight, 1.0);

    const std::vector<float> raw{2.0f, 7.0f, kInf, 4.0f};
    const ImageSpaceView r = assumeImageSpace(raw.data(), 2, 2, DepthWithoutCamera::Automatic);
    EXPECT_FALSE(r.normalised);
    EXPECT_DOUBLE_EQ(r.camera.viewHeight, 5.0);  // 7 - 2
    EXPECT_NE(r.describe().find("Z from 2 to 7"), std::string::npos) << r.describe();

    // Forced either way; a flat raw image (no range) keeps a unit view.
    EXPECT_DOUBLE_EQ(assumeImageSpace(raw.data(), 2, 2, DepthWithoutCamera::Normalised).camera.viewHeight, 1.0);
    EXPECT_NEAR(assumeImageSpace(normalised.data(), 2, 2, DepthWithoutCamera::Raw).camera.viewHeight, 0.5, 1e-6);
    const std::vector<float> flat(4, 3.0f);
    EXPECT_DOUBLE_EQ(assumeImageSpace(flat.data(), 2, 2, DepthWithoutCamera::Raw).camera.viewHeight, 1.0);
}

TEST(ImageSpaceCamera, AnImageWithItsOwnCameraKeepsIt) {
    auto b = test::makeImage(4, 2, {"Z"}, [](int, int, int) { return 5.0f; });
    Camera own;
    own.fovYDegrees = 40;
    b->metadata().camera = own;
    std::string assumption;
    const Camera c = cameraOrImageSpace(*b, b->requireFloat("Z"), DepthWithoutCamera::Automatic, &assumption);
    EXPECT_EQ(c.projection, Camera::Projection::Perspective);
    EXPECT_EQ(c.width, 4);
    EXPECT_TRUE(assumption.empty());
}

TEST(ImageSpaceCamera, MissingDepthNamesTheFileOrDatabase) {
    // The database is the folder holding data.csv above the product,
    // whatever its name.
    test::TempDir dir;
    std::filesystem::create_directories(dir.file("extract"));
    test::writeText(dir.file("extract/data.csv"), "phi,FILE\n0,image/0.png\n");
    auto b = test::makeImage(2, 2, {"Elevation"}, [](int, int, int) { return 1.0f; });
    b->metadata().attributes["source"] = dir.file("extract/image/0.png");
    EXPECT_EQ(missingDepthMessage(*b).rfind("database " + dir.file("extract") + " stores no depth (channels: Elevation)",
                                            0),
              0u)
        << missingDepthMessage(*b);
    b->metadata().attributes["source"] = "/x/picture.png";
    EXPECT_EQ(missingDepthMessage(*b).rfind("/x/picture.png stores no depth", 0), 0u);
    EXPECT_THROW(requireDepth(*b), Error);
}
