// The shared Stanford bunny (../shared/data) converted to OFF, ASCII STL and
// binary STL inside the test reads back as the OBJ's very triangles: a real
// mesh of 69,451 triangles through the new readers.
#include "off_stl_test_files.h"
#include "test_support.h"

#include <darkroom/scene/mesh_readers.h>

using namespace darkroom;

namespace {

// Triangle by triangle, corner by corner, the same positions.
void expectSameTriangles(const SceneObject& got, const SceneObject& want, const std::string& what) {
    ASSERT_EQ(got.indices.size(), want.indices.size()) << what;
    std::size_t differing = 0;
    for (std::size_t i = 0; i < want.indices.size(); ++i)
        for (std::size_t k = 0; k < 3; ++k)
            differing += got.vertices[4 * got.indices[i] + k] != want.vertices[4 * want.indices[i] + k];
    EXPECT_EQ(differing, 0u) << what;
}

}  // namespace

TEST(MeshFormats, BunnyAsOffAndStlGivesTheObjTriangles) {
    const std::string path = test::sharedData("meshes/stanford-bunny.obj");
    if (path.empty()) GTEST_SKIP() << "../shared/data is absent; the conversion test needs meshes/stanford-bunny.obj";
    const auto obj = readMesh(path);
    ASSERT_EQ(obj.size(), 1u);
    const SceneObject& bunny = obj[0];
    ASSERT_EQ(test::primitives(bunny), 69451u);

    test::TempDir dir;
    test::writeText(dir.file("bunny.off"), test::offText(bunny));
    test::writeText(dir.file("ascii.stl"), test::asciiStl(bunny, "bunny"));
    test::writeText(dir.file("binary.stl"), test::binaryStl(bunny));
    for (const char* name : {"bunny.off", "ascii.stl", "binary.stl"}) {
        const auto read = readMesh(dir.file(name));
        ASSERT_EQ(read.size(), 1u) << name;
        expectSameTriangles(read[0], bunny, name);
        // No two of the bunny's vertices share a position, so merging the
        // STL's soup finds every one again, numbered in first use as the
        // OBJ's surface is: the very same arrays.
        EXPECT_EQ(read[0].vertexCount(), 34834u) << name;
        EXPECT_EQ(read[0].vertices, bunny.vertices) << name;
        EXPECT_EQ(read[0].indices, bunny.indices) << name;
    }
}
