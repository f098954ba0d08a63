// Corrupted and truncated copies of valid files: every reader must either
// succeed or throw darkroom::Error naming the file, never crash or throw
// anything else. A small deterministic fuzz (fixed seeds) run on every build.
#include "off_stl_test_files.h"
#include "test_support.h"

#include <darkroom/scene/mesh_readers.h>

#include <random>

using namespace darkroom;
using darkroom::test::put;

namespace {

std::string binaryPly() {
    std::string s =
        "ply\nformat binary_little_endian 1.0\nelement vertex 4\nproperty float x\nproperty float y\nproperty float z\n"
        "property float t\nelement face 2\nproperty list uchar int vertex_indices\nproperty int c\n"
        "element tristrips 1\nproperty list int int vertex_indices\nend_header\n";
    for (int i = 0; i < 4; ++i)
        for (float v : {float(i & 1), float(i >> 1), 0.f, float(i)}) put(s, v, false);
    for (int f = 0; f < 2; ++f) {
        put(s, std::uint8_t(3), false);
        for (int v : {0, 1 + f, 2 + f}) put(s, std::int32_t(v), false);
        put(s, std::int32_t(f), false);
    }
    put(s, std::int32_t(5), false);
    for (int v : {0, 1, -1, 2, 3}) put(s, std::int32_t(v), false);
    return s;
}

std::string binaryVtk() {
    std::string s = "# vtk DataFile Version 3.0\nx\nBINARY\nDATASET POLYDATA\nPOINTS 3 float\n";
    for (float v : {0.f, 0.f, 0.f, 1.f, 0.f, 0.f, 0.f, 1.f, 0.f}) put(s, v, true);
    s += "\nPOLYGONS 1 4\n";
    for (int v : {3, 0, 1, 2}) put(s, std::int32_t(v), true);
    s += "\nLINES 1 3\n";
    for (int v : {2, 0, 2}) put(s, std::int32_t(v), true);
    s += "\nCELL_DATA 2\nSCALARS c int 1\nLOOKUP_TABLE default\n";
    for (int v : {5, 6}) put(s, std::int32_t(v), true);
    s += "\nPOINT_DATA 3\nFIELD f 1\nv 2 3 double\n";
    for (int i = 0; i < 6; ++i) put(s, double(i), true);
    return s + "\n";
}

std::string appendedVtp(bool zlib) {
    std::string data, conn = test::bytesOf(std::vector<std::int64_t>{0, 1, 2, 0, 2, 3});
    std::string pts = test::bytesOf(std::vector<float>{0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0});
    std::string off = test::bytesOf(std::vector<std::int64_t>{3, 6});
    std::vector<std::size_t> offsets;
    for (const std::string* a : {&pts, &conn, &off}) {
        offsets.push_back(data.size());
        if (zlib) {
            const std::string z = test::zlibCompress(*a);
            for (std::uint64_t w : {std::uint64_t(1), std::uint64_t(a->size()), std::uint64_t(a->size()), std::uint64_t(z.size())})
                put(data, w, false);
            data += z;
        } else {
            put(data, std::uint64_t(a->size()), false);
            data += *a;
        }
    }
    return std::string("<VTKFile type=\"PolyData\" version=\"1.0\" byte_order=\"LittleEndian\" header_type=\"UInt64\"") +
           (zlib ? " compressor=\"vtkZLibDataCompressor\"" : "") +
           ">\n<PolyData><Piece NumberOfPoints=\"4\" NumberOfPolys=\"2\">\n"
           "<Points><DataArray type=\"Float32\" NumberOfComponents=\"3\" format=\"appended\" offset=\"" + std::to_string(offsets[0]) + "\"/></Points>\n"
           "<Polys><DataArray type=\"Int64\" Name=\"connectivity\" format=\"appended\" offset=\"" + std::to_string(offsets[1]) + "\"/>\n"
           "<DataArray type=\"Int64\" Name=\"offsets\" format=\"appended\" offset=\"" + std::to_string(offsets[2]) + "\"/></Polys>\n"
           "</Piece></PolyData>\n<AppendedData encoding=\"raw\">_" + data + "\n</AppendedData></VTKFile>\n";
}

std::string asciiObj() { return "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 1\nf 1 2 3\nf -1 -2 -3 1\nl 1 2 4\n"; }

std::string asciiOff() {
    return "CNOFF # a comment\n4 2 0\n0 0 0 0 0 1 1 0 0 1\n1 0 0 0 0 1 0 1 0 1\n0 1 0 0 0 1 0 0 1 1\n"
           "1 1 1 0 0 1 1 1 1 1\n3 0 1 2\n4 3 2 1 0 0.5 0.5 0.5\n";
}

// Two triangles: the binary form's floats hold NULs, so no flip makes it ASCII by accident.
SceneObject twoTriangles() {
    SceneObject o;
    o.vertices = {0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 1, 1, 1, 0};
    o.indices = {0, 1, 2, 2, 1, 3};
    return o;
}

void fuzz(const std::string& name, const std::string& valid) {
    test::TempDir dir;
    const std::string path = dir.file(name);
    test::writeText(path, valid);
    ASSERT_NO_THROW(readMesh(path)) << name << " must be valid before it is corrupted";
    std::mt19937 rng(12345);
    int errors = 0;
    for (int round = 0; round < 250; ++round) {
        std::string s = valid;
        if (round % 4 == 0) {
            s.resize(rng() % s.size());  // truncation
        } else {
            const int flips = 1 + int(rng() % 4);
            for (int k = 0; k < flips; ++k) {
                const std::size_t at = rng() % s.size();
                const int kind = int(rng() % 3);
                s[at] = kind == 0 ? char(rng()) : kind == 1 ? char('0' + rng() % 10) : char(0xff);
            }
        }
        test::writeText(path, s);
        try {
            readMesh(path);
        } catch (const Error& e) {
            ++errors;
            EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << e.what();
        } catch (const std::exception& e) {
            ADD_FAILURE() << name << " round " << round << ": non-darkroom exception: " << e.what();
        }
    }
    EXPECT_GT(errors, 30) << "most corruptions of " << name << " should be detected";
}

}  // namespace

TEST(ReaderRobustness, BinaryPly) { fuzz("m.ply", binaryPly()); }
TEST(ReaderRobustness, BinaryLegacyVtk) { fuzz("m.vtk", binaryVtk()); }
TEST(ReaderRobustness, AppendedVtp) { fuzz("m.vtp", appendedVtp(false)); }
TEST(ReaderRobustness, AppendedZlibVtp) { fuzz("z.vtp", appendedVtp(true)); }
TEST(ReaderRobustness, Obj) { fuzz("m.obj", asciiObj()); }
TEST(ReaderRobustness, Off) { fuzz("m.off", asciiOff()); }
TEST(ReaderRobustness, AsciiStl) { fuzz("a.stl", test::asciiStl(twoTriangles())); }
TEST(ReaderRobustness, BinaryStl) { fuzz("b.stl", test::binaryStl(twoTriangles(), "solid header")); }
