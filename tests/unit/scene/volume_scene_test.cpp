// Volumes in scene files: representation boundary / isosurface (contourBy,
// isosurfaces) / slice (planes), the boundary by default, keys checked, and a
// capture of all three through the runner like any other object.
#include "test_support.h"

#include <darkroom/error.h>
#include <darkroom/data/image_io.h>
#include <darkroom/scene/scene_file.h>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>

using namespace darkroom;
using ::testing::HasSubstr;

namespace {

// An n^3 grid over [-1, 1]^3 in Kuhn tetrahedra, field r2 = |p|^2, ascii .vtu.
std::string tetrahedraVtu(int n) {
    const int m = n + 1;
    std::string pts, r2, conn, offs, types;
    for (int k = 0; k < m; ++k)
        for (int j = 0; j < m; ++j)
            for (int i = 0; i < m; ++i) {
                const double x = -1 + 2.0 * i / n, y = -1 + 2.0 * j / n, z = -1 + 2.0 * k / n;
                pts += std::to_string(x) + " " + std::to_string(y) + " " + std::to_string(z) + " ";
                r2 += std::to_string(x * x + y * y + z * z) + " ";
            }
    auto id = [&](int i, int j, int k) { return std::to_string(i + m * (j + m * k)); };
    int cells = 0;
    for (int k = 0; k < n; ++k)
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i) {
                const int steps[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
                for (const auto& order : steps) {
                    int c[3] = {0, 0, 0};
                    conn += id(i, j, k) + " ";
                    for (int a : order) {
                        ++c[a];
                        conn += id(i + c[0], j + c[1], k + c[2]) + " ";
                    }
                    offs += std::to_string(4 * ++cells) + " ";
                    types += "10 ";
                }
            }
    return "<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" version=\"1.0\">\n<UnstructuredGrid>\n"
           "<Piece NumberOfPoints=\"" + std::to_string(m * m * m) + "\" NumberOfCells=\"" + std::to_string(cells) +
           "\">\n<PointData><DataArray type=\"Float64\" Name=\"r2\" format=\"ascii\">" + r2 +
           "</DataArray></PointData>\n<Points><DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">" +
           pts + "</DataArray></Points>\n<Cells><DataArray type=\"Int32\" Name=\"connectivity\" format=\"ascii\">" +
           conn + "</DataArray><DataArray type=\"Int32\" Name=\"offsets\" format=\"ascii\">" + offs +
           "</DataArray><DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">" + types +
           "</DataArray></Cells>\n</Piece>\n</UnstructuredGrid>\n</VTKFile>\n";
}

const char* kObjects = R"(objects:
  - name: outside
    file: v.vtu
    translate: [-3, 0, 0]
  - name: shells
    file: v.vtu
    representation: isosurface
    contourBy: r2
    isosurfaces: [0.25, 0.6]
  - name: cut
    file: v.vtu
    representation: slice
    planes:
      - {origin: [0, 0, 0.1], normal: [0, 0, 1]}
    translate: [3, 0, 0]
)";

std::string errorOf(const std::string& yaml, const std::string& dir) {
    try {
        parseSceneFile(yaml, "s.yaml", dir);
    } catch (const Error& e) {
        return e.what();
    }
    return "no error";
}

}  // namespace

TEST(VolumeScene, ThreeRepresentationsOfOneFileBecomeThreeObjects) {
    test::TempDir dir;
    test::writeText(dir.file("v.vtu"), tetrahedraVtu(8));
    const SceneDescription d = parseSceneFile(kObjects, "s.yaml", dir.path());
    ASSERT_EQ(d.scene->objects.size(), 3u);
    const auto& boundary = d.scene->objects[0];
    EXPECT_EQ(boundary.name, "outside");
    EXPECT_EQ(boundary.primitiveCount(), 6u * 8 * 8 * 2);  // the cube's faces, two triangles per square
    EXPECT_EQ(d.scene->objects[1].name, "shells");
    EXPECT_GT(d.scene->objects[1].primitiveCount(), 200u);
    ASSERT_NE(d.scene->objects[2].field("r2"), nullptr);
    for (std::size_t i = 0; i < d.scene->objects[2].vertexCount(); ++i)
        EXPECT_NEAR(d.scene->objects[2].vertices[4 * i + 2], 0.1, 1e-6);  // on the plane (no translate in z)
    EXPECT_EQ(d.request.scalars, std::vector<std::string>{"r2"});
}

TEST(VolumeScene, KeysOfOtherRepresentationsAndMissingValuesAreErrors) {
    test::TempDir dir;
    test::writeText(dir.file("v.vtu"), tetrahedraVtu(2));
    EXPECT_THAT(errorOf("objects:\n  - file: v.vtu\n    contourBy: r2\n", dir.path()),
                HasSubstr("s.yaml:3:16: 'contourBy' only applies to representation: isosurface"));
    EXPECT_THAT(errorOf("objects:\n  - file: v.vtu\n    representation: isosurface\n    contourBy: r2\n", dir.path()),
                HasSubstr("s.yaml:3:21: representation isosurface needs 'isosurfaces' (a list of values)"));
    EXPECT_THAT(errorOf("objects:\n  - file: v.vtu\n    representation: slice\n    planes: [{origin: [0, 0, 0]}]\n",
                        dir.path()),
                HasSubstr("a slice plane needs a 'normal'"));
    EXPECT_THAT(errorOf("objects:\n  - generator: plane\n    representation: boundary\n", dir.path()),
                HasSubstr("needs a volume file (.vtu with 3D cells or .vti), not a generator"));
    EXPECT_THAT(errorOf("objects:\n  - file: v.vtu\n    representation: volume\n", dir.path()),
                HasSubstr("representation must be surface, lines or points (volumes: boundary, isosurface or slice)"));
    EXPECT_THAT(errorOf("objects:\n  - file: v.vtu\n    representation: isosurface\n    contourBy: p\n"
                        "    isosurfaces: [1]\n",
                        dir.path()),
                HasSubstr("s.yaml:2:11: object 'v': " + dir.path() + "/v.vtu: no point field 'p' to contour (point fields: r2;"));
}

TEST(VolumeScene, CapturesLikeAnyOtherObject) {
    test::TempDir dir;
    test::writeText(dir.file("v.vtu"), tetrahedraVtu(8));
    test::writeText(dir.file("s.yaml"), std::string(kObjects) + R"(cameras:
  fov: 10
  resolution: [240, 80]
  list:
    - {position: [0, -14, 4], target: [0, 0, 0], up: [0, 0, 1]}
)");
    const std::string cmd = std::string(DARKROOM_RUNNER) + " capture " + dir.file("s.yaml") + " --output " +
                            dir.file("s.cdb") + " > " + dir.file("log") + " 2>&1";
    ASSERT_EQ(std::system(cmd.c_str()), 0) << test::readText(dir.file("log"));
    const auto image = readImage(dir.file("s.cdb") + "/camera=0.exr");
    const float* z = image->requireFloat("Z");
    // Each third of the picture sees its object: box, shells, slice.
    int hits[3] = {0, 0, 0};
    for (int y = 0; y < 80; ++y)
        for (int x = 0; x < 240; ++x)
            if (std::isfinite(z[y * 240 + x])) ++hits[x / 80];
    EXPECT_GT(hits[0], 1000);
    EXPECT_GT(hits[1], 500);
    EXPECT_GT(hits[2], 10);
}
