// The direct reader of binary PLY triangle meshes (ply/ply_triangles.h) against
// the general reader: the same objects, value for value, whatever the byte
// order, window size or number of parallel tasks; and every file it does not
// take, or finds wrong, read or refused by the general reader with its message.
#include "direct_reader_checks.h"
#include "mesh_test_files.h"
#include "test_support.h"

#include <darkroom/limits.h>
#include <darkroom/scene/mesh_readers.h>

#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

using namespace darkroom;
using darkroom::test::expectError;
using darkroom::test::expectSameObjects;
using darkroom::test::put;

namespace {

// A bumpy w x h grid of points (x y z, a float "height", a uchar "flag") and
// its triangles (a uchar-counted list, a float "quality" and a short "tag"
// per face), listed in a scrambled order so that the numbering by first use
// differs from the file's; `unused` points no triangle uses sit after the
// first row. The default 230 x 231 grid has 105,340 triangles (an even count;
// `extra` faces make it odd), more than one parallel task's share.
struct Grid {
    int w = 230, h = 231;
    int unused = 3;
    bool big = false;
    bool ascii = false;
    std::string indexType = "int";
    std::string countType = "uchar";
    std::vector<std::vector<int>> extra;  // faces after the grid's

    int points() const { return w * h + unused; }
    int faces() const { return 2 * (w - 1) * (h - 1) + int(extra.size()); }
    int point(int i, int j) const { return j * w + i + (j > 0 ? unused : 0); }

    std::string header() const {
        const std::string fmt = ascii ? "ascii" : big ? "binary_big_endian" : "binary_little_endian";
        return "ply\nformat " + fmt + " 1.0\ncomment made by ply_direct_test\nelement vertex " +
               std::to_string(points()) +
               "\nproperty float x\nproperty float y\nproperty float z\nproperty float height\nproperty uchar flag\n"
               "element face " + std::to_string(faces()) + "\nproperty list " + countType + " " + indexType +
               " vertex_indices\nproperty float quality\nproperty short tag\nend_header\n";
    }
};

class Writer {
public:
    explicit Writer(const Grid& g) : g_(g), s_(g.header()) {}

    void vertex(float x, float y, float z, int flag) {
        if (g_.ascii) return line("%.9g %.9g %.9g %.9g %d\n", double(x), double(y), double(z), double(3 * y), flag);
        for (float v : {x, y, z, 3 * y}) put(s_, v, g_.big);
        put(s_, std::uint8_t(flag), g_.big);
    }

    void face(const std::vector<int>& v, float quality, int tag) {
        if (g_.ascii) {
            s_ += std::to_string(v.size());
            for (int i : v) s_ += " " + std::to_string(i);
            return line(" %.9g %d\n", double(quality), tag);
        }
        if (g_.countType == "int") put(s_, std::int32_t(v.size()), g_.big);
        else put(s_, std::uint8_t(v.size()), g_.big);
        for (int i : v) {
            if (g_.indexType == "float") put(s_, float(i), g_.big);
            else if (g_.indexType == "ushort") put(s_, std::uint16_t(i), g_.big);
            else put(s_, std::int32_t(i), g_.big);
        }
        put(s_, quality, g_.big);
        put(s_, std::int16_t(tag), g_.big);
    }

    std::string take() { return std::move(s_); }

private:
    template <class... A>
    void line(const char* f, A... a) {
        char b[200];
        std::snprintf(b, sizeof b, f, a...);
        s_ += b;
    }
    const Grid& g_;
    std::string s_;
};

std::string plyOf(const Grid& g) {
    Writer out(g);
    for (int j = 0; j < g.h; ++j) {
        for (int i = 0; i < g.w; ++i)
            out.vertex(0.01f * float(i), 0.02f * float((i * 7 + j * 3) % 11), 0.01f * float(j), (i + j) % 256);
        if (j == 0)
            for (int k = 0; k < g.unused; ++k) out.vertex(1e6f, 1e6f, 1e6f, 255);
    }
    const int cells = (g.w - 1) * (g.h - 1);
    for (int n = 0; n < cells; ++n) {
        const int c = int((std::int64_t(n) * 7919) % cells);  // 7919 is prime and no factor of cells: a permutation
        const int i = c % (g.w - 1), j = c / (g.w - 1);
        const int a = g.point(i, j), b = g.point(i + 1, j), d = g.point(i, j + 1), e = g.point(i + 1, j + 1);
        out.face({a, d, b}, float(c) * 0.5f, n % 3000);
        out.face({b, d, e}, -float(c), -(n % 3000));
    }
    for (const auto& f : g.extra) out.face(f, 42.f, 7);
    return out.take();
}

const auto general = &test::generalReader<PlyReadOptions>;
const auto windows = &test::windowsOf<PlyReadOptions>;

std::vector<SceneObject> readDirectOnly(const std::string& path, const PlyReadOptions& options = {}) {
    return test::readDirectOnly([](const std::string& p, const PlyReadOptions& o) { return readPly(p, o); }, path, options);
}

}  // namespace

TEST(PlyDirect, SameMeshAsTheGeneralReaderInEitherByteOrder) {
    for (bool big : {false, true}) {
        test::TempDir dir;
        Grid g;
        g.big = big;
        g.extra = {{5, 6, 7}};  // an odd number of triangles
        const std::string path = dir.file("grid.ply");
        test::writeText(path, plyOf(g));
        const auto serial = readPly(path, general());
        ASSERT_EQ(serial.size(), 1u);
        EXPECT_EQ(serial[0].indices.size(), 3u * std::size_t(g.faces()));
        EXPECT_EQ(serial[0].vertexCount(), std::size_t(g.w * g.h));  // the unused points are dropped
        EXPECT_TRUE(serial[0].primitiveCell.empty());
        ASSERT_EQ(serial[0].fields.size(), 4u);  // height, flag, quality, tag
        // One window, split over parallel tasks; then windows of a few
        // records, none a whole number of records long.
        expectSameObjects(readDirectOnly(path), serial);
        expectSameObjects(readDirectOnly(path, windows(1000)), serial);
        expectSameObjects(readDirectOnly(path, windows(1)), serial);
        expectSameObjects(readMesh(path), serial);
    }
}

TEST(PlyDirect, BinaryAndAsciiReadAlike) {
    test::TempDir dir;
    Grid g;
    g.w = 17;
    g.h = 9;
    test::writeText(dir.file("b.ply"), plyOf(g));
    g.ascii = true;
    test::writeText(dir.file("a.ply"), plyOf(g));
    auto binary = readPly(dir.file("b.ply"));
    auto ascii = readPly(dir.file("a.ply"));
    binary[0].name = ascii[0].name;
    expectSameObjects(binary, ascii);
}

TEST(PlyDirect, OtherIndexAndCountTypes) {
    test::TempDir dir;
    Grid g;
    g.w = g.h = 40;
    g.indexType = "ushort";
    g.countType = "int";
    const std::string path = dir.file("t.ply");
    test::writeText(path, plyOf(g));
    expectSameObjects(readDirectOnly(path, windows(333)), readPly(path, general()));
    // Whole-number float indices are valid; the general reader checks them.
    g.indexType = "float";
    test::writeText(path, plyOf(g));
    expectError([&] { readDirectOnly(path); }, {path, "--max-input-bytes"});
    expectSameObjects(readPly(path, windows(333)), readPly(path, general()));
}

// A quad after many triangles: the direct reader has read windows of
// triangles when it meets it, and gives the file to the general reader.
TEST(PlyDirect, APolygonLateInTheFileFallsBackToTheGeneralReader) {
    test::TempDir dir;
    Grid g;
    g.extra = {{0, 1, 2}, {0, 1, 231, 230}};
    const std::string path = dir.file("mixed.ply");
    test::writeText(path, plyOf(g));
    const auto objs = readPly(path, windows(4096));
    expectSameObjects(objs, readPly(path, general()));
    ASSERT_EQ(objs[0].primitiveCell.size(), std::size_t(g.faces()) + 1);  // the quad is two triangles of one cell
    EXPECT_EQ(objs[0].primitiveCell.back(), std::uint32_t(g.faces() - 1));
}

TEST(PlyDirect, TruncatedFileNamesTheFileAndElement) {
    test::TempDir dir;
    Grid g;
    std::string s = plyOf(g);
    const std::string path = dir.file("cut.ply");
    for (std::size_t cut : {std::size_t(1), std::size_t(5), s.size() / 2}) {
        test::writeText(path, s.substr(0, s.size() - cut));
        expectError([&] { readMesh(path); }, {path, "element 'face'", "truncated"});
    }
    test::writeText(path, s.substr(0, g.header().size() + 100));
    expectError([&] { readMesh(path); }, {path, "element 'vertex'", "truncated"});
}

TEST(PlyDirect, IndexOutOfRangeIsTheGeneralReadersError) {
    test::TempDir dir;
    Grid g;
    g.w = g.h = 50;
    g.extra = {{0, 1, 2}, {0, 99999, 2}};
    const std::string path = dir.file("bad.ply");
    test::writeText(path, plyOf(g));
    expectError([&] { readPly(path, windows(500)); },
                {path, "element 'face' " + std::to_string(g.faces() - 1), "vertex index 99999 out of range"});
    g.extra = {{0, 1, 2}, {0, -1, 2}};
    test::writeText(path, plyOf(g));
    expectError([&] { readPly(path); }, {path, "vertex index -1 out of range"});
}

// The direct reader reads the first 64 KiB for the header; a longer one
// (many comments) is left to the general reader, which reads it.
TEST(PlyDirect, LongHeaderIsReadWhole) {
    test::TempDir dir;
    Grid g;
    g.w = g.h = 30;
    std::string s = plyOf(g);
    std::string comments;
    for (int i = 0; i < 2000; ++i) comments += "comment a long header line to push end_header past 64 KiB\n";
    s.insert(s.find("element vertex"), comments);
    const std::string path = dir.file("long.ply");
    test::writeText(path, s);
    const auto objs = readPly(path);
    ASSERT_EQ(objs.size(), 1u);
    EXPECT_EQ(objs[0].indices.size(), 3u * std::size_t(g.faces()));
    expectSameObjects(objs, readPly(path, general()));
}

// The direct reader never holds the file whole, so --max-input-bytes (the
// largest file read whole) does not stop it; the general reader would refuse.
TEST(PlyDirect, ReadsFilesLargerThanTheWholeFileLimit) {
    test::TempDir dir;
    Grid g;
    g.w = g.h = 60;
    const std::string path = dir.file("big.ply");
    test::writeText(path, plyOf(g));
    const auto expected = readPly(path, general());
    std::vector<SceneObject> direct;
    EXPECT_NO_THROW(direct = readDirectOnly(path));
    expectSameObjects(direct, expected);
    expectError([&] { readDirectOnly(path, general()); }, {path, "--max-input-bytes"});
}
