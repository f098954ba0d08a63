// The STL reader: one closed box written as OFF, ASCII STL and binary STL
// (one with a header starting with "solid") reads as the same vertices and
// triangles; ASCII variants; merged positions; each refusal with its place.
#include "off_stl_test_files.h"
#include "test_support.h"

#include <darkroom/limits.h>
#include <darkroom/scene/mesh_readers.h>

#include <array>
#include <cmath>
#include <cstring>
#include <limits>

using namespace darkroom;
using darkroom::test::expectInputError;

namespace {

// A box from (-1, -2, -3) to (1, 2, 3): 8 vertices, 6 outward quads as 12 triangles.
const float kBox[8][3] = {{-1, -2, -3}, {1, -2, -3}, {1, 2, -3}, {-1, 2, -3},
                          {-1, -2, 3},  {1, -2, 3},  {1, 2, 3},  {-1, 2, 3}};
const int kQuads[6][4] = {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4}, {2, 3, 7, 6}, {0, 4, 7, 3}, {1, 2, 6, 5}};

SceneObject box() {
    SceneObject o;
    for (const auto& v : kBox) o.vertices.insert(o.vertices.end(), {v[0], v[1], v[2], 0.f});
    for (const auto& q : kQuads) {
        for (int v : {q[0], q[1], q[2], q[0], q[2], q[3]}) o.indices.push_back(std::uint32_t(v));
    }
    return o;
}

std::array<float, 3> corner(const SceneObject& o, std::size_t index) {
    const std::uint32_t v = o.indices[index];
    return {o.vertices[4 * v], o.vertices[4 * v + 1], o.vertices[4 * v + 2]};
}

// The box's 12 triangles, corner by corner, its 8 vertices and its bounds.
void expectBox(const std::vector<SceneObject>& objs, const std::string& what) {
    ASSERT_EQ(objs.size(), 1u) << what;
    const SceneObject& o = objs[0];
    const SceneObject want = box();
    EXPECT_EQ(o.representation, Representation::Surface) << what;
    EXPECT_EQ(o.vertexCount(), 8u) << what << ": the soup's 36 corners merged into 8 vertices";
    ASSERT_EQ(o.indices.size(), want.indices.size()) << what;
    for (std::size_t i = 0; i < want.indices.size(); ++i) EXPECT_EQ(corner(o, i), corner(want, i)) << what << " corner " << i;
    Scene scene;
    scene.objects = objs;
    const Bounds b = scene.bounds();
    EXPECT_EQ(b.lo, (Vec3{-1, -2, -3})) << what;
    EXPECT_EQ(b.hi, (Vec3{1, 2, 3})) << what;
}

std::string binaryFile(const std::string& header = "binary STL written by the test") { return test::binaryStl(box(), header); }

void putFloat(std::string& s, std::size_t at, float v) { std::memcpy(s.data() + at, &v, 4); }

}  // namespace

TEST(StlReader, BoxAsOffAsciiStlAndBinaryStlReadsAlike) {
    test::TempDir dir;
    test::writeText(dir.file("box.off"), test::offText(box()));
    test::writeText(dir.file("ascii.stl"), test::asciiStl(box()));
    test::writeText(dir.file("binary.stl"), binaryFile());
    const auto off = readMesh(dir.file("box.off"));
    const auto ascii = readMesh(dir.file("ascii.stl"));
    const auto binary = readMesh(dir.file("binary.stl"));
    expectBox(off, "OFF");
    expectBox(ascii, "ASCII STL");
    expectBox(binary, "binary STL");
    EXPECT_EQ(ascii[0].name, "ascii");
    // Numbered in first use, as the OFF reader's surface is: the same arrays.
    for (const auto* stl : {&ascii, &binary}) {
        EXPECT_EQ((*stl)[0].vertices, off[0].vertices);
        EXPECT_EQ((*stl)[0].indices, off[0].indices);
    }
    // One cell a triangle: the identity map is left implied.
    EXPECT_TRUE(binary[0].primitiveCell.empty());
}

TEST(StlReader, BinaryWhoseHeaderStartsWithSolid) {
    test::TempDir dir;
    const std::string bytes = binaryFile("solid box exported by a CAD tool");
    ASSERT_EQ(bytes.substr(0, 5), "solid");
    ASSERT_EQ(bytes.size(), 84u + 50u * 12u);
    test::writeText(dir.file("cad.STL"), bytes);
    expectBox(readMesh(dir.file("cad.STL")), "binary STL with a 'solid' header");
}

TEST(StlReader, AsciiVariants) {
    test::TempDir dir;
    std::string upper = test::asciiStl(box());
    for (const char* w : {"solid", "facet", "normal", "outer", "loop", "vertex", "endloop", "endfacet", "endsolid"})
        for (std::size_t at = 0; (at = upper.find(w, at)) != std::string::npos; at += std::strlen(w))
            for (std::size_t k = 0; k < std::strlen(w); ++k) upper[at + k] = char(std::toupper(upper[at + k]));
    std::string noNormal = test::asciiStl(box());
    for (std::size_t at = 0; (at = noNormal.find("facet normal 0 0 0", at)) != std::string::npos;)
        noNormal.replace(at, 18, "facet");
    std::string msvcNan = test::asciiStl(box());
    msvcNan.replace(msvcNan.find("normal 0 0 0"), 12, "normal -1.#IND00 -1.#IND00 -1.#IND00");
    // Two solids of 6 facets each (tools that join files write this).
    const std::string whole = test::asciiStl(box(), "a");
    std::size_t sixth = 0;
    for (int f = 0; f < 6; ++f) sixth = whole.find("endfacet", sixth) + 9;
    const std::string twoSolids = whole.substr(0, sixth) + "endsolid a\nsolid b\n" + whole.substr(sixth);
    std::string crlf;
    for (char c : test::asciiStl(box(), "")) crlf += c == '\n' ? std::string("\r\n") : std::string(1, c);
    for (const auto& [name, text] : std::vector<std::pair<std::string, std::string>>{
             {"upper.stl", upper}, {"no-normal.stl", noNormal}, {"msvc-nan.stl", msvcNan},
             {"two-solids.stl", twoSolids}, {"crlf.stl", crlf}, {"indented.stl", "  \n" + test::asciiStl(box())}}) {
        test::writeText(dir.file(name), text);
        expectBox(readMesh(dir.file(name)), name);
    }
}

TEST(StlReader, PositionsMergeBitForBitWithSignedZerosAlike) {
    test::TempDir dir;
    // Two triangles sharing the edge (0,0,0)-(1,0,0), one writing -0; a
    // triangle of zero area is kept (a ray never hits it).
    test::writeText(dir.file("m.stl"), "solid m\n"
                                       "facet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\nendloop\nendfacet\n"
                                       "facet normal 0 0 1\nouter loop\nvertex -0 0 0\nvertex 0 -1 0\nvertex 1 0 -0.0\nendloop\nendfacet\n"
                                       "facet normal 0 0 0\nouter loop\nvertex 5 5 5\nvertex 5 5 5\nvertex 5 5 5.0000001\nendloop\nendfacet\n"
                                       "endsolid m\n");
    const auto objs = readMesh(dir.file("m.stl"));
    ASSERT_EQ(objs.size(), 1u);
    EXPECT_EQ(objs[0].vertexCount(), 5u);  // 4 for the two triangles; 5 and 5.0000001 are one float
    EXPECT_EQ(objs[0].indices, (std::vector<std::uint32_t>{0, 1, 2, 0, 3, 1, 4, 4, 4}));
}

TEST(StlReader, AsciiErrorsNameTheLineAndWhatWasExpected) {
    test::TempDir dir;
    auto check = [&](const std::string& name, const std::string& text, const std::vector<std::string>& parts) {
        test::writeText(dir.file(name), text);
        std::vector<std::string> all{dir.file(name)};
        all.insert(all.end(), parts.begin(), parts.end());
        expectInputError([&] { readMesh(dir.file(name)); }, all);
    };
    const std::string open = "solid t\nfacet normal 0 0 1\nouter loop\n";  // lines 1-3
    const std::string three = "vertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\n";  // lines 4-6
    check("quad.stl", open + three + "vertex 1 1 0\nendloop\nendfacet\nendsolid\n",
          {":7:", "expected 'endloop' after 3 vertices (STL facets are triangles), got 'vertex'"});
    check("truncated.stl", open + "vertex 0 0 0\nvertex 1 0 0\n",
          {":6:", "unexpected end of file, expected 'vertex' (a facet has 3)", "truncated?"});
    check("text.stl", open + "vertex 0 0 0\nvertex 1 x 0\n", {":5:", "expected a vertex coordinate, got 'x'"});
    check("nan.stl", open + "vertex nan 0 0\n", {":4:", "facet 0: 'nan' is a non-finite coordinate (nan)"});
    check("huge.stl", open + "vertex 1e39 0 0\n", {":4:", "'1e39' is a non-finite coordinate (inf)"});
    check("no-end.stl", open + three + "endloop\nendfacet\n", {":9:", "unexpected end of file, expected 'facet' or 'endsolid'"});
    check("facets.stl", "solid t\nfacets\n", {":2:", "expected 'facet' or 'endsolid', got 'facets'"});
    check("outer.stl", "solid t\nfacet normal 0 0 1\nloop\n", {":3:", "expected 'outer', got 'loop'"});
    check("after.stl", open + three + "endloop\nendfacet\nendsolid t\nhello\n", {":10:", "expected 'solid', got 'hello'"});
    check("empty-solid.stl", "solid t\nendsolid t\n", {"no triangles; expected an STL with at least one facet"});
}

TEST(StlReader, BinaryErrorsNameTheTriangleAndTheSizes) {
    test::TempDir dir;
    auto check = [&](const std::string& name, const std::string& bytes, const std::vector<std::string>& parts) {
        test::writeText(dir.file(name), bytes);
        std::vector<std::string> all{dir.file(name) + ": "};
        all.insert(all.end(), parts.begin(), parts.end());
        expectInputError([&] { readMesh(dir.file(name)); }, all);
    };
    // A truncated binary file whose header starts with "solid": its floats' NULs say binary.
    check("truncated.stl", binaryFile("solid box").substr(0, 600),
          {"binary STL header declares 12 triangles, which take 84 + 50 x 12 = 684 bytes, but the file has 600",
           "truncated, or not an STL file?"});
    check("longer.stl", binaryFile() + "extra", {"= 684 bytes, but the file has 689"});
    check("short.stl", "abc", {"3 bytes: neither an ASCII STL (expected 'solid' first) nor a binary one"});
    check("empty.stl", "", {"0 bytes: neither an ASCII STL"});
    std::string nan = binaryFile();
    putFloat(nan, 84 + 50 * 3 + 12 + 12, std::numeric_limits<float>::quiet_NaN());
    check("nan.stl", nan, {"triangle 3 (byte 234): vertex 1 has a non-finite coordinate (nan)"});
    std::string inf = binaryFile();
    putFloat(inf, 84 + 50 * 11 + 12 + 24 + 8, std::numeric_limits<float>::infinity());
    check("inf.stl", inf, {"triangle 11 (byte 634): vertex 2 has a non-finite coordinate (inf)"});
    check("none.stl", binaryFile().substr(0, 80) + std::string(4, '\0'), {"no triangles"});
}

TEST(StlReader, TrianglesBeyondTheDecodedLimitAreRefused) {
    test::TempDir dir;
    test::writeText(dir.file("box.stl"), binaryFile());
    const std::uint64_t saved = limit(Limit::DecodedBytes);
    setLimit(Limit::DecodedBytes, 400);  // 12 triangles' corners take 432 bytes
    expectInputError([&] { readMesh(dir.file("box.stl")); }, {dir.file("box.stl"), "12 STL triangles", "--max-decoded-bytes"});
    setLimit(Limit::DecodedBytes, saved);
    expectBox(readMesh(dir.file("box.stl")), "within the limit");
}
