#include "mesh_test_files.h"
#include "test_support.h"

#include <darkroom/scene/mesh_readers.h>

#include <cmath>

using namespace darkroom;
using darkroom::test::expectError;
using darkroom::test::put;

namespace {

// Five points; one vertex cell (point 4), one polyline (0,1,2), one quad
// (0,1,2,3) and one strip (0,1,3,2): VTK numbers their cells 0, 1, 2, 3.
const float kPoints[5][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0.5f, 0.5f, 1}};
const std::vector<std::vector<int>> kVerts{{4}}, kLines{{0, 1, 2}}, kPolys{{0, 1, 2, 3}}, kStrips{{0, 1, 3, 2}};
const float kTemp[5] = {10, 11, 12, 13, 14};
const int kCellId[4] = {100, 101, 102, 103};
const float kVel[4][3] = {{3, 4, 0}, {0, 0, 1}, {1, 0, 0}, {0, 2, 0}};

std::string cellsAscii(const char* kw, const std::vector<std::vector<int>>& cells) {
    std::size_t size = 0;
    for (const auto& c : cells) size += c.size() + 1;
    std::string s = std::string(kw) + " " + std::to_string(cells.size()) + " " + std::to_string(size) + "\n";
    for (const auto& c : cells) {
        s += std::to_string(c.size());
        for (int v : c) s += " " + std::to_string(v);
        s += "\n";
    }
    return s;
}

std::string asciiVtk() {
    std::string s = "# vtk DataFile Version 3.0\ntest\nASCII\nDATASET POLYDATA\nPOINTS 5 float\n";
    for (const auto& p : kPoints) s += std::to_string(p[0]) + " " + std::to_string(p[1]) + " " + std::to_string(p[2]) + "\n";
    s += cellsAscii("VERTICES", kVerts) + cellsAscii("LINES", kLines) + cellsAscii("POLYGONS", kPolys) +
         cellsAscii("TRIANGLE_STRIPS", kStrips);
    s += "POINT_DATA 5\nSCALARS temp float 1\nLOOKUP_TABLE default\n";
    for (float t : kTemp) s += std::to_string(t) + "\n";
    s += "CELL_DATA 4\nSCALARS id int\nLOOKUP_TABLE default\n";
    for (int c : kCellId) s += std::to_string(c) + " ";
    s += "\nFIELD FieldData 1\nvel 3 4 float\n";
    for (const auto& v : kVel) s += std::to_string(v[0]) + " " + std::to_string(v[1]) + " " + std::to_string(v[2]) + "\n";
    return s;
}

std::string cellsBinary(const char* kw, const std::vector<std::vector<int>>& cells) {
    std::size_t size = 0;
    for (const auto& c : cells) size += c.size() + 1;
    std::string s = std::string(kw) + " " + std::to_string(cells.size()) + " " + std::to_string(size) + "\n";
    for (const auto& c : cells) {
        put(s, std::int32_t(c.size()), true);
        for (int v : c) put(s, std::int32_t(v), true);
    }
    return s + "\n";
}

std::string binaryVtk() {
    std::string s = "# vtk DataFile Version 3.0\ntest\nBINARY\nDATASET POLYDATA\nPOINTS 5 float\n";
    for (const auto& p : kPoints)
        for (float c : p) put(s, c, true);
    s += "\n" + cellsBinary("VERTICES", kVerts) + cellsBinary("LINES", kLines) + cellsBinary("POLYGONS", kPolys) +
         cellsBinary("TRIANGLE_STRIPS", kStrips);
    s += "POINT_DATA 5\nSCALARS temp double 1\nLOOKUP_TABLE default\n";
    for (float t : kTemp) put(s, double(t), true);
    s += "\nCELL_DATA 4\nSCALARS id int\nLOOKUP_TABLE default\n";
    for (int c : kCellId) put(s, std::int32_t(c), true);
    s += "\nFIELD FieldData 1\nvel 3 4 float\n";
    for (const auto& v : kVel)
        for (float c : v) put(s, c, true);
    return s + "\n";
}

void checkParts(const std::vector<SceneObject>& objs) {
    ASSERT_EQ(objs.size(), 3u);
    const SceneObject& surf = objs[0];
    const SceneObject& lines = objs[1];
    const SceneObject& verts = objs[2];
    EXPECT_EQ(surf.representation, Representation::Surface);
    EXPECT_EQ(lines.representation, Representation::Lines);
    EXPECT_EQ(verts.representation, Representation::Points);
    // Quad -> 2 triangles (local cell 0 = VTK cell 2), strip -> 2 (local 1 = cell 3).
    EXPECT_EQ(test::primitives(surf), 4u);
    EXPECT_EQ(surf.primitiveCell, (std::vector<std::uint32_t>{0, 0, 1, 1}));
    EXPECT_EQ(surf.field("id")->values, (std::vector<float>{102, 103}));
    EXPECT_EQ(surf.field("id")->association, ScalarField::Association::Cell);
    EXPECT_EQ(surf.vertexCount(), 4u);  // point 4 is only a vertex cell
    EXPECT_EQ(surf.field("temp")->values, (std::vector<float>{10, 11, 12, 13}));
    // Polyline of 3 points: 2 segments of cell 1.
    EXPECT_EQ(test::primitives(lines), 2u);
    EXPECT_EQ(lines.field("id")->values, (std::vector<float>{101}));
    EXPECT_EQ(lines.field("temp")->values, (std::vector<float>{10, 11, 12}));
    EXPECT_EQ(test::primitives(verts), 1u);
    EXPECT_EQ(verts.vertices[2], 1.f);
    EXPECT_EQ(verts.field("id")->values, (std::vector<float>{100}));
    EXPECT_EQ(verts.field("temp")->values, (std::vector<float>{14}));
    // A 3-component FIELD array: magnitude under its name, components as _0.._2.
    EXPECT_EQ(verts.field("vel")->values, (std::vector<float>{5}));
    EXPECT_EQ(verts.field("vel_1")->values, (std::vector<float>{4}));
    EXPECT_EQ(surf.field("vel_1")->values, (std::vector<float>{0, 2}));
    EXPECT_EQ(lines.field("vel_2")->values, (std::vector<float>{1}));
}

}  // namespace

TEST(VtkLegacyReader, AsciiPolyDataWithPointAndCellData) {
    test::TempDir dir;
    test::writeText(dir.file("a.vtk"), asciiVtk());
    const auto objs = readMesh(dir.file("a.vtk"));
    checkParts(objs);
    EXPECT_EQ(objs[0].name, "a/surface");
    EXPECT_EQ(objs[2].name, "a/points");
}

TEST(VtkLegacyReader, BinaryBigEndian) {
    test::TempDir dir;
    test::writeText(dir.file("b.vtk"), binaryVtk());
    checkParts(readMesh(dir.file("b.vtk")));
}

TEST(VtkLegacyReader, Version51OffsetsAndConnectivity) {
    test::TempDir dir;
    test::writeText(dir.file("n.vtk"),
                    "# vtk DataFile Version 5.1\nnew layout\nASCII\nDATASET POLYDATA\nPOINTS 4 float\n"
                    "0 0 0 1 0 0 1 1 0 0 1 0\n"
                    "POLYGONS 3 7\nOFFSETS vtktypeint64\n0 4 7\nCONNECTIVITY vtktypeint64\n0 1 2 3 0 2 1\n"
                    "CELL_DATA 2\nSCALARS c double\nLOOKUP_TABLE default\n5 6\n"
                    "METADATA\nINFORMATION 0\n\n");
    const auto objs = readMesh(dir.file("n.vtk"));
    ASSERT_EQ(objs.size(), 1u);
    EXPECT_EQ(test::primitives(objs[0]), 3u);
    EXPECT_EQ(objs[0].primitiveCell, (std::vector<std::uint32_t>{0, 0, 1}));
    EXPECT_EQ(objs[0].field("c")->values, (std::vector<float>{5, 6}));
}

TEST(VtkLegacyReader, TruncatedBinary) {
    test::TempDir dir;
    std::string s = binaryVtk();
    s.resize(s.find("POLYGONS") + 20);
    test::writeText(dir.file("cut.vtk"), s);
    expectError([&] { readMesh(dir.file("cut.vtk")); }, {dir.file("cut.vtk"), "POLYGONS", "truncated"});
}

TEST(VtkLegacyReader, BadIndexNonNumericHeaderAndDatasetType) {
    test::TempDir dir;
    std::string s = asciiVtk();
    s.replace(s.find("4 0 1 2 3"), 9, "4 0 1 2 8");
    test::writeText(dir.file("idx.vtk"), s);
    expectError([&] { readMesh(dir.file("idx.vtk")); }, {dir.file("idx.vtk") + ":15:", "POLYGONS", "point index 8 out of range"});

    s = asciiVtk();
    s.replace(s.find("10.000000"), 9, "ten");
    test::writeText(dir.file("num.vtk"), s);
    expectError([&] { readMesh(dir.file("num.vtk")); }, {dir.file("num.vtk") + ":22:", "'ten'"});

    test::writeText(dir.file("hdr.vtk"), "DATASET POLYDATA\nPOINTS 0 float\n");
    expectError([&] { readMesh(dir.file("hdr.vtk")); }, {dir.file("hdr.vtk") + ":1:", "# vtk DataFile"});

    test::writeText(dir.file("grid.vtk"), "# vtk DataFile Version 3.0\ng\nASCII\nDATASET STRUCTURED_POINTS\n");
    expectError([&] { readMesh(dir.file("grid.vtk")); }, {dir.file("grid.vtk") + ":4:", "unsupported dataset type 'STRUCTURED_POINTS'"});

    s = asciiVtk();
    s.replace(s.find("POINT_DATA 5"), 12, "POINT_DATA 6");
    test::writeText(dir.file("count.vtk"), s);
    expectError([&] { readMesh(dir.file("count.vtk")); }, {dir.file("count.vtk"), "SCALARS temp", "'CELL_DATA'"});
}
