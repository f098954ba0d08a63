#include "mesh_test_files.h"
#include "test_support.h"

#include <darkroom/scene/mesh_readers.h>

#include <set>

using namespace darkroom;
using darkroom::test::expectError;

TEST(ObjReader, FacesInEveryFormNegativeIndicesAndLines) {
    test::TempDir dir;
    test::writeText(dir.file("m.obj"),
                    "# a quad, a triangle by negative indices and a polyline\n"
                    "o thing\n"
                    "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n"
                    "vt 0 0\nvn 0 0 1\n"
                    "f 1/1/1 2/1/1 3//1 4/1\n"
                    "v 2 0 0\n"
                    "f -4 -1 -3\n"
                    "l 1 2 3\n");
    const auto objs = readMesh(dir.file("m.obj"));
    ASSERT_EQ(objs.size(), 2u);
    const SceneObject& s = objs[0];
    EXPECT_EQ(s.name, "m/surface");
    EXPECT_EQ(s.representation, Representation::Surface);
    EXPECT_EQ(s.vertexCount(), 5u);
    EXPECT_EQ(s.indices, (std::vector<std::uint32_t>{0, 1, 2, 0, 2, 3, 1, 4, 2}));
    EXPECT_EQ(s.primitiveCell, (std::vector<std::uint32_t>{0, 0, 1}));
    const SceneObject& l = objs[1];
    EXPECT_EQ(l.name, "m/lines");
    EXPECT_EQ(l.representation, Representation::Lines);
    // Segments join consecutive vertices: the polyline's three points in order.
    EXPECT_EQ(l.vertexCount(), 3u);
    EXPECT_EQ(l.indices, (std::vector<std::uint32_t>{0, 1}));
    EXPECT_EQ(l.vertices[4 * 2 + 1], 1.f);
}

TEST(ObjReader, IndexOutOfRangeNamesLine) {
    test::TempDir dir;
    test::writeText(dir.file("bad.obj"), "v 0 0 0\nv 1 0 0\nv 0 1 0\n\nf 1 2 7\n");
    expectError([&] { readMesh(dir.file("bad.obj")); }, {dir.file("bad.obj") + ":5:", "vertex index 7 out of range"});
    test::writeText(dir.file("zero.obj"), "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 0 1 2\n");
    expectError([&] { readMesh(dir.file("zero.obj")); }, {dir.file("zero.obj") + ":4:", "out of range"});
    test::writeText(dir.file("neg.obj"), "v 0 0 0\nv 1 0 0\nv 0 1 0\nf -1 -2 -4\n");
    expectError([&] { readMesh(dir.file("neg.obj")); }, {dir.file("neg.obj") + ":4:", "-4"});
}

TEST(ObjReader, NonNumericCoordinateNamesLine) {
    test::TempDir dir;
    test::writeText(dir.file("bad.obj"), "v 0 0 0\nv 1 zero 0\n");
    expectError([&] { readMesh(dir.file("bad.obj")); }, {dir.file("bad.obj") + ":2:", "'zero'"});
    test::writeText(dir.file("face.obj"), "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 x/1\n");
    expectError([&] { readMesh(dir.file("face.obj")); }, {dir.file("face.obj") + ":4:", "'x/1'"});
}

TEST(ObjReader, StanfordBunny) {
    const std::string path = test::sharedData("meshes/stanford-bunny.obj");
    if (path.empty()) GTEST_SKIP() << "../shared/data is absent; the real-file test needs meshes/stanford-bunny.obj";
    const auto objs = readMesh(path);
    ASSERT_EQ(objs.size(), 1u);
    const SceneObject& o = objs[0];
    EXPECT_EQ(o.name, "stanford-bunny");
    // The file lists 35,947 vertices; 1,113 are referenced by no face and are
    // dropped, leaving the 34,834 of the data README.
    EXPECT_EQ(o.vertexCount(), 34834u);
    EXPECT_EQ(test::primitives(o), 69451u);
    EXPECT_TRUE(o.primitiveCell.empty());
    std::set<std::uint32_t> used(o.indices.begin(), o.indices.end());
    EXPECT_EQ(used.size(), 34834u);
    EXPECT_EQ(*used.rbegin(), 34833u);
    Scene scene;
    scene.objects = objs;
    const Bounds b = scene.bounds();
    // The Stanford bunny is about 0.15 units across.
    EXPECT_NEAR(b.hi.x - b.lo.x, 0.156, 0.01);
}
