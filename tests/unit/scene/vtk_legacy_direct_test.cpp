// The direct reader of binary legacy VTK triangle meshes
// (vtk_legacy/legacy_triangles.h) against the general reader: the same
// objects, value for value, in either cell layout, with float or double
// points, with or without point scalars, whatever the window size; and
// every file it does not take, or finds wrong, read or refused by the
// general reader with its message.
#include "direct_reader_checks.h"
#include "mesh_test_files.h"
#include "test_support.h"

#include <darkroom/limits.h>
#include <darkroom/scene/mesh_readers.h>

#include <array>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

using namespace darkroom;
using darkroom::test::expectError;
using darkroom::test::bits;
using darkroom::test::expectSameObjects;
using darkroom::test::put;

namespace {

// A bumpy w x h grid of points and its triangles, listed in a scrambled
// order so that the numbering by first use differs from the file's;
// `unused` points no triangle uses sit after the first row. The default
// 230 x 231 grid has 105,340 triangles, more than one parallel task's share.
struct Grid {
    int w = 230, h = 231;
    int unused = 3;
    bool ascii = false;
    bool doublePoints = false;
    bool offsets = false;                 // VTK 5.1's OFFSETS/CONNECTIVITY layout
    std::string indexType = "vtktypeint64";  // of the 5.1 layout
    int scalars = 1;                      // 0; 1: float "height"; 2: and double "slope"
    std::vector<std::vector<int>> extra;  // cells after the grid's
    std::string after;                    // text after the point data

    int points() const { return w * h + unused; }
    int point(int i, int j) const { return j * w + i + (j > 0 ? unused : 0); }
};

class Writer {
public:
    explicit Writer(const Grid& g) : g_(g) {}

    void text(const std::string& t) { s_ += t; }

    void value(double v, bool isDouble) {
        if (g_.ascii) return isDouble ? number(v, "%.17g ") : number(double(float(v)), "%.9g ");
        if (isDouble) put(s_, v, true);
        else put(s_, float(v), true);
    }

    void integer(long long v, const std::string& type) {
        if (g_.ascii) return number(double(v), "%.0f ");
        if (type == "vtktypeint64") put(s_, std::int64_t(v), true);
        else if (type == "unsigned_char") put(s_, std::uint8_t(v), true);
        else put(s_, std::int32_t(v), true);
    }

    std::string take() { return std::move(s_); }

private:
    void number(double v, const char* format) {
        char b[64];
        std::snprintf(b, sizeof b, format, v);
        s_ += b;
    }
    const Grid& g_;
    std::string s_;
};

std::vector<std::vector<int>> cellsOf(const Grid& g) {
    std::vector<std::vector<int>> cells;
    const int quads = (g.w - 1) * (g.h - 1);
    for (int n = 0; n < quads; ++n) {
        const int c = int((std::int64_t(n) * 7919) % quads);  // 7919 is prime and no factor of quads: a permutation
        const int i = c % (g.w - 1), j = c / (g.w - 1);
        const int a = g.point(i, j), b = g.point(i + 1, j), d = g.point(i, j + 1), e = g.point(i + 1, j + 1);
        cells.push_back({a, d, b});
        cells.push_back({b, d, e});
    }
    cells.insert(cells.end(), g.extra.begin(), g.extra.end());
    return cells;
}

void writeCells(const Grid& g, Writer& out) {
    const auto cells = cellsOf(g);
    std::size_t size = 0;
    for (const auto& c : cells) size += c.size();
    if (g.offsets) {
        out.text("POLYGONS " + std::to_string(cells.size() + 1) + " " + std::to_string(size) + "\nOFFSETS " +
                 g.indexType + "\n");
        long long offset = 0;
        out.integer(0, g.indexType);
        for (const auto& c : cells) out.integer(offset += (long long)c.size(), g.indexType);
        out.text("\nCONNECTIVITY " + g.indexType + "\n");
        for (const auto& c : cells)
            for (int v : c) out.integer(v, g.indexType);
    } else {
        out.text("POLYGONS " + std::to_string(cells.size()) + " " + std::to_string(size + cells.size()) + "\n");
        for (const auto& c : cells) {
            out.integer((long long)c.size(), "int");
            for (int v : c) out.integer(v, "int");
        }
    }
    out.text("\n");
}

std::string vtkOf(const Grid& g) {
    Writer out(g);
    out.text(std::string("# vtk DataFile Version ") + (g.offsets ? "5.1" : "3.0") + "\nvtk_legacy_direct_test\n" +
             (g.ascii ? "ASCII" : "BINARY") + "\nDATASET POLYDATA\nPOINTS " + std::to_string(g.points()) +
             (g.doublePoints ? " double\n" : " float\n"));
    std::vector<std::array<double, 3>> xyz;
    for (int j = 0; j < g.h; ++j) {
        for (int i = 0; i < g.w; ++i) xyz.push_back({0.01 * i, 0.02 * ((i * 7 + j * 3) % 11), 0.01 * j});
        if (j == 0)
            for (int k = 0; k < g.unused; ++k) xyz.push_back({1e6, 1e6, 1e6});
    }
    for (const auto& p : xyz)
        for (double c : p) out.value(c, g.doublePoints);
    out.text("\n");
    writeCells(g, out);
    if (g.scalars > 0) {
        out.text("POINT_DATA " + std::to_string(g.points()) + "\nSCALARS height float 1\nLOOKUP_TABLE default\n");
        for (const auto& p : xyz) out.value(3 * p[1], false);
        out.text("\n");
    }
    if (g.scalars > 1) {
        out.text("SCALARS slope double\n");  // no LOOKUP_TABLE line, no component count
        for (const auto& p : xyz) out.value(p[0] * 0.1 + p[2], true);
        out.text("\n");
    }
    out.text(g.after);
    return out.take();
}

const auto general = &test::generalReader<VtkLegacyReadOptions>;
const auto windows = &test::windowsOf<VtkLegacyReadOptions>;

std::vector<SceneObject> readDirectOnly(const std::string& path, const VtkLegacyReadOptions& options = {}) {
    return test::readDirectOnly([](const std::string& p, const VtkLegacyReadOptions& o) { return readVtkLegacy(p, o); }, path, options);
}

// The general reader's message for `path` (empty if it reads it).
std::string generalError(const std::string& path) {
    try {
        readVtkLegacy(path, general());
    } catch (const Error& e) {
        return e.what();
    }
    return {};
}

// The file is left to the general reader: the direct one alone cannot read it.
void expectFallback(const std::string& path) {
    expectError([&] { readDirectOnly(path); }, {path, "--max-input-bytes"});
    expectSameObjects(readVtkLegacy(path, windows(1000)), readVtkLegacy(path, general()));
}

}  // namespace

TEST(VtkLegacyDirect, SameMeshAsTheGeneralReaderInEitherLayout) {
    for (bool offsets : {false, true})
        for (bool doublePoints : {false, true})
            for (int scalars : {0, 1, 2}) {
                SCOPED_TRACE(std::to_string(offsets) + std::to_string(doublePoints) + std::to_string(scalars));
                test::TempDir dir;
                Grid g;
                g.offsets = offsets;
                g.doublePoints = doublePoints;
                g.scalars = scalars;
                g.extra = {{5, 6, 7}};  // an odd number of triangles
                const std::string path = dir.file("grid.vtk");
                test::writeText(path, vtkOf(g));
                const auto serial = readVtkLegacy(path, general());
                ASSERT_EQ(serial.size(), 1u);
                EXPECT_EQ(serial[0].name, "grid");
                EXPECT_EQ(serial[0].vertexCount(), std::size_t(g.w * g.h));  // the unused points are dropped
                EXPECT_TRUE(serial[0].primitiveCell.empty());
                ASSERT_EQ(serial[0].fields.size(), std::size_t(scalars));
                // One window, split over parallel tasks; then windows of a
                // few records, none a whole number of records long.
                expectSameObjects(readDirectOnly(path), serial);
                expectSameObjects(readDirectOnly(path, windows(1000)), serial);
                expectSameObjects(readDirectOnly(path, windows(1)), serial);
                expectSameObjects(readMesh(path), serial);
            }
}

TEST(VtkLegacyDirect, SmallAndOtherIndexTypes) {
    test::TempDir dir;
    const std::string path = dir.file("s.vtk");
    for (const char* type : {"int", "vtktypeint64", "unsigned_char"}) {
        Grid g;
        g.w = 3;
        g.h = 2;
        g.unused = 0;
        g.offsets = true;
        g.indexType = type;
        test::writeText(path, vtkOf(g));
        expectSameObjects(readDirectOnly(path, windows(7)), readVtkLegacy(path, general()));
    }
    Grid one;
    one.w = one.h = 2;
    test::writeText(path, vtkOf(one));
    const auto objs = readDirectOnly(path);
    ASSERT_EQ(objs.size(), 1u);
    EXPECT_EQ(objs[0].indices.size(), 6u);
    expectSameObjects(objs, readVtkLegacy(path, general()));
}

TEST(VtkLegacyDirect, BinaryAndAsciiReadAlike) {
    test::TempDir dir;
    Grid g;
    g.w = 17;
    g.h = 9;
    g.scalars = 2;
    test::writeText(dir.file("b.vtk"), vtkOf(g));
    g.ascii = true;
    test::writeText(dir.file("a.vtk"), vtkOf(g));
    auto binary = readVtkLegacy(dir.file("b.vtk"));
    auto ascii = readVtkLegacy(dir.file("a.vtk"));
    binary[0].name = ascii[0].name;
    expectSameObjects(binary, ascii);
}

// A quad after many triangles: the direct reader has read windows of
// triangles when it meets it, and gives the file to the general reader.
TEST(VtkLegacyDirect, APolygonLateInTheFileFallsBackToTheGeneralReader) {
    for (bool offsets : {false, true}) {
        test::TempDir dir;
        Grid g;
        g.offsets = offsets;
        g.extra = {{0, 1, 2}, {0, 1, 231, 230}};
        const std::string path = dir.file("mixed.vtk");
        test::writeText(path, vtkOf(g));
        expectFallback(path);
        const auto objs = readVtkLegacy(path, windows(4096));
        const std::size_t cells = cellsOf(g).size();
        ASSERT_EQ(objs[0].primitiveCell.size(), cells + 1);  // the quad is two triangles of one cell
        EXPECT_EQ(objs[0].primitiveCell.back(), std::uint32_t(cells - 1));
    }
}

// What the direct reader leaves to the general one, which reads it as before.
TEST(VtkLegacyDirect, OtherContentFallsBackToTheGeneralReader) {
    test::TempDir dir;
    const std::string path = dir.file("other.vtk");
    std::string line = "LINES 1 3\n";
    for (int v : {2, 0, 1}) put(line, std::int32_t(v), true);
    const std::vector<std::string> afters = {
        "FIELD FieldData 1\nt 1 117 float\n" + std::string(4 * 117, '\0') + "\n",
        "VECTORS v float\n" + std::string(12 * 117, '\0') + "\n",
        "METADATA\nINFORMATION 0\n\n",
        line + "\n",
    };
    for (const auto& after : afters) {
        SCOPED_TRACE(after.substr(0, 12));
        Grid g;
        g.w = 13;
        g.h = 9;  // 117 points
        g.unused = 0;
        g.after = after;
        test::writeText(path, vtkOf(g));
        expectFallback(path);
    }
    // A 2-component SCALARS array: a magnitude and two components.
    Grid g;
    g.w = g.h = 5;
    g.scalars = 0;
    g.after = "POINT_DATA " + std::to_string(g.points()) + "\nSCALARS uv float 2\n" +
              std::string(std::size_t(8 * g.points()), '\0') + "\n";
    test::writeText(path, vtkOf(g));
    expectFallback(path);
    // Triangle strips.
    g.after = "TRIANGLE_STRIPS 1 5\n";
    for (int v : {4, 0, 1, 5, 6}) put(g.after, std::int32_t(v), true);
    test::writeText(path, vtkOf(g));
    expectFallback(path);
}

TEST(VtkLegacyDirect, CellDataFallsBackToTheGeneralReader) {
    test::TempDir dir;
    const std::string path = dir.file("cells.vtk");
    Grid g;
    g.w = g.h = 6;
    const std::size_t cells = cellsOf(g).size();
    g.after = "CELL_DATA " + std::to_string(cells) + "\nSCALARS c float\nLOOKUP_TABLE default\n";
    for (std::size_t c = 0; c < cells; ++c) put(g.after, float(c), true);
    test::writeText(path, vtkOf(g));
    expectFallback(path);
    EXPECT_EQ(readVtkLegacy(path)[0].field("c")->values.size(), cells);
}

TEST(VtkLegacyDirect, TruncatedFileGivesTheGeneralReadersError) {
    test::TempDir dir;
    for (bool offsets : {false, true}) {
        Grid g;
        g.w = g.h = 40;
        g.offsets = offsets;
        const std::string s = vtkOf(g);
        const std::string path = dir.file("cut.vtk");
        for (std::size_t keep : {s.size() - 2, s.size() - 100, s.find("SCALARS") + 30, s.find("POLYGONS") + 50,
                                 s.find("POINTS") + 200}) {
            test::writeText(path, s.substr(0, keep));
            const std::string expected = generalError(path);
            ASSERT_FALSE(expected.empty()) << keep;
            EXPECT_NE(expected.find("truncated"), std::string::npos) << expected;
            expectError([&] { readVtkLegacy(path); }, {expected});
        }
    }
}

TEST(VtkLegacyDirect, IndexOutOfRangeIsTheGeneralReadersError) {
    test::TempDir dir;
    for (bool offsets : {false, true}) {
        Grid g;
        g.w = g.h = 50;
        g.offsets = offsets;
        g.extra = {{0, 1, 2}, {0, 99999, 2}};
        const std::string path = dir.file("bad.vtk");
        test::writeText(path, vtkOf(g));
        expectError([&] { readVtkLegacy(path, windows(500)); }, {path, "POLYGONS", "point index 99999 out of range"});
        g.extra = {{0, 1, 2}, {0, -1, 2}};
        test::writeText(path, vtkOf(g));
        expectError([&] { readVtkLegacy(path); }, {generalError(path)});
    }
}

// Point data of another count is the general reader's error.
TEST(VtkLegacyDirect, PointDataOfAnotherCount) {
    test::TempDir dir;
    Grid g;
    g.w = g.h = 7;
    g.scalars = 0;
    g.after = "POINT_DATA 3\nSCALARS t float\nLOOKUP_TABLE default\n" + std::string(12, '\0') + "\n";
    const std::string path = dir.file("count.vtk");
    test::writeText(path, vtkOf(g));
    const std::string expected = generalError(path);
    ASSERT_FALSE(expected.empty());
    expectError([&] { readVtkLegacy(path); }, {expected});
}

// The direct reader never holds the file whole, so --max-input-bytes does
// not stop it; --max-decoded-bytes bounds what it decodes.
TEST(VtkLegacyDirect, LimitsOfTheDirectReader) {
    test::TempDir dir;
    Grid g;
    g.w = g.h = 60;
    const std::string path = dir.file("big.vtk");
    test::writeText(path, vtkOf(g));
    std::vector<SceneObject> direct;
    EXPECT_NO_THROW(direct = readDirectOnly(path));
    expectSameObjects(direct, readVtkLegacy(path, general()));
    expectError([&] { readDirectOnly(path, general()); }, {path, "--max-input-bytes"});
    const test::ScopedLimit decoded(Limit::DecodedBytes, 1000);
    expectError([&] { readVtkLegacy(path); }, {path, "--max-decoded-bytes"});
}

// A keyword line cut by the direct reader's 4 KiB look: a long title.
TEST(VtkLegacyDirect, LongTitleIsReadByTheGeneralReader) {
    test::TempDir dir;
    Grid g;
    g.w = g.h = 8;
    std::string s = vtkOf(g);
    s.insert(s.find("\nBINARY"), std::string(5000, 't'));
    const std::string path = dir.file("title.vtk");
    test::writeText(path, s);
    expectFallback(path);
}

// Signalling NaNs come out as the general reader gives them (quiet, the
// payload kept), bit for bit; so do -0 and infinities.
TEST(VtkLegacyDirect, NaNsAndSignedZerosReadAlike) {
    test::TempDir dir;
    Grid g;
    g.w = g.h = 9;
    g.scalars = 2;
    std::string s = vtkOf(g);
    const std::size_t points = s.find("float\n") + 6;
    s.replace(points, 4, std::string("\x7f\x80\x00\x01", 4));      // x of point 0: a signalling NaN
    s.replace(points + 4, 4, std::string("\x80\x00\x00\x00", 4));  // its y: -0
    s.replace(points + 8, 4, std::string("\xff\x80\x00\x00", 4));  // its z: -infinity
    const std::size_t height = s.find("LOOKUP_TABLE default\n") + 21;
    s.replace(height, 4, std::string("\x7f\xa0\x00\x00", 4));
    const std::size_t slope = s.find("slope double\n") + 13;
    s.replace(slope, 8, std::string("\x7f\xf0\x00\x00\x00\x00\x00\x01", 8));  // a signalling double NaN
    const std::string path = dir.file("nan.vtk");
    test::writeText(path, s);
    const auto direct = readDirectOnly(path);
    expectSameObjects(direct, readVtkLegacy(path, general()));
    std::uint32_t x = 0;
    std::memcpy(&x, &direct[0].vertices[0], 4);
    EXPECT_EQ(x, 0x7fc00001u);
}
