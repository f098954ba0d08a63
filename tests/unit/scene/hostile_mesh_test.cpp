// Regressions for the mesh readers' faults found by fuzzing and by hand (issue
// 18): each input is built here, small, and must give a one-line InputError
// naming the file instead of a crash, a huge allocation or a blocked read.
#include "mesh_test_files.h"
#include "test_support.h"

#include <darkroom/scene/mesh_readers.h>
#include <darkroom/limits.h>

#include <sys/stat.h>

#include <cstdint>
#include <string>

using namespace darkroom;
using darkroom::test::expectError;
using darkroom::test::expectInputError;
using darkroom::test::put;

namespace {

const char* kXyz = "property float x\nproperty float y\nproperty float z\n";

// Three vertices, then two 'element face' blocks that both carry a cell
// property: the second block's count sized the cell arrays, the first wrote
// beyond them (a heap overflow under AddressSanitizer).
std::string twoFaceBlocks() {
    std::string s = std::string("ply\nformat binary_little_endian 1.0\nelement vertex 3\n") + kXyz +
                    "element face 4\nproperty list uchar int vertex_indices\nproperty float q\n"
                    "element face 1\nproperty list uchar int vertex_indices\nproperty float q\nend_header\n";
    for (float v : {0.f, 0.f, 0.f, 1.f, 0.f, 0.f, 0.f, 1.f, 0.f}) put(s, v, false);
    for (int f = 0; f < 5; ++f) {
        put(s, std::uint8_t(3), false);
        for (int v : {0, 1, 2}) put(s, std::int32_t(v), false);
        put(s, float(f), false);
    }
    return s;
}

}  // namespace

TEST(HostileMesh, PlyWithTwoFaceElementsIsRefused) {
    test::TempDir dir;
    const std::string path = dir.file("two-faces.ply");
    test::writeText(path, twoFaceBlocks());
    expectInputError([&] { readMesh(path); }, {path + ":", "a second 'element face'", "expected one"});
}

TEST(HostileMesh, PlyElementWithoutPropertiesAllocatesNothing) {
    test::TempDir dir;
    // 500 million vertices in a few dozen bytes: once over 6 GB of points.
    const std::string ascii = dir.file("ascii.ply");
    test::writeText(ascii, "ply\nformat ascii 1.0\nelement vertex 500000000\nend_header\n");
    expectInputError([&] { readMesh(ascii); }, {ascii, "element 'vertex' declares 500000000 entries"});
    // Binary: an element of size 0 fits any file, so the vertex lacks x instead.
    const std::string binary = dir.file("binary.ply");
    test::writeText(binary, "ply\nformat binary_little_endian 1.0\nelement vertex 500000000\nend_header\n");
    expectInputError([&] { readMesh(binary); }, {binary + ":3:", "no scalar property 'x'"});
    // An unknown element without properties is skipped whole, however large its count.
    const std::string other = dir.file("other.ply");
    std::string s = std::string("ply\nformat binary_little_endian 1.0\nelement vertex 1\n") + kXyz +
                    "element nothing 4000000000\nend_header\n";
    for (float v : {1.f, 2.f, 3.f}) put(s, v, false);
    test::writeText(other, s);
    const auto objs = readMesh(other);
    ASSERT_EQ(objs.size(), 1u);
    EXPECT_EQ(objs[0].vertexCount(), 1u);
}

TEST(HostileMesh, PlyCountsBeyondTheFileAreRefusedBeforeAllocating) {
    test::TempDir dir;
    const std::string path = dir.file("short.ply");
    std::string s = std::string("ply\nformat binary_little_endian 1.0\nelement vertex 400000000\n") + kXyz + "end_header\n";
    for (float v : {1.f, 2.f, 3.f}) put(s, v, false);
    test::writeText(path, s);
    expectInputError([&] { readMesh(path); }, {path + ":3:", "400000000 entries", "truncated?"});
}

TEST(HostileMesh, PlyVertexCountWithinTheDecodedLimit) {
    test::TempDir dir;
    const std::string path = dir.file("big.ply");
    std::string s = std::string("ply\nformat binary_little_endian 1.0\nelement vertex 100\n") + kXyz + "end_header\n";
    for (int i = 0; i < 300; ++i) put(s, float(i), false);
    test::writeText(path, s);
    const std::uint64_t saved = limit(Limit::DecodedBytes);
    setLimit(Limit::DecodedBytes, 1000);
    expectInputError([&] { readMesh(path); }, {path, "--max-decoded-bytes"});
    setLimit(Limit::DecodedBytes, saved);
    EXPECT_EQ(readMesh(path).front().vertexCount(), 100u);
}

TEST(HostileMesh, PlyWithoutCoordinatesIsAnError) {
    test::TempDir dir;
    for (const char* axis : {"x", "y", "z"}) {
        std::string props;
        for (const char* a : {"x", "y", "z"})
            if (std::string(a) != axis) props += std::string("property float ") + a + "\n";
        const std::string path = dir.file(std::string("no-") + axis + ".ply");
        test::writeText(path, "ply\nformat ascii 1.0\nelement vertex 1\n" + props + "end_header\n1 2\n");
        expectInputError([&] { readMesh(path); }, {path + ":3:", std::string("no scalar property '") + axis + "'"});
    }
    const std::string none = dir.file("no-vertex.ply");
    test::writeText(none, "ply\nformat ascii 1.0\nelement face 0\nproperty list uchar int vertex_indices\nend_header\n");
    expectInputError([&] { readMesh(none); }, {none, "no 'element vertex'"});
}

TEST(HostileMesh, EmptyObjIsAnError) {
    test::TempDir dir;
    for (const std::string text : {"", "# only a comment\n", "o name\ng group\nvt 0 0\n"}) {
        const std::string path = dir.file("empty.obj");
        test::writeText(path, text);
        expectInputError([&] { readMesh(path); }, {path, "no vertices"});
    }
}

TEST(HostileMesh, DeeplyNestedVtkXmlIsRefusedWithoutRecursion) {
    test::TempDir dir;
    const std::string path = dir.file("deep.vtp");
    // 300,000 levels overflowed the stack in the element tree's walks.
    const int depth = 300000;
    std::string s = "<VTKFile type=\"PolyData\">\n";
    s.reserve(std::size_t(depth) * 7 + 64);
    for (int i = 0; i < depth; ++i) s += "<a>";
    for (int i = 0; i < depth; ++i) s += "</a>";
    s += "</VTKFile>\n";
    test::writeText(path, s);
    expectInputError([&] { readMesh(path); }, {path + ":2:", "byte offset", "nested", "expected at most 256"});
}

TEST(HostileMesh, ZlibDataLargerThanItsArrayIsRefusedBeforeInflating) {
    test::TempDir dir;
    // One point (3 float32 = 12 bytes), whose zlib header declares 1 GiB in
    // 1024 blocks of 1 MiB each; the compressed blocks are not even there.
    std::string head;
    put(head, std::uint32_t(1024), false);
    put(head, std::uint32_t(1 << 20), false);
    put(head, std::uint32_t(0), false);
    for (int i = 0; i < 1024; ++i) put(head, std::uint32_t(1100), false);
    const std::string path = dir.file("bomb.vtp");
    test::writeText(path, "<VTKFile type=\"PolyData\" compressor=\"vtkZLibDataCompressor\">\n<PolyData>\n"
                          "<Piece NumberOfPoints=\"1\">\n<Points>\n"
                          "<DataArray type=\"Float32\" NumberOfComponents=\"3\" format=\"binary\">" +
                              test::base64(head) + "</DataArray>\n</Points>\n</Piece>\n</PolyData>\n</VTKFile>\n");
    expectInputError([&] { readMesh(path); }, {path + ":5:", "declares 1073741824 bytes", "needs at most 12"});
}

TEST(HostileMesh, ZlibDataBeyondTheDecodedLimitIsRefused) {
    test::TempDir dir;
    // Connectivity has no count to compare with: the limit alone applies.
    const std::string raw(64 * 1024, '\0');
    const std::string comp = test::zlibCompress(raw);
    std::string bin;
    put(bin, std::uint32_t(1), false);
    put(bin, std::uint32_t(raw.size()), false);
    put(bin, std::uint32_t(raw.size()), false);
    put(bin, std::uint32_t(comp.size()), false);
    bin += comp;
    const std::string path = dir.file("conn.vtp");
    test::writeText(path, "<VTKFile type=\"PolyData\" compressor=\"vtkZLibDataCompressor\">\n<PolyData>\n"
                          "<Piece NumberOfPoints=\"0\" NumberOfPolys=\"1\">\n<Polys>\n"
                          "<DataArray type=\"Int32\" Name=\"connectivity\" format=\"binary\">" +
                              test::base64(bin) +
                              "</DataArray>\n</Polys>\n</Piece>\n</PolyData>\n</VTKFile>\n");
    const std::uint64_t saved = limit(Limit::DecodedBytes);
    setLimit(Limit::DecodedBytes, 4096);
    expectInputError([&] { readMesh(path); }, {path + ":5:", "connectivity", "--max-decoded-bytes"});
    setLimit(Limit::DecodedBytes, saved);
}

TEST(HostileMesh, SpecialFilesAreRefusedWithoutBlocking) {
    test::TempDir dir;
    for (const char* ext : {"ply", "obj", "vtk", "vtp", "vtu"}) {
        // A FIFO nobody writes to: opening it for reading would block.
        const std::string fifo = dir.file(std::string("pipe.") + ext);
        ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
        expectInputError([&] { readMesh(fifo); }, {fifo, "a FIFO", "expected a regular file"});
        const std::string folder = dir.file(std::string("folder.") + ext);
        ASSERT_EQ(::mkdir(folder.c_str(), 0700), 0);
        expectInputError([&] { readMesh(folder); }, {folder, "a directory"});
    }
    // /dev/zero under a mesh's name: a symlink, followed to the device.
    const std::string zero = dir.file("zero.ply");
    ASSERT_EQ(::symlink("/dev/zero", zero.c_str()), 0);
    expectInputError([&] { readMesh(zero); }, {zero, "a character device"});
}
