// Scene files yaml-cpp accepts but capture must refuse before anything is
// traced: alias bombs and recursive aliases, repeated keys, extra documents,
// misspelt keys, and camera values that abort inside Embree (issue 18).
#include "mesh_test_files.h"
#include "test_support.h"

#include <darkroom/scene/scene_file.h>

using namespace darkroom;
using darkroom::test::expectError;

namespace {

const std::string kObjects = "objects:\n  - generator: isosurface\n    parameters: {resolution: 8}\n";

SceneDescription parse(const std::string& yaml) { return parseSceneFile(yaml, "scene.yaml", "."); }

void expectInputError(const std::string& yaml, const std::vector<std::string>& parts) {
    expectError([&] { (void)parse(yaml); }, parts);
    EXPECT_THROW((void)parse(yaml), InputError);
}

}  // namespace

TEST(SceneFileGuard, AliasBombAndRecursiveAliasAreRefused) {
    std::string bomb = kObjects + "cameras:\n  grid:\n    phi: &a [0, 0, 0, 0, 0, 0, 0, 0, 0, 0]\n";
    for (char c = 'b'; c <= 'j'; ++c) {
        bomb += std::string("    x") + c + ": &" + c + " [";
        for (int i = 0; i < 10; ++i) bomb += std::string(i ? ", " : "") + "*" + char(c - 1);
        bomb += "]\n";
    }
    expectInputError(bomb, {"scene.yaml:", "aliases expand to more than"});
    expectInputError(kObjects + "cameras: &c {grid: *c}\n", {"scene.yaml:4:", "recursive alias"});
}

TEST(SceneFileGuard, DuplicateKeysAndSecondDocumentsAreRefused) {
    expectInputError(kObjects + "cameras: {fov: 20, fov: 40}\n", {"scene.yaml:4:", "duplicate key 'fov'"});
    expectInputError(kObjects + "cameras: {}\ncameras: {fov: 40}\n", {"scene.yaml:5:", "duplicate key 'cameras'"});
    expectInputError(kObjects + "---\n" + kObjects, {"scene.yaml:", "second YAML document"});
}

TEST(SceneFileGuard, MisspeltKeysNameTheNearestValidKey) {
    expectInputError(kObjects + "camera: {fov: 40}\n", {"scene.yaml:4:", "unknown key 'camera'", "did you mean 'cameras'"});
    expectInputError(kObjects + "cameras: {grid: {distnace: 4}}\n", {"unknown key 'distnace'", "did you mean 'distance'"});
}

TEST(SceneFileGuard, ExtremeCameraValuesAreRefusedAtTheirLine) {
    expectInputError(kObjects + "cameras:\n  grid: {distance: 1e20}\n", {"scene.yaml:5:", "distance 1e+20", "too far"});
    expectInputError(kObjects + "cameras:\n  fov: 1e-300\n", {"scene.yaml:5:", "fov must lie in"});
    expectInputError(kObjects + "cameras:\n  fov: 179.99999\n", {"scene.yaml:5:", "fov must lie in"});
    expectInputError(kObjects + "cameras:\n  grid: {target: [0, 1e300, 0]}\n", {"scene.yaml:5:", "target", "too far"});
    expectInputError(kObjects + "cameras:\n  projection: orthographic\n  height: 1e300\n",
                     {"scene.yaml:6:", "height 1e+300", "out of proportion"});
    expectInputError(kObjects + "cameras:\n  list:\n    - {position: [1e300, 0, 0]}\n",
                     {"scene.yaml:6:", "position", "too far"});
    expectInputError(kObjects + "cameras:\n  list:\n    - {position: [0, 0, 3], target: [0, 0, -1e16]}\n",
                     {"scene.yaml:6:", "target", "too far"});
    // Directions may be any non-zero length; only their direction counts.
    const auto d = parse(kObjects + "cameras:\n  list:\n    - {position: [0, 0, 3], forward: [0, 0, -1e300], up: [0, 1e-300, 0]}\n");
    ASSERT_EQ(d.cameras.size(), 1u);
    EXPECT_NEAR(d.cameras[0].camera.forward.z, -1, 1e-12);
    // Sane values far beyond the default still load.
    EXPECT_EQ(parse(kObjects + "cameras:\n  fov: 0.5\n  grid: {distance: 1000, phi: 2, theta: 1}\n").cameras.size(), 2u);
}

TEST(SceneFileGuard, CamerasBeyondSinglePrecisionAreRefusedWhateverTheSceneSize) {
    // Within 10^6 radii of a scene 10^14 across, but beyond the 1.8e18 from
    // which Embree refuses (asserts on) rays: it used to abort the capture.
    const std::string big = "objects:\n  - generator: isosurface\n    parameters: {resolution: 8}\n    scale: 1e14\n";
    expectInputError(big + "cameras:\n  grid: {distance: 1e19, phi: 1, theta: 1}\n",
                     {"scene.yaml:6:", "camera phi=-180, theta=0", "beyond 1e+18 world units"});
    // Default cameras around a scene that itself reaches 1e18.
    const std::string huge = "objects:\n  - generator: isosurface\n    parameters: {resolution: 8}\n    scale: 1e18\n";
    expectInputError(huge, {"scene.yaml", "beyond 1e+18 world units"});
    expectInputError(big + "cameras:\n  projection: orthographic\n  height: 1e19\n  grid: {distance: 1e15, phi: 1, theta: 1}\n",
                     {"scene.yaml:6:", "view's half extent"});
}
