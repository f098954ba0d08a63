// The OFF reader: a box of six quads in every variant the reader accepts
// (COFF, NOFF, CNOFF, counts on the keyword's line, comments, blank lines,
// CRLF), and each refusal with its file:line and what was expected.
#include "mesh_test_files.h"
#include "test_support.h"

#include <darkroom/limits.h>
#include <darkroom/scene/mesh_readers.h>

#include <array>
#include <filesystem>

using namespace darkroom;
using darkroom::test::expectInputError;

namespace {

// A box from (-1, -2, -3) to (1, 2, 3): 8 vertices, 6 outward quads.
const float kBox[8][3] = {{-1, -2, -3}, {1, -2, -3}, {1, 2, -3}, {-1, 2, -3},
                          {-1, -2, 3},  {1, -2, 3},  {1, 2, 3},  {-1, 2, 3}};
const int kQuads[6][4] = {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4}, {2, 3, 7, 6}, {0, 4, 7, 3}, {1, 2, 6, 5}};

// The box as OFF text: `vertexTail` and `faceTail` follow each vertex's
// x y z and each face's indices (normals, colours, comments).
std::string boxOff(const std::string& head, const std::string& vertexTail = "", const std::string& faceTail = "") {
    std::string s = head;
    for (const auto& v : kBox)
        s += std::to_string(int(v[0])) + " " + std::to_string(int(v[1])) + " " + std::to_string(int(v[2])) + vertexTail + "\n";
    for (const auto& q : kQuads)
        s += "4 " + std::to_string(q[0]) + " " + std::to_string(q[1]) + " " + std::to_string(q[2]) + " " +
             std::to_string(q[3]) + faceTail + "\n";
    return s;
}

std::array<float, 3> corner(const SceneObject& o, std::size_t triangle, std::size_t c) {
    const std::uint32_t v = o.indices[3 * triangle + c];
    return {o.vertices[4 * v], o.vertices[4 * v + 1], o.vertices[4 * v + 2]};
}

// Each quad fanned into (q0 q1 q2), (q0 q2 q3), in the file's order.
void expectBox(const std::vector<SceneObject>& objs, const std::string& name) {
    ASSERT_EQ(objs.size(), 1u) << name;
    const SceneObject& o = objs[0];
    EXPECT_EQ(o.name, name);
    EXPECT_EQ(o.representation, Representation::Surface);
    EXPECT_EQ(o.vertexCount(), 8u);
    ASSERT_EQ(test::primitives(o), 12u);
    for (std::size_t f = 0; f < 6; ++f)
        for (std::size_t half = 0; half < 2; ++half)
            for (std::size_t c = 0; c < 3; ++c) {
                const int v = kQuads[f][c == 0 ? 0 : c + half];
                EXPECT_EQ(corner(o, 2 * f + half, c), (std::array<float, 3>{kBox[v][0], kBox[v][1], kBox[v][2]}))
                    << name << " face " << f << " triangle " << half << " corner " << c;
            }
    EXPECT_EQ(o.primitiveCell, (std::vector<std::uint32_t>{0, 0, 1, 1, 2, 2, 3, 3, 4, 4, 5, 5}));
    EXPECT_TRUE(o.fields.empty()) << "normals and colours are not kept";
    Scene scene;
    scene.objects = objs;
    const Bounds b = scene.bounds();
    EXPECT_EQ(b.lo, (Vec3{-1, -2, -3}));
    EXPECT_EQ(b.hi, (Vec3{1, 2, 3}));
}

}  // namespace

TEST(OffReader, BoxOfQuadsIsFanTriangulated) {
    test::TempDir dir;
    test::writeText(dir.file("box.off"), boxOff("OFF\n8 6 12\n"));
    expectBox(readMesh(dir.file("box.off")), "box");
}

TEST(OffReader, VariantsCountsOnTheKeywordLineAndComments) {
    test::TempDir dir;
    const std::pair<const char*, std::string> files[] = {
        {"coff.off", boxOff("COFF\n8 6 0\n", " 255 128 0 255", " 0.5 0.5 0.5")},
        {"noff.off", boxOff("NOFF\n8 6 0\n", " 0 0 1")},
        {"cnoff.off", boxOff("CNOFF\n8 6 0\n", " 0 0 1 0.1 0.2 0.3 1", " 7")},
        {"stoff.off", boxOff("STOFF\n8 6 0\n", " 0.25 0.75")},
        {"same-line.off", boxOff("OFF 8 6 12\n")},
        {"glued.off", boxOff("OFF8 6 0\n")},  // as ModelNet writes it
        {"no-edges.off", boxOff("OFF\n8 6\n")},
        {"comments.off", boxOff("# written by hand\n\nOFF # the keyword\n# counts next\n8 6 0 # v f e\n\n",
                                " # a vertex", " # a face\n# between faces\n")},
        {"upper.OFF", boxOff("OFF\r\n8 6 0\r\n", "\r", "\r")},
    };
    for (const auto& [name, text] : files) {
        test::writeText(dir.file(name), text);
        expectBox(readMesh(dir.file(name)), std::filesystem::path(name).stem().string());
    }
}

TEST(OffReader, VerticesWithoutFacesAreAPointCloud) {
    test::TempDir dir;
    test::writeText(dir.file("points.off"), "OFF\n3 0 0\n0 0 0\n1 0 0\n0 1 0\n");
    const auto objs = readMesh(dir.file("points.off"));
    ASSERT_EQ(objs.size(), 1u);
    EXPECT_EQ(objs[0].representation, Representation::Points);
    EXPECT_EQ(objs[0].vertexCount(), 3u);
}

TEST(OffReader, FaceErrorsNameTheLineAndWhatWasExpected) {
    test::TempDir dir;
    auto check = [&](const std::string& name, const std::string& text, const std::vector<std::string>& parts) {
        test::writeText(dir.file(name), text);
        std::vector<std::string> all{dir.file(name) + ":"};
        all.insert(all.end(), parts.begin(), parts.end());
        expectInputError([&] { readMesh(dir.file(name)); }, all);
    };
    // Vertex lines longer than the least a vertex takes, so the counts fit the file.
    const std::string head = "OFF\n3 1 0\n0.0 0.0 0.0\n1.0 0.0 0.0\n0.0 1.0 0.0\n";
    check("range.off", head + "3 0 1 3\n", {":6:", "face 0: vertex index 3 out of range; expected 0 to 2", "line 2"});
    check("negative-index.off", head + "3 0 -1 2\n", {":6:", "vertex index -1 out of range"});
    check("two.off", head + "2 0 1\n", {":6:", "face 0: a face needs at least 3 vertices, got 2"});
    check("short-face.off", head + "4 0 1 2\n", {":6:", "declares 4 vertices but the line holds only 3 values"});
    check("long-face.off", head + "3 0 1 2 1 1 1 1 1\n", {":6:", "5 values after its 3 vertex indices; expected at most 4"});
    check("index-text.off", head + "3 0 one 2\n", {":6:", "expected a vertex index, got 'one'"});
    check("count-text.off", head + "three 0 1 2\n", {":6:", "expected the face's vertex count, got 'three'"});
    check("faces-missing.off", "OFF\n3 2 0\n0.0 0.0 0.0\n1.0 0.0 0.0\n0.0 1.0 0.0\n3 0 1 2\n",
          {":7:", "unexpected end of file after 1 of the 2 faces declared on line 2", "truncated?"});
    check("extra.off", head + "3 0 1 2\n3 0 1 2\n", {":7:", "after the 1 faces declared on line 2", "are the counts right?"});
}

TEST(OffReader, HeaderAndVertexErrorsNameTheLineAndWhatWasExpected) {
    test::TempDir dir;
    auto check = [&](const std::string& name, const std::string& text, const std::vector<std::string>& parts) {
        test::writeText(dir.file(name), text);
        std::vector<std::string> all{dir.file(name)};
        all.insert(all.end(), parts.begin(), parts.end());
        expectInputError([&] { readMesh(dir.file(name)); }, all);
    };
    check("empty.off", "# nothing\n\n", {"empty file; expected an OFF header"});
    check("ply.off", "ply\n", {":1:", "expected an OFF header ('OFF', 'COFF', 'NOFF', 'CNOFF' or 'STOFF'), got 'ply'"});
    check("binary.off", "OFF BINARY\n", {":1:", "binary OFF ('OFF BINARY') is not supported"});
    check("4d.off", "4OFF\n1 0 0\n0 0 0 0\n", {":1:", "4D and n-dimensional OFF are not supported"});
    check("no-counts.off", "OFF\n", {":2:", "unexpected end of file; expected the counts"});
    check("negative.off", "OFF\n# counts\n-1 2 0\n", {":3:", "a negative count"});
    check("negative-faces.off", "OFF 3 -2 0\n", {":1:", "a negative count"});
    check("counts.off", "OFF\n3 x 0\n", {":2:", "expected the counts 'vertices faces edges' (edges optional), got 'x'"});
    check("four-counts.off", "OFF\n3 1 0 0\n", {":2:", "got 4 values"});
    check("no-vertices.off", "OFF\n0 0 0\n", {":2:", "no vertices"});
    check("huge.off", "OFF\n400000000 1 0\n0 0 0\n", {":2:", "declares 400000000 vertices and 1 faces", "truncated?"});
    check("vertices-missing.off", "OFF\n4 1 0\n0.000000 0.000000 0.000000\n1.000000 0 0\n",
          {":5:", "unexpected end of file after 2 of the 4 vertices declared on line 2; expected 'x y z'"});
    check("short-vertex.off", "OFF\n3 0 0\n0.0 0.0 0.0\n1 0\n0.0 1.0 0.0\n", {":4:", "vertex 1: expected 'x y z', got 2 values"});
    check("normal-missing.off", "NOFF\n3 0 0\n0 0 0 0 0 1\n1 0 0\n0 1 0 0 0 1\n",
          {":4:", "vertex 1: expected 'x y z nx ny nz', got 3 values"});
    check("text.off", "OFF\n3 0 0\n0 0 0\n1 zero 0\n0 1 0\n", {":4:", "vertex 1: expected a number, got 'zero'"});
    check("nan.off", "OFF\n3 0 0\n0 0 0\n1 nan 0\n0 1 0\n", {":4:", "coordinate 'nan' is not a finite float32"});
    check("big.off", "OFF\n3 0 0\n0 0 0\n1 1e39 0\n0 1 0\n", {":4:", "coordinate '1e39' is not a finite float32"});
}

TEST(OffReader, VerticesBeyondTheDecodedLimitAreRefused) {
    test::TempDir dir;
    test::writeText(dir.file("box.off"), boxOff("OFF\n8 6 0\n"));
    const std::uint64_t saved = limit(Limit::DecodedBytes);
    setLimit(Limit::DecodedBytes, 64);  // 8 vertices take 96 bytes
    expectInputError([&] { readMesh(dir.file("box.off")); }, {dir.file("box.off"), "--max-decoded-bytes"});
    setLimit(Limit::DecodedBytes, saved);
    EXPECT_EQ(readMesh(dir.file("box.off")).front().vertexCount(), 8u);
}
