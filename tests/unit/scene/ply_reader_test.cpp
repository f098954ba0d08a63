#include "mesh_test_files.h"
#include "test_support.h"

#include <darkroom/scene/mesh_readers.h>

#include <cmath>

using namespace darkroom;
using darkroom::test::expectError;
using darkroom::test::put;

namespace {

// Four vertices (x y z nx red) of a unit square and one off it, a quad and a
// triangle with a per-face "quality".
const char* kHeader =
    "ply\n"
    "format %s 1.0\n"
    "comment written by the test\n"
    "element vertex 5\n"
    "property float x\nproperty float y\nproperty float z\n"
    "property float nx\nproperty uchar red\n"
    "element face 2\n"
    "property list uchar int vertex_indices\n"
    "property float quality\n"
    "end_header\n";

std::string header(const char* format) {
    char buf[512];
    std::snprintf(buf, sizeof buf, kHeader, format);
    return buf;
}

const float kPos[5][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {2, 0, 0}};

std::string binaryPly(bool big) {
    std::string s = header(big ? "binary_big_endian" : "binary_little_endian");
    for (int i = 0; i < 5; ++i) {
        for (float c : kPos[i]) put(s, c, big);
        put(s, float(i) * 0.5f, big);
        put(s, std::uint8_t(10 * i), big);
    }
    put(s, std::uint8_t(4), big);
    for (int v : {0, 1, 2, 3}) put(s, std::int32_t(v), big);
    put(s, 7.5f, big);
    put(s, std::uint8_t(3), big);
    for (int v : {1, 4, 2}) put(s, std::int32_t(v), big);
    put(s, -2.0f, big);
    return s;
}

std::string asciiPly() {
    std::string s = header("ascii");
    for (int i = 0; i < 5; ++i)
        s += std::to_string(kPos[i][0]) + " " + std::to_string(kPos[i][1]) + " " + std::to_string(kPos[i][2]) + " " +
             std::to_string(i * 0.5) + " " + std::to_string(10 * i) + "\n";
    s += "4 0 1 2 3 7.5\n3 1 4 2 -2\n";
    return s;
}

void checkSquare(const std::vector<SceneObject>& objs) {
    ASSERT_EQ(objs.size(), 1u);
    const SceneObject& o = objs[0];
    EXPECT_EQ(o.representation, Representation::Surface);
    ASSERT_EQ(o.vertexCount(), 5u);
    EXPECT_EQ(o.vertices[4 * 4 + 0], 2.f);
    EXPECT_EQ(o.vertices[4 * 2 + 1], 1.f);
    // The quad is fanned into two triangles that both map back to face 0.
    EXPECT_EQ(o.indices, (std::vector<std::uint32_t>{0, 1, 2, 0, 2, 3, 1, 4, 2}));
    EXPECT_EQ(o.primitiveCell, (std::vector<std::uint32_t>{0, 0, 1}));
    const ScalarField* nx = o.field("nx");
    const ScalarField* red = o.field("red");
    const ScalarField* q = o.field("quality");
    ASSERT_TRUE(nx && red && q);
    EXPECT_EQ(nx->association, ScalarField::Association::Point);
    EXPECT_EQ(nx->values, (std::vector<float>{0, 0.5f, 1, 1.5f, 2}));
    EXPECT_EQ(red->values, (std::vector<float>{0, 10, 20, 30, 40}));
    EXPECT_EQ(q->association, ScalarField::Association::Cell);
    EXPECT_EQ(q->values, (std::vector<float>{7.5f, -2.f}));
    EXPECT_EQ(o.fields.size(), 3u);  // x, y, z are geometry, not fields
}

}  // namespace

TEST(PlyReader, AsciiFacesAndProperties) {
    test::TempDir dir;
    test::writeText(dir.file("square.ply"), asciiPly());
    const auto objs = readMesh(dir.file("square.ply"));
    checkSquare(objs);
    EXPECT_EQ(objs[0].name, "square");
}

TEST(PlyReader, BinaryLittleEndian) {
    test::TempDir dir;
    test::writeText(dir.file("le.ply"), binaryPly(false));
    checkSquare(readMesh(dir.file("le.ply")));
}

TEST(PlyReader, BinaryBigEndian) {
    test::TempDir dir;
    test::writeText(dir.file("be.PLY"), binaryPly(true));
    checkSquare(readMesh(dir.file("be.PLY")));
}

TEST(PlyReader, TriangleStripsWithRestartsKeepTheirCell) {
    test::TempDir dir;
    std::string s =
        "ply\nformat ascii 1.0\nelement vertex 6\nproperty float x\nproperty float y\nproperty float z\n"
        "element face 1\nproperty list uchar int vertex_indices\nproperty int tag\n"
        "element tristrips 1\nproperty list int int vertex_indices\nproperty int tag\nend_header\n";
    for (int i = 0; i < 6; ++i) s += std::to_string(i % 3) + " " + std::to_string(i / 3) + " 0\n";
    s += "3 0 1 4 11\n";
    s += "8 0 1 3 4 -1 1 2 4 22\n";
    test::writeText(dir.file("strip.ply"), s);
    const auto objs = readMesh(dir.file("strip.ply"));
    ASSERT_EQ(objs.size(), 1u);
    const SceneObject& o = objs[0];
    // Face (1 triangle) + strip run 0,1,3,4 (2 triangles, the 2nd flipped) + run 1,2,4 (1).
    ASSERT_EQ(test::primitives(o), 4u);
    EXPECT_EQ(o.primitiveCell, (std::vector<std::uint32_t>{0, 1, 1, 1}));
    EXPECT_EQ(o.field("tag")->values, (std::vector<float>{11, 22}));
    // Same winding for both triangles of the first run: (0,1,3) then (3,1,4) as (1,3,4) flipped.
    auto pos = [&](std::uint32_t i) { return std::array<float, 2>{o.vertices[4 * i], o.vertices[4 * i + 1]}; };
    auto signedArea = [&](std::size_t t) {
        const auto a = pos(o.indices[3 * t]), b = pos(o.indices[3 * t + 1]), c = pos(o.indices[3 * t + 2]);
        return (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
    };
    EXPECT_GT(signedArea(1) * signedArea(2), 0.f);
}

TEST(PlyReader, VerticesOnlyBecomeAPointCloud) {
    test::TempDir dir;
    test::writeText(dir.file("cloud.ply"),
                    "ply\nformat ascii 1.0\nelement vertex 3\nproperty double x\nproperty double y\n"
                    "property double z\nproperty float temperature\nend_header\n0 0 0 1\n1 0 0 2\n0 1 0 3\n");
    const auto objs = readMesh(dir.file("cloud.ply"));
    ASSERT_EQ(objs.size(), 1u);
    EXPECT_EQ(objs[0].representation, Representation::Points);
    EXPECT_EQ(test::primitives(objs[0]), 3u);
    EXPECT_EQ(objs[0].field("temperature")->values, (std::vector<float>{1, 2, 3}));
}

TEST(PlyReader, TruncatedBinaryNamesFileAndElement) {
    test::TempDir dir;
    std::string s = binaryPly(false);
    s.resize(s.size() - 6);
    test::writeText(dir.file("cut.ply"), s);
    expectError([&] { readMesh(dir.file("cut.ply")); }, {dir.file("cut.ply"), "element 'face' 1", "truncated"});
}

TEST(PlyReader, FaceIndexOutOfRangeIsAnError) {
    test::TempDir dir;
    std::string s = asciiPly();
    s.replace(s.find("3 1 4 2"), 7, "3 1 9 2");
    test::writeText(dir.file("bad.ply"), s);
    // Line 20: header (13 lines), 5 vertices, the first face, then this one.
    expectError([&] { readMesh(dir.file("bad.ply")); }, {dir.file("bad.ply") + ":20:", "vertex index 9 out of range"});
}

TEST(PlyReader, BinaryFaceIndexOutOfRangeIsAnError) {
    test::TempDir dir;
    std::string s = binaryPly(true);
    // The triangle's second index (4) sits 4 + 4 bytes before its quality float.
    const std::size_t at = s.size() - 4 - 8;
    s.replace(at, 4, std::string("\x7f\0\0\0", 4));
    test::writeText(dir.file("bad.ply"), s);
    expectError([&] { readMesh(dir.file("bad.ply")); }, {dir.file("bad.ply"), "element 'face' 1", "out of range"});
}

TEST(PlyReader, NonNumericTokenNamesLine) {
    test::TempDir dir;
    std::string s = asciiPly();
    s.replace(s.find("7.5"), 3, "abc");
    test::writeText(dir.file("nan.ply"), s);
    expectError([&] { readMesh(dir.file("nan.ply")); }, {dir.file("nan.ply") + ":19:", "'quality'", "'abc'"});
}

TEST(PlyReader, MissingHeader) {
    test::TempDir dir;
    test::writeText(dir.file("none.ply"), "0 0 0\n1 1 1\n");
    expectError([&] { readMesh(dir.file("none.ply")); }, {dir.file("none.ply") + ":1:", "expected 'ply'"});
    test::writeText(dir.file("open.ply"), "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\n");
    expectError([&] { readMesh(dir.file("open.ply")); }, {dir.file("open.ply"), "end_header"});
}

TEST(MeshReaders, UnknownExtensionAndMissingFile) {
    expectError([] { readMesh("/nonexistent/x.ply"); }, {"/nonexistent/x.ply", "cannot open"});
    expectError([] { readMesh("model.stl"); }, {"model.stl", ".stl"});
}
