// Scanning a scene's time series (darkroom/scene/time_series.h) and loading
// one step of it: how steps are timed, ordered and matched, framing on given
// bounds, and the errors for series the loader of one scene cannot take.
#include "mesh_test_files.h"
#include "test_support.h"

#include <darkroom/error.h>
#include <darkroom/scene/scene_file.h>
#include <darkroom/scene/time_series.h>

#include <gtest/gtest.h>

#include <filesystem>

using namespace darkroom;
using darkroom::test::expectError;

namespace {

// A tetrahedron scaled by `size`.
void writeTetra(const std::string& path, double size) {
    const std::string s = std::to_string(size);
    test::writeText(path, "v 0 0 0\nv " + s + " 0 0\nv 0 " + s + " 0\nv 0 0 " + s + "\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n");
}

std::string sceneWith(const std::string& object) {
    return "objects:\n" + object + "  - generator: particles\n    parameters: {count: 10}\ncameras:\n  grid: {phi: 2}\n";
}

}  // namespace

TEST(TimeSeries, GlobStepsAreTimedAndOrderedByTheNumberInTheirNames) {
    test::TempDir dir;
    writeTetra(dir.file("t10.obj"), 3);
    writeTetra(dir.file("t0.5.obj"), 1);
    writeTetra(dir.file("t1.5.obj"), 2);
    test::writeText(dir.file("s.yaml"), sceneWith("  - file: t*.obj\n"));
    const SceneSeries series = scanSceneSeries(dir.file("s.yaml"));
    ASSERT_EQ(series.columns, std::vector<std::string>{"time"});
    ASSERT_EQ(series.steps.size(), 3u);
    const double times[] = {0.5, 1.5, 10};
    const char* files[] = {"t0.5.obj", "t1.5.obj", "t10.obj"};
    for (int i = 0; i < 3; ++i) {
        EXPECT_EQ(series.steps[i].values.at(0).number(), times[i]);
        EXPECT_EQ(std::filesystem::path(series.steps[i].files.at(0)).filename(), files[i]);
        EXPECT_EQ(series.steps[i].files.size(), 1u);  // the particles are static
    }
    EXPECT_FALSE(series.framePerStep);
}

TEST(TimeSeries, AStepIsFramedOnTheGivenBoundsNotItsOwn) {
    test::TempDir dir;
    writeTetra(dir.file("small.obj"), 1);
    test::writeText(dir.file("s.yaml"), sceneWith("  - file: t*.obj\n"));
    SceneLoadOptions own;
    own.stepFiles[0] = dir.file("small.obj");
    SceneLoadOptions framed = own;
    framed.framing = Bounds{{-10, -10, -10}, {10, 10, 10}};
    const SceneDescription a = loadSceneFile(dir.file("s.yaml"), own);
    const SceneDescription b = loadSceneFile(dir.file("s.yaml"), framed);
    const double distance = length(b.cameras[0].camera.position);  // the framing's centre is the origin
    EXPECT_NEAR(distance, fittingDistance(b.cameras[0].camera, std::sqrt(300.0)), 1e-9);
    EXPECT_LT(length(a.cameras[0].camera.position - a.scene->bounds().center()), distance / 2);
}

TEST(TimeSeries, LoadingASeriesAsOneSceneIsRefused) {
    test::TempDir dir;
    writeTetra(dir.file("t1.obj"), 1);
    test::writeText(dir.file("s.yaml"), sceneWith("  - file: t*.obj\n"));
    expectError([&] { loadSceneFile(dir.file("s.yaml")); },
                {"s.yaml:2:11", "'t*.obj' is a time series", "`darkroom capture` captures it step by step"});
}

TEST(TimeSeries, KeysThatDoNotFitAreRefused) {
    test::TempDir dir;
    writeTetra(dir.file("t1.obj"), 1);
    test::writeText(dir.file("s.yaml"), sceneWith("  - file: t1.obj\n    time: [1]\n"));
    expectError([&] { loadSceneFile(dir.file("s.yaml")); }, {"s.yaml:3:11", "'time' only applies to a time series"});
    test::writeText(dir.file("s.yaml"), sceneWith("  - file: t1.obj\n") + "  framing: zoom\n");
    expectError([&] { loadSceneFile(dir.file("s.yaml")); }, {"framing must be series", "or step"});
    test::writeText(dir.file("s.yaml"), sceneWith("  - file: t*.obj\n    time: [1, 2]\n"));
    expectError([&] { scanSceneSeries(dir.file("s.yaml")); },
                {"object 't*'", "'time' lists 2 values but", "matches 1 files"});
}

TEST(TimeSeries, ADatabaseWithoutAFileColumnIsRefusedNamingItsCsv) {
    test::TempDir dir;
    std::filesystem::create_directories(dir.file("run.cdb"));
    test::writeText(dir.file("run.cdb/data.csv"), "time,value\n0,1\n1,2\n");
    test::writeText(dir.file("s.yaml"), sceneWith("  - file: run.cdb\n"));
    expectError([&] { scanSceneSeries(dir.file("s.yaml")); },
                {"s.yaml:2:11: object 'run'", "run.cdb/data.csv: no FILE column", "expected one FILE column"});
}
