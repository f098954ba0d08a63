// Every argument of the in situ API is checked (issue 26, C1): values that
// used to end in Embree's assertion abort inside darkroom_insitu_capture
// (cameras a million scene radii away, non-finite targets, absurd view
// heights) and values the API took silently (huge strides, negative or NaN
// radii, names with line breaks) are refused with DARKROOM_INSITU_BAD_INPUT
// and a one-line message; the simulation goes on.
#include "test_support.h"

#include <darkroom/insitu.h>

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <limits>
#include <string>
#include <vector>

namespace darkroom::test {
namespace {

const double kNaN = std::numeric_limits<double>::quiet_NaN();
const double kInf = std::numeric_limits<double>::infinity();

// A session with one sphere of radius 0.5 at the origin in step 0, ready to capture.
struct Ball {
    TempDir dir;
    std::vector<float> sphere = {0.0f, 0.0f, 0.0f, 0.5f};
    darkroom_insitu* s = darkroom_insitu_open(dir.file("db.cdb").c_str(), DARKROOM_INSITU_CREATE);
    Ball() { darkroom_insitu_set_image(s, 8, 8, 30.0, 0.0); }
    ~Ball() { darkroom_insitu_close(s); }
    int capture() {
        darkroom_insitu_begin_step(s, 0.0);
        darkroom_insitu_points(s, "ball", sphere.data(), 16, 1, nullptr, 0.0f);
        return darkroom_insitu_capture(s);
    }
    std::string error() const { return darkroom_insitu_error(s); }
    bool wroteNothing() const { return !std::filesystem::exists(dir.file("db.cdb")); }
};

const double kOrigin[3] = {0, 0, 0}, kUp[3] = {0, 0, 1}, kAngle[1] = {0};

void expectRefusedCapture(Ball& b, const std::vector<std::string>& parts) {
    EXPECT_EQ(b.capture(), DARKROOM_INSITU_BAD_INPUT) << b.error();
    const std::string e = b.error();
    EXPECT_EQ(e.find("darkroom_insitu_capture"), 0u) << e;
    for (const auto& p : parts) EXPECT_NE(e.find(p), std::string::npos) << "'" << p << "' not in: " << e;
    EXPECT_EQ(e.find('\n'), std::string::npos) << e;
    EXPECT_TRUE(b.wroteNothing());
}

TEST(InSituArguments, AnOrbitFarBeyondTheSceneIsRefusedAtCaptureNotAborted) {
    Ball b;
    // Finite and positive: whether 1e20 is too far depends on the data.
    ASSERT_EQ(darkroom_insitu_camera_orbit(b.s, kOrigin, 1e20, kUp, kAngle, 1, kAngle, 1), DARKROOM_INSITU_OK);
    expectRefusedCapture(b, {"distance 1e+20 is too far", "within 1e+06 scene radii (radius 0.866025)"});
}

TEST(InSituArguments, AnOrbitTargetFarBeyondTheSceneIsRefusedAtCapture) {
    Ball b;
    const double target[3] = {1e300, 0, 0};
    ASSERT_EQ(darkroom_insitu_camera_orbit(b.s, target, 3.0, kUp, kAngle, 1, kAngle, 1), DARKROOM_INSITU_OK);
    expectRefusedCapture(b, {"target [1e+300, 0, 0] is too far from the scene"});
}

TEST(InSituArguments, AListedCameraFarBeyondTheSceneIsRefusedAtCapture) {
    Ball b;
    const double at[3] = {0, 0, 1e20};
    const double up[3] = {0, 1, 0};
    ASSERT_EQ(darkroom_insitu_add_camera(b.s, at, kOrigin, up), DARKROOM_INSITU_OK);
    expectRefusedCapture(b, {"camera 0", "position [0, 0, 1e+20] is too far from the scene"});
}

TEST(InSituArguments, AnOrthographicHeightOutOfProportionIsRefusedAtCapture) {
    Ball b;
    ASSERT_EQ(darkroom_insitu_set_image(b.s, 8, 8, 0.0, 1e300), DARKROOM_INSITU_OK);
    ASSERT_EQ(darkroom_insitu_camera_orbit(b.s, kOrigin, 3.0, kUp, kAngle, 1, kAngle, 1), DARKROOM_INSITU_OK);
    expectRefusedCapture(b, {"height 1e+300 is out of proportion to the scene"});
}

TEST(InSituArguments, CamerasBeyondSinglePrecisionAreRefusedWhateverTheDataSize) {
    // A sphere of radius 1e14: a camera at 1e19 lies within 10^6 radii, but
    // Embree refuses (asserts on) rays from beyond 1.8e18.
    Ball b;
    b.sphere[3] = 1e14f;
    ASSERT_EQ(darkroom_insitu_camera_orbit(b.s, kOrigin, 1e19, kUp, kAngle, 1, kAngle, 1), DARKROOM_INSITU_OK);
    expectRefusedCapture(b, {"phi=0, theta=0", "position", "beyond 1e+18 world units"});
    // An orthographic view's rays start across its extent.
    Ball o;
    o.sphere[3] = 1e14f;
    ASSERT_EQ(darkroom_insitu_set_image(o.s, 8, 8, 0.0, 1e19), DARKROOM_INSITU_OK);
    ASSERT_EQ(darkroom_insitu_camera_orbit(o.s, kOrigin, 1e15, kUp, kAngle, 1, kAngle, 1), DARKROOM_INSITU_OK);
    expectRefusedCapture(o, {"beyond 1e+18 world units", "view's half extent"});
}

TEST(InSituArguments, AStepWithoutObjectsIsCheckedOnlyAgainstTheFloatReach) {
    // No particles yet: nothing says where the data lie, so a camera far
    // from the origin (where they will be) is not refused; one beyond a
    // float's reach still is.
    Ball b;
    const double far[3] = {1e9, 0, 0}, at[3] = {1e9, 0, 5}, up[3] = {0, 1, 0};
    ASSERT_EQ(darkroom_insitu_add_camera(b.s, at, far, up), DARKROOM_INSITU_OK);
    ASSERT_EQ(darkroom_insitu_begin_step(b.s, 0.0), DARKROOM_INSITU_OK);
    ASSERT_EQ(darkroom_insitu_points(b.s, "tracers", nullptr, 16, 0, nullptr, 0.0f), DARKROOM_INSITU_OK);
    EXPECT_EQ(darkroom_insitu_capture(b.s), DARKROOM_INSITU_OK) << b.error();
    Ball c;
    const double beyond[3] = {1e19, 0, 0}, beyondAt[3] = {1e19, 0, 5};
    ASSERT_EQ(darkroom_insitu_add_camera(c.s, beyondAt, beyond, up), DARKROOM_INSITU_OK);
    ASSERT_EQ(darkroom_insitu_begin_step(c.s, 0.0), DARKROOM_INSITU_OK);
    EXPECT_EQ(darkroom_insitu_capture(c.s), DARKROOM_INSITU_BAD_INPUT);
    EXPECT_NE(c.error().find("beyond 1e+18 world units"), std::string::npos) << c.error();
}

TEST(InSituArguments, ARefusedCaptureLeavesTheSessionUsable) {
    Ball b;
    ASSERT_EQ(darkroom_insitu_set_image(b.s, 8, 8, 0.0, 1e300), DARKROOM_INSITU_OK);
    ASSERT_EQ(darkroom_insitu_camera_orbit(b.s, kOrigin, 3.0, kUp, kAngle, 1, kAngle, 1), DARKROOM_INSITU_OK);
    ASSERT_EQ(b.capture(), DARKROOM_INSITU_BAD_INPUT);
    // A height in proportion, and the same step captures.
    ASSERT_EQ(darkroom_insitu_set_image(b.s, 8, 8, 0.0, 2.0), DARKROOM_INSITU_OK);
    ASSERT_EQ(b.capture(), DARKROOM_INSITU_OK) << b.error();
    EXPECT_EQ(darkroom_insitu_rows_written(b.s), 1);
}

TEST(InSituArguments, NonFiniteCameraValuesAreRefusedAtTheCall) {
    Ball b;
    const double nan3[3] = {kNaN, 0, 0}, inf3[3] = {0, kInf, 0}, at[3] = {0, 0, 3}, upY[3] = {0, 1, 0};
    const struct {
        int code;
        const char* part;
    } cases[] = {
        {darkroom_insitu_camera_orbit(b.s, nan3, 3.0, kUp, kAngle, 1, kAngle, 1), "target"},
        {darkroom_insitu_camera_orbit(b.s, inf3, 3.0, kUp, kAngle, 1, kAngle, 1), "target"},
        {darkroom_insitu_camera_orbit(b.s, kOrigin, 3.0, nan3, kAngle, 1, kAngle, 1), "up"},
        {darkroom_insitu_camera_orbit(b.s, kOrigin, kNaN, kUp, kAngle, 1, kAngle, 1), "distance"},
        {darkroom_insitu_add_camera(b.s, nan3, kOrigin, upY), "position"},
        {darkroom_insitu_add_camera(b.s, at, inf3, upY), "target"},
        {darkroom_insitu_add_camera(b.s, at, kOrigin, inf3), "up"},
    };
    for (const auto& c : cases) {
        EXPECT_EQ(c.code, DARKROOM_INSITU_BAD_INPUT) << c.part;
    }
    // Each message names the argument: checked one at a time.
    EXPECT_EQ(darkroom_insitu_camera_orbit(b.s, nan3, 3.0, kUp, kAngle, 1, kAngle, 1), DARKROOM_INSITU_BAD_INPUT);
    EXPECT_NE(b.error().find("darkroom_insitu_camera_orbit: target [nan, 0, 0] must be finite"), std::string::npos)
        << b.error();
    EXPECT_EQ(darkroom_insitu_add_camera(b.s, at, kOrigin, inf3), DARKROOM_INSITU_BAD_INPUT);
    EXPECT_NE(b.error().find("darkroom_insitu_add_camera: up [0, inf, 0] must be finite"), std::string::npos)
        << b.error();
    // Nothing was added by the refused calls: a first orbit is still accepted.
    EXPECT_EQ(darkroom_insitu_camera_orbit(b.s, kOrigin, 3.0, kUp, kAngle, 1, kAngle, 1), DARKROOM_INSITU_OK) << b.error();
}

TEST(InSituArguments, FieldsOfViewAreBoundedAsInSceneFiles) {
    Ball b;
    for (double fov : {1e-300, 179.99999, -1.0, kNaN, kInf}) {
        EXPECT_EQ(darkroom_insitu_set_image(b.s, 8, 8, fov, 0.0), DARKROOM_INSITU_BAD_INPUT) << fov;
        EXPECT_NE(b.error().find("fov must lie in [0.001, 179.999] degrees"), std::string::npos) << b.error();
    }
    for (double height : {0.0, -1.0, kNaN, kInf}) {
        EXPECT_EQ(darkroom_insitu_set_image(b.s, 8, 8, 0.0, height), DARKROOM_INSITU_BAD_INPUT) << height;
    }
    EXPECT_EQ(darkroom_insitu_set_image(b.s, 8, 8, 0.001, 0.0), DARKROOM_INSITU_OK);
    EXPECT_EQ(darkroom_insitu_set_image(b.s, 8, 8, 179.999, 0.0), DARKROOM_INSITU_OK);
}

TEST(InSituArguments, HugeStridesAreRefused) {
    Ball b;
    ASSERT_EQ(darkroom_insitu_begin_step(b.s, 0.0), DARKROOM_INSITU_OK);
    float v[12] = {};
    const std::uint32_t tri[3] = {0, 1, 2}, seg[1] = {0};
    const std::size_t huge = std::size_t(1) << 40;
    EXPECT_EQ(darkroom_insitu_triangles(b.s, "t", v, huge, 3, tri, 1), DARKROOM_INSITU_BAD_INPUT);
    EXPECT_NE(b.error().find("1099511627776 bytes apart"), std::string::npos) << b.error();
    EXPECT_EQ(darkroom_insitu_lines(b.s, "l", v, huge, 2, seg, 1, nullptr, 0.1f), DARKROOM_INSITU_BAD_INPUT);
    EXPECT_EQ(darkroom_insitu_points(b.s, "p", v, huge, 1, nullptr, 0.1f), DARKROOM_INSITU_BAD_INPUT);
    EXPECT_EQ(darkroom_insitu_points(b.s, "p", v, std::size_t(-4), 1, nullptr, 0.1f), DARKROOM_INSITU_BAD_INPUT);
}

TEST(InSituArguments, NegativeOrNaNRadiiAreRefused) {
    Ball b;
    ASSERT_EQ(darkroom_insitu_begin_step(b.s, 0.0), DARKROOM_INSITU_OK);
    const float nan = std::numeric_limits<float>::quiet_NaN();
    // x, y, z records (12 bytes) with the constant radius.
    const float xyz[6] = {0, 0, 0, 1, 0, 0};
    const std::uint32_t seg[1] = {0};
    EXPECT_EQ(darkroom_insitu_points(b.s, "p", xyz, 12, 2, nullptr, -1.0f), DARKROOM_INSITU_BAD_INPUT);
    EXPECT_EQ(darkroom_insitu_points(b.s, "p", xyz, 12, 2, nullptr, nan), DARKROOM_INSITU_BAD_INPUT);
    // The constant is checked even when records carry the radii.
    const float xyzr[8] = {0, 0, 0, 0.1f, 1, 0, 0, 0.1f};
    EXPECT_EQ(darkroom_insitu_points(b.s, "p", xyzr, 16, 2, nullptr, -1.0f), DARKROOM_INSITU_BAD_INPUT);
    EXPECT_NE(b.error().find("radius -1"), std::string::npos) << b.error();
    // Radii in their own array, and in the records.
    const float radii[2] = {0.1f, -0.5f};
    EXPECT_EQ(darkroom_insitu_points(b.s, "p", xyz, 12, 2, radii, 0.0f), DARKROOM_INSITU_BAD_INPUT);
    EXPECT_NE(b.error().find("vertex 1 has radius -0.5"), std::string::npos) << b.error();
    const float nanRecords[8] = {0, 0, 0, 0.1f, 1, 0, 0, nan};
    EXPECT_EQ(darkroom_insitu_lines(b.s, "l", nanRecords, 16, 2, seg, 1, nullptr, 0.0f), DARKROOM_INSITU_BAD_INPUT);
    EXPECT_NE(b.error().find("vertex 1 has radius nan"), std::string::npos) << b.error();
    // A refused call declares nothing: the names are free.
    EXPECT_EQ(darkroom_insitu_points(b.s, "p", xyzr, 16, 2, nullptr, 0.0f), DARKROOM_INSITU_OK) << b.error();
    EXPECT_EQ(darkroom_insitu_lines(b.s, "l", xyzr, 16, 2, seg, 1, nullptr, 0.0f), DARKROOM_INSITU_OK) << b.error();
}

TEST(InSituArguments, AnObjectWithoutElementsNeedsNoArrays) {
    // As a rank without a part of an object declares it (docs/insitu.md,
    // "With MPI"). Its radii were once read at NULL + 12 (UBSan, found by
    // the fuzz harness; tests/fuzz/corpus/insitu/empty-part.txt).
    Ball b;
    const double at[3] = {0, 0, 3}, up[3] = {0, 1, 0};
    ASSERT_EQ(darkroom_insitu_add_camera(b.s, at, kOrigin, up), DARKROOM_INSITU_OK);
    ASSERT_EQ(darkroom_insitu_begin_step(b.s, 0.0), DARKROOM_INSITU_OK);
    EXPECT_EQ(darkroom_insitu_points(b.s, "p", nullptr, 16, 0, nullptr, 0.0f), DARKROOM_INSITU_OK) << b.error();
    EXPECT_EQ(darkroom_insitu_lines(b.s, "l", nullptr, 16, 0, nullptr, 0, nullptr, 0.0f), DARKROOM_INSITU_OK) << b.error();
    EXPECT_EQ(darkroom_insitu_triangles(b.s, "t", nullptr, 0, 0, nullptr, 0), DARKROOM_INSITU_OK) << b.error();
    EXPECT_EQ(darkroom_insitu_capture(b.s), DARKROOM_INSITU_OK) << b.error();
    EXPECT_EQ(darkroom_insitu_rows_written(b.s), 1);
}

TEST(InSituArguments, NamesWithLineBreaksOrControlCharactersAreRefused) {
    Ball b;
    ASSERT_EQ(darkroom_insitu_begin_step(b.s, 0.0), DARKROOM_INSITU_OK);
    const float xyzr[4] = {0, 0, 0, 0.5f};
    const float value[1] = {1};
    EXPECT_EQ(darkroom_insitu_points(b.s, "a\nb", xyzr, 16, 1, nullptr, 0.0f), DARKROOM_INSITU_BAD_INPUT);
    EXPECT_NE(b.error().find("a control character"), std::string::npos) << b.error();
    EXPECT_EQ(b.error().find('\n'), std::string::npos) << b.error();
    EXPECT_EQ(darkroom_insitu_request_field(b.s, "t\x01"), DARKROOM_INSITU_BAD_INPUT);
    ASSERT_EQ(darkroom_insitu_points(b.s, "ball", xyzr, 16, 1, nullptr, 0.0f), DARKROOM_INSITU_OK);
    EXPECT_EQ(darkroom_insitu_field(b.s, "ball", "t\r", value, 1, DARKROOM_INSITU_POINT_DATA), DARKROOM_INSITU_BAD_INPUT);
    // A session on a path with a line break is refused at once.
    darkroom_insitu* bad = darkroom_insitu_open(b.dir.file("a\nb.cdb").c_str(), DARKROOM_INSITU_CREATE);
    EXPECT_EQ(darkroom_insitu_begin_step(bad, 0.0), DARKROOM_INSITU_BAD_INPUT);
    EXPECT_NE(std::string(darkroom_insitu_error(bad)).find("darkroom_insitu_open: the database path"), std::string::npos)
        << darkroom_insitu_error(bad);
    EXPECT_EQ(std::string(darkroom_insitu_error(bad)).find('\n'), std::string::npos);
    darkroom_insitu_close(bad);
}

TEST(InSituArguments, SwitchesAreZeroOrOne) {
    Ball b;
    EXPECT_EQ(darkroom_insitu_request_normals(b.s, 2), DARKROOM_INSITU_BAD_INPUT);
    EXPECT_NE(b.error().find("darkroom_insitu_request_normals: on is 2; expected 0 (off) or 1 (on)"), std::string::npos)
        << b.error();
    EXPECT_EQ(darkroom_insitu_request_ids(b.s, 1, -1), DARKROOM_INSITU_BAD_INPUT);
    EXPECT_EQ(darkroom_insitu_set_half_float(b.s, 7), DARKROOM_INSITU_BAD_INPUT);
    EXPECT_EQ(darkroom_insitu_request_ids(b.s, 1, 1), DARKROOM_INSITU_OK);
}

TEST(InSituArguments, AReportedErrorIsOneLine) {
    // darkroom_insitu_error promises one line, also for a binding's message,
    // and a failure always says something.
    Ball b;
    EXPECT_EQ(darkroom_insitu_report_error(b.s, "array 'x'\nis not contiguous\r"), DARKROOM_INSITU_BAD_INPUT);
    EXPECT_EQ(b.error(), "array 'x' is not contiguous ");
    EXPECT_EQ(darkroom_insitu_report_error(b.s, nullptr), DARKROOM_INSITU_BAD_INPUT);
    EXPECT_EQ(b.error(), "an error without a message (darkroom_insitu_report_error)");
    EXPECT_EQ(darkroom_insitu_report_error(nullptr, "x"), DARKROOM_INSITU_BAD_INPUT);
}

TEST(InSituArguments, ThreadCountsAndAngleCountsAreBounded) {
    Ball b;
    EXPECT_EQ(darkroom_insitu_set_threads(b.s, 1 << 30), DARKROOM_INSITU_BAD_INPUT);
    EXPECT_NE(b.error().find("expected 0 to 4096"), std::string::npos) << b.error();
    EXPECT_EQ(darkroom_insitu_set_threads(b.s, 2), DARKROOM_INSITU_OK);
    // Counts beyond any array a simulation would hand over are refused
    // before the angles are read.
    EXPECT_EQ(darkroom_insitu_camera_orbit(b.s, kOrigin, 3.0, kUp, kAngle, 1 << 30, kAngle, 1),
              DARKROOM_INSITU_BAD_INPUT);
    EXPECT_NE(b.error().find("phi_count"), std::string::npos) << b.error();
}

}  // namespace
}  // namespace darkroom::test
