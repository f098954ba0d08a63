// A database holds products of one kind (issue 26, D6): a resumed session
// whose image size, projection, cameras or channels differ from what made
// the database is refused, naming what differs; and a session's setup is
// fixed once it has captured, so no call in mid-session mixes products.
#include "test_support.h"

#include <darkroom/data/image_io.h>
#include <darkroom/insitu.h>

#include <gtest/gtest.h>

#include <functional>
#include <string>
#include <vector>

namespace darkroom::test {
namespace {

const double kAt[3] = {0, 0, 5}, kTo[3] = {0, 0, 0}, kUp[3] = {0, 1, 0};

// One session on `db`: `setup` configures it (after the defaults below),
// then step `time` (a sphere) is captured. Returns the capture's status and
// error.
std::pair<int, std::string> session(const std::string& db, int mode, double time,
                                    const std::function<void(darkroom_insitu*)>& setup = {}) {
    std::vector<float> sphere = {0.0f, 0.0f, 0.0f, 0.5f};
    darkroom_insitu* s = darkroom_insitu_open(db.c_str(), mode);
    darkroom_insitu_set_image(s, 8, 8, 30.0, 0.0);
    if (setup) setup(s);
    if (darkroom_insitu_add_camera(s, kAt, kTo, kUp) != DARKROOM_INSITU_OK) ADD_FAILURE() << darkroom_insitu_error(s);
    darkroom_insitu_begin_step(s, time);
    darkroom_insitu_points(s, "ball", sphere.data(), 16, 1, nullptr, 0.0f);
    const int code = darkroom_insitu_capture(s);
    const std::string error = darkroom_insitu_error(s);
    darkroom_insitu_close(s);
    return {code, error};
}

void expectResumeRefused(const std::function<void(darkroom_insitu*)>& change, const std::vector<std::string>& parts) {
    TempDir dir;
    const std::string db = dir.file("db.cdb");
    ASSERT_EQ(session(db, DARKROOM_INSITU_CREATE, 0.0).first, DARKROOM_INSITU_OK);
    const std::string before = readText(db + "/data.csv");
    const auto [code, error] = session(db, DARKROOM_INSITU_RESUME, 1.0, change);
    EXPECT_EQ(code, DARKROOM_INSITU_FAILED) << error;
    EXPECT_NE(error.find("cannot resume"), std::string::npos) << error;
    for (const auto& p : parts) EXPECT_NE(error.find(p), std::string::npos) << "'" << p << "' not in: " << error;
    // Said the way the API spells it, not the command line's --overwrite.
    EXPECT_EQ(error.find("--overwrite"), std::string::npos) << error;
    EXPECT_NE(error.find("use DARKROOM_INSITU_OVERWRITE to start afresh"), std::string::npos) << error;
    EXPECT_EQ(readText(db + "/data.csv"), before);
}

TEST(InSituSessionState, AResumeWithAnotherImageSizeIsRefusedNamingIt) {
    expectResumeRefused([](darkroom_insitu* s) { darkroom_insitu_set_image(s, 16, 8, 30.0, 0.0); },
                        {"resolution 8x8 \u2192 16x8"});
}

TEST(InSituSessionState, AResumeWithOtherChannelsIsRefusedNamingThem) {
    expectResumeRefused([](darkroom_insitu* s) { darkroom_insitu_request_field(s, "temperature"); },
                        {"channels depth only \u2192 temperature"});
    expectResumeRefused([](darkroom_insitu* s) { darkroom_insitu_set_half_float(s, 1); }, {"half floats no \u2192 yes"});
}

TEST(InSituSessionState, AResumeWithAnotherProjectionOrOtherCamerasIsRefused) {
    expectResumeRefused([](darkroom_insitu* s) { darkroom_insitu_set_image(s, 8, 8, 40.0, 0.0); },
                        {"projection perspective, fov 30 \u2192 perspective, fov 40"});
    const double elsewhere[3] = {0, 5, 0}, upZ[3] = {0, 0, 1};
    expectResumeRefused([&](darkroom_insitu* s) { darkroom_insitu_add_camera(s, elsewhere, kTo, upZ); },
                        {"cameras a list of 1 \u2192 a list of 2"});
}

TEST(InSituSessionState, AResumeWithTheSameSetupCompletesTheDatabase) {
    TempDir dir;
    const std::string db = dir.file("db.cdb");
    ASSERT_EQ(session(db, DARKROOM_INSITU_CREATE, 0.0).first, DARKROOM_INSITU_OK);
    const auto [code, error] = session(db, DARKROOM_INSITU_RESUME, 1.0);
    EXPECT_EQ(code, DARKROOM_INSITU_OK) << error;
    EXPECT_NE(readText(db + "/data.csv").find("1,0,time=1_camera=0.exr"), std::string::npos);
}

TEST(InSituSessionState, TheSetupIsFixedAfterTheFirstCapture) {
    TempDir dir;
    const std::string db = dir.file("db.cdb");
    std::vector<float> sphere = {0.0f, 0.0f, 0.0f, 0.5f};
    darkroom_insitu* s = darkroom_insitu_open(db.c_str(), DARKROOM_INSITU_CREATE);
    ASSERT_EQ(darkroom_insitu_set_image(s, 8, 8, 30.0, 0.0), DARKROOM_INSITU_OK);
    ASSERT_EQ(darkroom_insitu_add_camera(s, kAt, kTo, kUp), DARKROOM_INSITU_OK);
    auto step = [&](double time) {
        darkroom_insitu_begin_step(s, time);
        darkroom_insitu_points(s, "ball", sphere.data(), 16, 1, nullptr, 0.0f);
        return darkroom_insitu_capture(s);
    };
    ASSERT_EQ(step(0.0), DARKROOM_INSITU_OK) << darkroom_insitu_error(s);

    const double phi[1] = {0};
    const struct {
        int code;
        const char* call;
    } refused[] = {
        {darkroom_insitu_set_image(s, 16, 16, 30.0, 0.0), "darkroom_insitu_set_image"},
        {darkroom_insitu_request_field(s, "temperature"), "darkroom_insitu_request_field"},
        {darkroom_insitu_request_normals(s, 1), "darkroom_insitu_request_normals"},
        {darkroom_insitu_request_ids(s, 1, 0), "darkroom_insitu_request_ids"},
        {darkroom_insitu_set_half_float(s, 1), "darkroom_insitu_set_half_float"},
        {darkroom_insitu_add_camera(s, kTo, kAt, kUp), "darkroom_insitu_add_camera"},
        {darkroom_insitu_camera_orbit(s, kTo, 5.0, kUp, phi, 1, phi, 1), "darkroom_insitu_camera_orbit"},
    };
    for (const auto& r : refused) EXPECT_EQ(r.code, DARKROOM_INSITU_BAD_INPUT) << r.call;
    EXPECT_EQ(darkroom_insitu_set_image(s, 16, 16, 30.0, 0.0), DARKROOM_INSITU_BAD_INPUT);
    const std::string error = darkroom_insitu_error(s);
    EXPECT_NE(error.find("darkroom_insitu_set_image: the session's setup is fixed after its first capture"),
              std::string::npos)
        << error;
    // Threads change how fast, not what is written.
    EXPECT_EQ(darkroom_insitu_set_threads(s, 1), DARKROOM_INSITU_OK);

    ASSERT_EQ(step(1.0), DARKROOM_INSITU_OK) << darkroom_insitu_error(s);
    ASSERT_EQ(darkroom_insitu_close(s), DARKROOM_INSITU_OK);
    for (const char* file : {"/time=0_camera=0.exr", "/time=1_camera=0.exr"}) {
        const auto image = readImage(db + file);
        EXPECT_EQ(image->width(), 8) << file;
        EXPECT_EQ(image->channels().size(), 1u) << file << ": depth only";
    }
}

TEST(InSituSessionState, ARefusedFirstCaptureDoesNotFixTheSetup) {
    TempDir dir;
    darkroom_insitu* s = darkroom_insitu_open(dir.file("db.cdb").c_str(), DARKROOM_INSITU_CREATE);
    // No step yet: the capture is refused and the setup may still change.
    ASSERT_EQ(darkroom_insitu_add_camera(s, kAt, kTo, kUp), DARKROOM_INSITU_OK);
    EXPECT_EQ(darkroom_insitu_capture(s), DARKROOM_INSITU_BAD_INPUT);
    EXPECT_EQ(darkroom_insitu_set_image(s, 16, 16, 30.0, 0.0), DARKROOM_INSITU_OK) << darkroom_insitu_error(s);
    EXPECT_EQ(darkroom_insitu_request_field(s, "temperature"), DARKROOM_INSITU_OK) << darkroom_insitu_error(s);
    darkroom_insitu_close(s);
}

}  // namespace
}  // namespace darkroom::test
