// The `Capture` node: renders a scene file's camera through a registered
// backend inside a pipeline, with overrides, and reports bad input clearly.
#include <darkroom/error.h>
#include <darkroom/core/run_filter.h>
#include <gtest/gtest.h>

#include "test_meshes.h"
#include "test_support.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <limits>
#include <map>
#include <string>
#include <vector>

namespace darkroom::test {
namespace {

// The square's two triangles as a binary STL: 80-byte header, count, then
// per triangle a normal, three vertices and a 16-bit attribute.
std::string quadStl() {
    std::string s(80, ' ');
    auto put = [&](auto v) { s.append(reinterpret_cast<const char*>(&v), sizeof v); };  // little-endian hosts
    put(std::uint32_t(2));
    const float triangles[2][9] = {{-1, -1, -5, 1, -1, -5, 1, 1, -5}, {-1, -1, -5, 1, 1, -5, -1, 1, -5}};
    for (const auto& t : triangles) {
        for (float n : {0.f, 0.f, 1.f}) put(n);
        for (int k = 0; k < 9; ++k) put(t[k]);
        put(std::uint16_t(0));
    }
    return s;
}

// A 2x2 square facing +z at z = -5, as an OBJ, an OFF and a binary STL file,
// and a scene file (drawing `mesh`, one of them) with two cameras on the z
// axis looking at it.
struct SceneFiles {
    TempDir dir;
    std::string scene = dir.file("scene.yaml");
    std::string mesh;
    SceneFiles(double fov = 40.0, std::string meshFile = "quad.obj") : mesh(std::move(meshFile)) {
        writeText(dir.file("quad.obj"), "v -1 -1 -5\nv 1 -1 -5\nv 1 1 -5\nv -1 1 -5\nf 1 2 3\nf 1 3 4\n");
        writeText(dir.file("quad.off"), "OFF\n4 2 0\n-1 -1 -5\n1 -1 -5\n1 1 -5\n-1 1 -5\n3 0 1 2\n3 0 2 3\n");
        writeText(dir.file("quad.stl"), quadStl());
        writeScene(fov);
    }
    void writeScene(double fov) {
        writeText(scene, "version: 1\n"
                         "objects:\n"
                         "  - file: " + mesh + "\n"
                         "cameras:\n"
                         "  projection: perspective\n"
                         "  fov: " + std::to_string(fov) + "\n"
                         "  resolution: [32, 24]\n"
                         "  list:\n"
                         "    - {position: [0, 0, 0], target: [0, 0, -5], up: [0, 1, 0]}\n"
                         "    - {position: [0, 0, 2], target: [0, 0, -5], up: [0, 1, 0]}\n"
                         "channels:\n"
                         "  normals: true\n");
    }
};

std::unique_ptr<Filter> makeCapture() { return pluginRegistry().createFilter("Capture"); }

BufferPtr run(Filter& f, const std::map<std::string, std::vector<Value>>& inputs) {
    FilterRunOptions o;
    o.registry = &pluginRegistry();
    o.threads = 2;
    return runFilter(f, inputs, o).outputs.at("image").asImage();
}

float centre(const BufferPtr& b, const char* channel) {
    return b->requireFloat(channel)[std::size_t(b->height() / 2) * b->width() + b->width() / 2];
}

TEST(Capture, RendersTheChosenCameraOfASceneFile) {
    SceneFiles files;
    auto f = makeCapture();
    ASSERT_TRUE(f);
    auto first = run(*f, {{"scene", {Value(files.scene)}}});
    EXPECT_EQ(first->width(), 32);
    EXPECT_EQ(first->height(), 24);
    EXPECT_NEAR(centre(first, "Z"), 5.0f, 1e-5f);
    EXPECT_NEAR(centre(first, "N.z"), 1.0f, 1e-6f);  // the scene file asked for normals
    EXPECT_EQ(first->requireFloat("Z")[0], std::numeric_limits<float>::infinity());
    ASSERT_TRUE(first->metadata().camera.has_value());
    EXPECT_EQ(first->metadata().camera->position, (Vec3{0, 0, 0}));

    // Same instance, other camera: the cached scene renders the new view.
    auto second = run(*f, {{"scene", {Value(files.scene)}}, {"camera", {Value(1)}}});
    EXPECT_NEAR(centre(second, "Z"), 7.0f, 1e-5f);
    EXPECT_EQ(second->metadata().camera->position, (Vec3{0, 0, 2}));
}

// OFF and STL files in a scene file: the same square, so the same pixels as the OBJ's.
TEST(Capture, RendersOffAndStlMeshesLikeTheirObj) {
    SceneFiles objFiles;
    auto f = makeCapture();
    const auto obj = run(*f, {{"scene", {Value(objFiles.scene)}}});
    const std::size_t pixels = std::size_t(obj->width()) * std::size_t(obj->height());
    for (const char* mesh : {"quad.off", "quad.stl"}) {
        SceneFiles files(40.0, mesh);
        auto g = makeCapture();
        const auto b = run(*g, {{"scene", {Value(files.scene)}}});
        EXPECT_NEAR(centre(b, "Z"), 5.0f, 1e-5f) << mesh;
        EXPECT_NEAR(centre(b, "N.z"), 1.0f, 1e-6f) << mesh;
        for (const char* channel : {"Z", "N.x", "N.y", "N.z"}) {
            const std::vector<float> got(b->requireFloat(channel), b->requireFloat(channel) + pixels);
            const std::vector<float> want(obj->requireFloat(channel), obj->requireFloat(channel) + pixels);
            EXPECT_TRUE(std::equal(got.begin(), got.end(), want.begin(), [](float x, float y) {
                return x == y || (std::isnan(x) && std::isnan(y));
            })) << mesh << " " << channel;
        }
    }
}

TEST(Capture, OverridesResolutionAndChannels) {
    SceneFiles files;
    auto f = makeCapture();
    auto b = run(*f, {{"scene", {Value(files.scene)}}, {"width", {Value(10)}}, {"height", {Value(6)}},
                      {"ids", {Value(true)}}});
    EXPECT_EQ(b->width(), 10);
    EXPECT_EQ(b->height(), 6);
    EXPECT_EQ(b->metadata().camera->width, 10);
    EXPECT_TRUE(b->hasChannel("objectId"));
    EXPECT_TRUE(b->hasChannel("primitiveId"));
    EXPECT_EQ(b->requireUInt("objectId")[3 * 10 + 5], 0u);
}

// The scene file's `channels: {layers: K}` passes through the node: the
// square (one crossing) fills layer 0 and leaves layer 1 empty.
TEST(Capture, PassesTheSceneFilesLayersThrough) {
    SceneFiles files;
    writeText(files.scene, readText(files.scene) + "  layers: 2\n");
    auto f = makeCapture();
    const auto b = run(*f, {{"scene", {Value(files.scene)}}});
    EXPECT_NEAR(centre(b, "Z"), 5.0f, 1e-5f);
    EXPECT_EQ(centre(b, "layer1.Z"), std::numeric_limits<float>::infinity());
    EXPECT_TRUE(std::isnan(centre(b, "layer1.N.z")));
}

// The `normals` input on a scene file that stores none: the normals come in
// the file's style, smooth unless it says geometric, so within one triangle
// smooth normals vary and geometric ones do not. The node reloads the scene
// once to prepare the vertex normals, and keeps it.
TEST(Capture, NormalsInputGivesTheFilesStyle) {
    TempDir dir;
    writeObj(dir.file("sphere.obj"), uvSphere(8, 16, 1.0, {0, 0, -5}));
    auto scene = [&](const std::string& name, const std::string& channels) {
        writeText(dir.file(name), "objects: [{file: sphere.obj}]\ncameras:\n  resolution: [48, 48]\n  fov: 30\n"
                                  "  list: [{position: [0, 0, 0], target: [0, 0, -5]}]\nchannels: {" + channels + "}\n");
        return dir.file(name);
    };
    // How many pixels have a normal other than the first pixel of their triangle's.
    auto varying = [](const BufferPtr& b) {
        std::map<std::uint32_t, std::size_t> first;
        std::size_t n = 0;
        for (std::size_t i = 0; i < b->pixelCount(); ++i) {
            const std::uint32_t t = b->requireUInt("primitiveId")[i];
            if (t == 0xFFFFFFFFu) continue;
            const std::size_t j = first.emplace(t, i).first->second;
            for (const char* c : {"N.x", "N.y", "N.z"}) n += b->requireFloat(c)[i] != b->requireFloat(c)[j];
        }
        return n;
    };
    auto f = makeCapture();
    const std::string smooth = scene("smooth.yaml", "featureAngle: 40");
    EXPECT_FALSE(run(*f, {{"scene", {Value(smooth)}}, {"ids", {Value(true)}}})->hasChannel("N.x"));
    EXPECT_GT(varying(run(*f, {{"scene", {Value(smooth)}}, {"normals", {Value(true)}}, {"ids", {Value(true)}}})), 500u);
    EXPECT_FALSE(run(*f, {{"scene", {Value(smooth)}}, {"ids", {Value(true)}}})->hasChannel("N.x"))
        << "the input alone decides, as before";
    const std::string flat = scene("geometric.yaml", "normals: geometric");
    EXPECT_EQ(varying(run(*f, {{"scene", {Value(flat)}}, {"ids", {Value(true)}}})), 0u);
}

TEST(Capture, PicksUpAnEditedSceneFile) {
    SceneFiles files(40.0);
    auto f = makeCapture();
    auto wide = run(*f, {{"scene", {Value(files.scene)}}});
    files.writeScene(10.0);
    // Make sure the modification time differs even on coarse-grained file systems.
    std::filesystem::last_write_time(files.scene,
                                     std::filesystem::last_write_time(files.scene) + std::chrono::seconds(2));
    auto narrow = run(*f, {{"scene", {Value(files.scene)}}});
    EXPECT_DOUBLE_EQ(narrow->metadata().camera->fovYDegrees, 10.0);
    // Narrower view: the square covers more pixels.
    auto covered = [](const BufferPtr& b) {
        int n = 0;
        for (std::size_t i = 0; i < b->pixelCount(); ++i) n += std::isfinite(b->requireFloat("Z")[i]);
        return n;
    };
    EXPECT_GT(covered(narrow), covered(wide));
}

TEST(Capture, BadInputGivesClearErrors) {
    SceneFiles files;
    auto f = makeCapture();
    try {
        run(*f, {{"scene", {Value(files.scene)}}, {"camera", {Value(5)}}});
        FAIL() << "camera 5 does not exist";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("2 cameras"), std::string::npos) << e.what();
    }
    try {
        run(*f, {{"scene", {Value(files.dir.file("missing.yaml"))}}});
        FAIL() << "a missing scene file must throw";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("missing.yaml"), std::string::npos) << e.what();
    }
    EXPECT_THROW(run(*f, {}), Error);  // no scene at all
    try {
        run(*f, {{"scene", {Value(files.scene)}}, {"backend", {Value("no-such-backend")}}});
        FAIL() << "an unknown backend must throw";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("no-such-backend"), std::string::npos) << e.what();
    }
}

}  // namespace
}  // namespace darkroom::test
