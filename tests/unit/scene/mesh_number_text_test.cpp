// Values beyond long long in a mesh file's counts and indices are named in
// the error as written. The readers converted them to long long to print
// them: undefined behaviour (UBSan, found by the VTK legacy fuzz harness in
// tests/fuzz), and the message said -9223372036854775808.
#include "mesh_test_files.h"
#include "test_support.h"

#include <darkroom/scene/mesh_readers.h>

#include <string>

using namespace darkroom;
using darkroom::test::expectError;

TEST(MeshNumberText, VtkLegacyCellSizeBeyondLongLong) {
    test::TempDir dir;
    const std::string path = dir.file("huge-cell.vtk");
    test::writeText(path,
                    "# vtk DataFile Version 3.0\nhuge cell size\nASCII\nDATASET POLYDATA\n"
                    "POINTS 3 float\n0 0 0 1 0 0 0 1 0\nVERTICES 1 2\n2.2e54 1\n");
    expectError([&] { readVtkLegacy(path); }, {path, "has 2.2e+54 points"});
}

TEST(MeshNumberText, VtkLegacyPointIndexBeyondLongLong) {
    test::TempDir dir;
    const std::string path = dir.file("huge-index.vtk");
    test::writeText(path,
                    "# vtk DataFile Version 3.0\nhuge index\nASCII\nDATASET POLYDATA\n"
                    "POINTS 3 float\n0 0 0 1 0 0 0 1 0\nPOLYGONS 1 4\n3 0 1 -1e300\n");
    expectError([&] { readVtkLegacy(path); }, {path, "point index -1e+300 out of range"});
}

TEST(MeshNumberText, PlyVertexIndexBeyondLongLong) {
    test::TempDir dir;
    const std::string path = dir.file("huge-index.ply");
    test::writeText(path,
                    "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                    "property float z\nelement face 1\nproperty list uchar double vertex_indices\nend_header\n"
                    "0 0 0\n1 0 0\n0 1 0\n3 0 1 1e300\n");
    expectError([&] { readPly(path); }, {path, "vertex index 1e+300 out of range"});
}
