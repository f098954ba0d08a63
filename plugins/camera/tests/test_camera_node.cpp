// Camera: ParaView's camera values become the buffer's camera (checked by
// reconstructing known world points), TTK's normalised depth becomes
// distances, everything else passes through, bad values are named.
#include "test_support.h"

#include <darkroom/error.h>
#include <darkroom/core/run_filter.h>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <numbers>

using namespace darkroom;
using ::testing::HasSubstr;

namespace {

using Inputs = std::map<std::string, std::vector<Value>>;
const float kInf = std::numeric_limits<float>::infinity();

FilterRunResult run(Inputs inputs) {
    auto f = test::pluginRegistry().createFilter("Camera");
    FilterRunOptions o;
    o.threads = 2;
    o.nodeType = "Camera";
    return runFilter(*f, inputs, o);
}

BufferPtr runImage(Inputs inputs) { return run(std::move(inputs)).outputs.at("image").asImage(); }

std::string errorOf(Inputs inputs) {
    try {
        run(std::move(inputs));
    } catch (const Error& e) {
        return e.what();
    }
    return "no error";
}

BufferPtr depthImage(int w, int h, float value) {
    return test::makeImage(w, h, {"Z", "value"}, [=](int x, int, int c) { return c == 0 ? value : float(x); });
}

}  // namespace

TEST(CameraNode, PerspectiveValuesReconstructTheFocalPointAndTheFrustum) {
    const auto out = runImage({{"image", {Value(depthImage(64, 48, 5.f))}},
                               {"position", {Value(Vec3{1, 2, 8})}},
                               {"focalPoint", {Value(Vec3{1, 2, 3})}},
                               {"viewUp", {Value(Vec3{0, 3, 0})}},
                               {"viewAngle", {Value(40.0)}}});
    ASSERT_TRUE(out->metadata().camera);
    const Camera& c = *out->metadata().camera;
    EXPECT_EQ(c.width, 64);
    EXPECT_EQ(c.height, 48);
    EXPECT_EQ(c.projection, Camera::Projection::Perspective);
    // The image centre at the focal distance is the focal point.
    const Vec3 centre = c.worldPosition(32, 24, 5);
    EXPECT_NEAR(centre.x, 1, 1e-12);
    EXPECT_NEAR(centre.y, 2, 1e-12);
    EXPECT_NEAR(centre.z, 3, 1e-12);
    // The top edge at depth 5 lies 5 tan(20 deg) above it (vertical view angle, as vtkCamera's).
    EXPECT_NEAR(c.worldPosition(32, 0, 5).y, 2 + 5 * std::tan(20 * std::numbers::pi / 180), 1e-12);
    EXPECT_EQ(out->metadata().attributes.at("camera.source"), "Camera 'runFilter'");
}

TEST(CameraNode, ParallelScaleIsHalfTheViewHeight) {
    const auto out = runImage({{"image", {Value(depthImage(10, 20, 1.f))}},
                               {"position", {Value(Vec3{0, 0, 0})}},
                               {"focalPoint", {Value(Vec3{0, -1, 0})}},
                               {"viewUp", {Value(Vec3{0, 0, 1})}},
                               {"parallelProjection", {Value(true)}},
                               {"parallelScale", {Value(2.5)}}});
    const Camera& c = *out->metadata().camera;
    EXPECT_EQ(c.projection, Camera::Projection::Orthographic);
    EXPECT_DOUBLE_EQ(c.viewHeight, 5.0);
    EXPECT_NEAR(c.worldPosition(5, 0, 3).z, 2.5, 1e-12);   // top edge: +scale along view up
    EXPECT_NEAR(c.worldPosition(5, 0, 3).y, -3.0, 1e-12);  // depth along the view direction
}

TEST(CameraNode, NormalisedDepthBecomesDistanceAndOtherChannelsPassThrough) {
    const std::vector<float> d{0.f, 0.25f, 0.5f, 1.f, kInf, 0.75f};
    auto in = test::makeImage(3, 2, {"Z", "Elevation"}, [&](int x, int y, int c) {
        return c == 0 ? d[std::size_t(y) * 3 + x] : std::sqrt(float(x + 3 * y));
    });
    const auto out = runImage({{"image", {Value(BufferPtr(in))}},
                               {"depth", {Value("normalised")}},
                               {"near", {Value(2.0)}},
                               {"far", {Value(6.0)}}});
    const float* z = out->requireFloat("Z");
    EXPECT_EQ(z[0], 2.f);
    EXPECT_EQ(z[1], 3.f);
    EXPECT_EQ(z[2], 4.f);
    EXPECT_EQ(z[3], kInf);  // TTK's 1.0: no hit
    EXPECT_EQ(z[4], kInf);
    EXPECT_EQ(z[5], 5.f);
    EXPECT_EQ(std::memcmp(out->requireFloat("Elevation"), in->requireFloat("Elevation"), 6 * sizeof(float)), 0);
    EXPECT_THAT(out->metadata().attributes.at("depth.convention"), HasSubstr("near 2 far 6"));
}

TEST(CameraNode, WhenMissingKeepsAnExistingCamera) {
    auto in = test::makeImage(4, 4, {"Z"}, [](int, int, int) { return 1.f; });
    Camera mine;
    mine.position = {9, 9, 9};
    mine.width = mine.height = 4;
    in->metadata().camera = mine;
    const BufferPtr input = in;
    const auto out = runImage({{"image", {Value(input)}}, {"apply", {Value("whenMissing")}}});
    EXPECT_EQ(out.get(), input.get());  // nothing changed, nothing copied
    const auto replaced = runImage({{"image", {Value(input)}}});
    EXPECT_EQ(replaced->metadata().camera->position.z, 1.0);  // the default position
}

TEST(CameraNode, BadValuesAreNamed) {
    const Value img(depthImage(4, 4, 0.5f));
    EXPECT_THAT(errorOf({{"image", {img}}, {"focalPoint", {Value(Vec3{0, 0, 1})}}}),
                HasSubstr("node 'runFilter' (Camera): position and focalPoint must be distinct"));
    EXPECT_THAT(errorOf({{"image", {img}}, {"viewUp", {Value(Vec3{0, 0, 2})}}}),
                HasSubstr("viewUp must be a non-zero vector not parallel to the view direction"));
    EXPECT_THAT(errorOf({{"image", {img}}, {"depth", {Value("normalised")}}, {"near", {Value(3.0)}},
                         {"far", {Value(3.0)}}}),
                HasSubstr("far (3.000000) must be greater than near (3.000000)"));
    EXPECT_THAT(errorOf({{"image", {Value(depthImage(4, 4, 7.f))}}, {"depth", {Value("normalised")}}}),
                HasSubstr("expects Z in [0, 1] (or +inf for background), but pixel (0, 0) holds 7"));
    EXPECT_THAT(errorOf({{"image", {Value(test::makeImage(2, 2, {"R"}, [](int, int, int) { return 0.f; }))}},
                         {"depth", {Value("normalised")}}}),
                HasSubstr("needs a float channel Z; the image has R"));
}
