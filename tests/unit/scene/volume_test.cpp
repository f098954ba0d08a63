// Volume representations with known answers: a linear field's isosurface is
// a plane (exact positions, area, no cracks across tetrahedra, hexahedra,
// wedges, pyramids and voxels); a sphere's isosurface is closed with the
// sphere's area and volume; boundaries are closed and face outwards; fields
// are interpolated exactly where they are linear; slices lie on their plane.
#include "test_support.h"
#include "volume_test_meshes.h"

#include <darkroom/error.h>
#include <darkroom/scene/mesh_readers.h>
#include <darkroom/scene/volume.h>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <map>
#include <utility>

using namespace darkroom;
using darkroom::test::cubes;
using ::testing::HasSubstr;

namespace {

Vec3 vertex(const SceneObject& o, std::size_t i) {
    return {o.vertices[4 * i], o.vertices[4 * i + 1], o.vertices[4 * i + 2]};
}

struct MeshMeasures {
    double area = 0;
    double signedVolume = 0;  // divergence theorem: > 0 when a closed surface faces outwards
    std::size_t openEdges = 0;
    std::size_t overusedEdges = 0;
};

MeshMeasures measure(const SceneObject& o) {
    MeshMeasures m;
    std::map<std::pair<std::uint32_t, std::uint32_t>, int> edges;
    for (std::size_t t = 0; t + 2 < o.indices.size(); t += 3) {
        const Vec3 a = vertex(o, o.indices[t]), b = vertex(o, o.indices[t + 1]), c = vertex(o, o.indices[t + 2]);
        m.area += 0.5 * length(cross(b - a, c - a));
        m.signedVolume += dot(a, cross(b, c)) / 6.0;
        for (int e = 0; e < 3; ++e) {
            std::uint32_t p = o.indices[t + e], q = o.indices[t + (e + 1) % 3];
            if (p > q) std::swap(p, q);
            ++edges[{p, q}];
        }
    }
    for (const auto& [k, n] : edges) {
        m.openEdges += n == 1;
        m.overusedEdges += n > 2;
    }
    return m;
}

VolumeRepresentation iso(const std::string& field, std::vector<double> values) {
    VolumeRepresentation r;
    r.kind = VolumeRepresentation::Kind::Isosurface;
    r.contourBy = field;
    r.isovalues = std::move(values);
    return r;
}

const ScalarField& fieldOf(const SceneObject& o, const std::string& name) {
    const ScalarField* f = o.field(name);
    if (!f) throw Error("no field " + name);
    return *f;
}

}  // namespace

TEST(VolumeIsosurface, SingleTetrahedronGivesTheExactTriangleWithInterpolatedFields) {
    VolumeMesh v;
    v.source = "tet";
    v.points = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1};
    v.connectivity = {0, 1, 2, 3};
    v.offsets = {0, 4};
    v.types = {10};
    v.pointData = {{"f", 1, {0, 1, 1, 1}}, {"g", 1, {0, 2, 0, 0}}, {"v", 3, {0, 0, 0, 1, 0, 0, 0, 3, 0, 0, 0, 0}}};
    v.cellData = {{"c", 1, {7}}};
    const SceneObject o = volumeSurface(v, iso("f", {0.5}), "t");
    ASSERT_EQ(o.indices.size(), 3u);
    ASSERT_EQ(o.vertexCount(), 3u);
    const ScalarField& g = fieldOf(o, "g");
    double gSum = 0;
    for (std::size_t i = 0; i < 3; ++i) {
        const Vec3 p = vertex(o, i);
        EXPECT_DOUBLE_EQ(p.x + p.y + p.z, 0.5) << "on the plane x + y + z = 0.5";
        EXPECT_FLOAT_EQ(g.values[i], float(2 * p.x));  // g = 2x at the vertex (x = 0.5 or 0)
        gSum += g.values[i];
    }
    EXPECT_DOUBLE_EQ(gSum, 1.0);
    // Vector fields: magnitude and components, as the mesh readers give them.
    EXPECT_NE(o.field("v"), nullptr);
    EXPECT_NE(o.field("v_1"), nullptr);
    EXPECT_EQ(fieldOf(o, "c").association, ScalarField::Association::Cell);
    EXPECT_EQ(fieldOf(o, "c").values, std::vector<float>{7});
    // The normal points from high f to low f: towards the origin.
    const Vec3 n = cross(vertex(o, o.indices[1]) - vertex(o, o.indices[0]), vertex(o, o.indices[2]) - vertex(o, o.indices[0]));
    EXPECT_LT(dot(n, Vec3{1, 1, 1}), 0);
}

// A plane through grid points: values exactly at the level weld into one
// vertex instead of several coincident ones, and no triangle is degenerate.
TEST(VolumeSlice, PlaneThroughGridPointsHasNoDegenerateTriangles) {
    const VolumeMesh v = cubes(2, "hex", {});
    VolumeRepresentation r;
    r.kind = VolumeRepresentation::Kind::Slice;
    r.planes = {{{1, 1, 1}, {0, 0, 1}}};
    const SceneObject o = volumeSurface(v, r, "cut");
    const MeshMeasures m = measure(o);
    EXPECT_NEAR(m.area, 4.0, 1e-9);
    EXPECT_EQ(m.overusedEdges, 0u);
    for (std::size_t t = 0; t < o.indices.size(); t += 3) {
        const Vec3 a = vertex(o, o.indices[t]);
        EXPECT_GT(length(cross(vertex(o, o.indices[t + 1]) - a, vertex(o, o.indices[t + 2]) - a)), 1e-12);
    }
}

// A linear field is reproduced exactly by every split (the centroid's mean is
// the field at the centroid), so x = 1.3 cuts a flat 3 x 3 square without cracks.
TEST(VolumeIsosurface, LinearFieldGivesAFlatCracklessPlaneInEveryCellType) {
    for (const std::string kind : {"tet", "hex", "voxel", "wedge", "pyramid"}) {
        SCOPED_TRACE(kind);
        const VolumeMesh v = cubes(3, kind, {{"x", [](const Vec3& p) { return p.x; }},
                                            {"h", [](const Vec3& p) { return 2 * p.z - p.y; }}});
        const SceneObject o = volumeSurface(v, iso("x", {1.3}), "plane");
        const MeshMeasures m = measure(o);
        EXPECT_NEAR(m.area, 9.0, 1e-9);
        EXPECT_EQ(m.overusedEdges, 0u);
        // Only the square's rim is open: 4 sides, cut into at least 3 edges each.
        const ScalarField& h = fieldOf(o, "h");
        for (std::size_t i = 0; i < o.vertexCount(); ++i) {
            const Vec3 p = vertex(o, i);
            EXPECT_NEAR(p.x, 1.3, 1e-6);
            EXPECT_NEAR(h.values[i], 2 * p.z - p.y, 1e-5) << "linear fields interpolate exactly";
        }
        std::size_t rimEdges = 0;
        std::map<std::pair<std::uint32_t, std::uint32_t>, int> edges;
        for (std::size_t t = 0; t < o.indices.size(); t += 3)
            for (int e = 0; e < 3; ++e) {
                std::uint32_t p = o.indices[t + e], q = o.indices[t + (e + 1) % 3];
                if (p > q) std::swap(p, q);
                ++edges[{p, q}];
            }
        for (const auto& [k, n] : edges)
            if (n == 1) {
                const Vec3 a = vertex(o, k.first), b = vertex(o, k.second);
                auto onRim = [](const Vec3& p) { return p.y < 1e-6 || p.y > 3 - 1e-6 || p.z < 1e-6 || p.z > 3 - 1e-6; };
                EXPECT_TRUE(onRim(a) && onRim(b)) << "a crack inside the square";
                ++rimEdges;
            }
        EXPECT_EQ(rimEdges, m.openEdges);
    }
}

TEST(VolumeIsosurface, SphereOnImageDataIsClosedWithTheSphereAreaAndVolume) {
    VolumeMesh v;
    v.source = "image";
    const int n = 41;
    v.dims = {n, n, n};
    v.origin = {-1, -1, -1};
    v.spacing = {2.0 / (n - 1), 2.0 / (n - 1), 2.0 / (n - 1)};
    VolumeArray r2{"r2", 1, {}};
    for (std::size_t i = 0; i < v.pointCount(); ++i) {
        const Vec3 p = v.point(i);
        r2.values.push_back(float(dot(p, p)));
    }
    v.pointData.push_back(std::move(r2));
    const SceneObject o = volumeSurface(v, iso("r2", {0.5, 0.25}), "spheres");
    const MeshMeasures m = measure(o);
    EXPECT_EQ(m.openEdges, 0u);
    EXPECT_EQ(m.overusedEdges, 0u);
    const double pi = 3.14159265358979323846;
    const double area = 4 * pi * (0.5 + 0.25), volume = 4.0 / 3.0 * pi * (std::pow(0.5, 1.5) + std::pow(0.25, 1.5));
    EXPECT_NEAR(m.area / area, 1.0, 0.01);
    // r2 grows outwards, so normals (high to low) face inwards: negative volume.
    EXPECT_NEAR(-m.signedVolume / volume, 1.0, 0.01);
}

TEST(VolumeBoundary, FacesOutwardsIsClosedAndCarriesCellFields) {
    for (const std::string kind : {"tet", "hex", "voxel", "wedge", "pyramid"}) {
        SCOPED_TRACE(kind);
        const VolumeMesh v = cubes(2, kind, {{"z", [](const Vec3& p) { return p.z; }}});
        const SceneObject o = volumeSurface(v, VolumeRepresentation{}, "box");
        const MeshMeasures m = measure(o);
        EXPECT_NEAR(m.area, 24.0, 1e-9);
        EXPECT_NEAR(m.signedVolume, 8.0, 1e-9) << "closed and facing outwards";
        EXPECT_EQ(m.openEdges, 0u);
        // Only boundary points are kept; the pyramids' centres are inside.
        for (std::size_t i = 0; i < o.vertexCount(); ++i) {
            const Vec3 p = vertex(o, i);
            EXPECT_TRUE(p.x == 0 || p.x == 2 || p.y == 0 || p.y == 2 || p.z == 0 || p.z == 2);
            EXPECT_EQ(fieldOf(o, "z").values[i], float(p.z));
        }
        EXPECT_EQ(fieldOf(o, "cell").association, ScalarField::Association::Cell);
    }
}

TEST(VolumeBoundary, ImageDataIsTheBoxWithItsVoxelsCellData) {
    VolumeMesh v;
    v.source = "image";
    v.dims = {3, 4, 5};
    v.origin = {1, 2, 3};
    v.spacing = {0.5, 1, 2};
    v.cellData = {{"c", 1, std::vector<float>(v.cellCount())}};
    for (std::size_t c = 0; c < v.cellCount(); ++c) v.cellData[0].values[c] = float(c);
    const SceneObject o = volumeSurface(v, VolumeRepresentation{}, "box");
    const MeshMeasures m = measure(o);
    const double sx = 1, sy = 3, sz = 8;  // extents
    EXPECT_NEAR(m.area, 2 * (sx * sy + sy * sz + sx * sz), 1e-9);
    EXPECT_NEAR(m.signedVolume, sx * sy * sz, 1e-9);
    EXPECT_EQ(m.openEdges, 0u);
}

TEST(VolumeSlice, PlanesCutFlatFacingTheirNormalWithFieldsInterpolated) {
    const VolumeMesh v = cubes(2, "tet", {{"s", [](const Vec3& p) { return p.x + 10 * p.z; }}});
    VolumeRepresentation r;
    r.kind = VolumeRepresentation::Kind::Slice;
    r.planes = {{{0, 0, 0.5}, {0, 0, 2}}, {{1, 1.1, 1}, {1, 1, 0}}};
    const SceneObject o = volumeSurface(v, r, "cut");
    const MeshMeasures m = measure(o);
    EXPECT_NEAR(m.area, 4.0 + 1.9 * std::sqrt(2.0) * 2, 1e-6);  // float32 positions
    const ScalarField& s = fieldOf(o, "s");
    for (std::size_t i = 0; i < o.vertexCount(); ++i) {
        const Vec3 p = vertex(o, i);
        EXPECT_TRUE(std::abs(p.z - 0.5) < 1e-6 || std::abs(p.x + p.y - 2.1) < 1e-6);
        EXPECT_NEAR(s.values[i], p.x + 10 * p.z, 1e-5);
    }
    for (std::size_t t = 0; t < o.indices.size(); t += 3) {
        const Vec3 a = vertex(o, o.indices[t]);
        const Vec3 n = cross(vertex(o, o.indices[t + 1]) - a, vertex(o, o.indices[t + 2]) - a);
        const Vec3 normal = std::abs(a.z - 0.5) < 1e-6 ? Vec3{0, 0, 1} : Vec3{1, 1, 0};
        EXPECT_GT(dot(n, normal), 0) << "triangle " << t / 3;
    }
}

TEST(VolumeErrors, MissingFieldsAndEmptyResultsAreNamed) {
    const VolumeMesh v = cubes(1, "hex", {{"x", [](const Vec3& p) { return p.x; }}});
    try {
        volumeSurface(v, iso("pressure", {1}), "o");
        ADD_FAILURE();
    } catch (const Error& e) {
        EXPECT_THAT(e.what(), HasSubstr("test hex: no point field 'pressure' to contour (point fields: x; cell fields cannot"));
    }
    try {
        volumeSurface(v, iso("x", {5}), "o");
        ADD_FAILURE();
    } catch (const Error& e) {
        EXPECT_THAT(e.what(), HasSubstr("the isosurface is empty: no isovalue lies within 'x', which ranges from 0"));
    }
}

TEST(VolumeReaders, VtuAndVtiAsWrittenByVtk) {
    test::TempDir dir;
    // Two tetrahedra sharing a face, a triangle and a line, ascii, VTK 9 layout.
    test::writeText(dir.file("t.vtu"), R"(<?xml version="1.0"?>
<VTKFile type="UnstructuredGrid" version="1.0" byte_order="LittleEndian" header_type="UInt64">
  <UnstructuredGrid>
    <Piece NumberOfPoints="5" NumberOfCells="4">
      <PointData>
        <DataArray type="Float32" Name="f" format="ascii">0 1 2 3 4</DataArray>
      </PointData>
      <CellData>
        <DataArray type="Int32" Name="id" format="ascii">10 11 12 13</DataArray>
      </CellData>
      <Points>
        <DataArray type="Float32" NumberOfComponents="3" format="ascii">0 0 0 1 0 0 0 1 0 0 0 1 1 1 1</DataArray>
      </Points>
      <Cells>
        <DataArray type="Int64" Name="connectivity" format="ascii">0 1 2 3 1 2 3 4 0 1 2 0 4</DataArray>
        <DataArray type="Int64" Name="offsets" format="ascii">4 8 11 13</DataArray>
        <DataArray type="UInt8" Name="types" format="ascii">10 10 5 3</DataArray>
      </Cells>
    </Piece>
  </UnstructuredGrid>
</VTKFile>
)");
    const VolumeMesh u = readVolume(dir.file("t.vtu"));
    EXPECT_EQ(u.pointCount(), 5u);
    EXPECT_EQ(u.cellCount(), 4u);
    EXPECT_EQ(u.volumeCellCount(), 2u);
    EXPECT_TRUE(isVolumeFile(dir.file("t.vtu")));
    // Boundary: 6 outer faces of the two tetrahedra (the shared one drops) plus the triangle cell.
    const SceneObject b = volumeSurface(u, VolumeRepresentation{}, "b");
    EXPECT_EQ(b.indices.size(), 7u * 3);

    test::writeText(dir.file("i.vti"), R"(<?xml version="1.0"?>
<VTKFile type="ImageData" version="1.0" byte_order="LittleEndian" header_type="UInt64">
  <ImageData WholeExtent="1 2 0 1 0 1" Origin="10 0 0" Spacing="2 1 1" Direction="1 0 0 0 1 0 0 0 1">
    <Piece Extent="1 2 0 1 0 1">
      <PointData>
        <DataArray type="Float64" Name="d" format="ascii">0 1 0 1 0 1 0 1</DataArray>
      </PointData>
    </Piece>
  </ImageData>
</VTKFile>
)");
    const VolumeMesh im = readVolume(dir.file("i.vti"));
    EXPECT_EQ(im.dims, (std::array<int, 3>{2, 2, 2}));
    EXPECT_DOUBLE_EQ(im.point(0).x, 12.0);  // origin + spacing * extent start
    EXPECT_DOUBLE_EQ(im.point(1).x, 14.0);
    const SceneObject s = volumeSurface(im, iso("d", {0.25}), "s");
    for (std::size_t i = 0; i < s.vertexCount(); ++i) EXPECT_NEAR(vertex(s, i).x, 12.5, 1e-9);
    EXPECT_NEAR(measure(s).area, 1.0, 1e-9);

    test::writeText(dir.file("flat.vti"), R"(<?xml version="1.0"?>
<VTKFile type="ImageData" version="1.0"><ImageData WholeExtent="0 3 0 3 0 0"><Piece Extent="0 3 0 3 0 0"/></ImageData></VTKFile>
)");
    try {
        readVolume(dir.file("flat.vti"));
        ADD_FAILURE();
    } catch (const Error& e) {
        EXPECT_THAT(e.what(), HasSubstr("flat.vti:2: WholeExtent 4 x 4 x 1 points is not a volume"));
    }
}

// A real file written by TTK's tools (../shared/data/meshes/fertility.vtu):
// triangles only, so its boundary is its surface, as readMesh reads it.
TEST(VolumeReaders, FertilityHasNo3DCellsAndItsBoundaryIsItsSurface) {
    const std::string path = test::sharedData("meshes/fertility.vtu");
    if (path.empty()) GTEST_SKIP() << "../shared/data/meshes is absent";
    const VolumeMesh v = readVolume(path);
    EXPECT_EQ(v.pointCount(), 5166u);
    EXPECT_EQ(v.volumeCellCount(), 0u);
    EXPECT_FALSE(isVolumeFile(path));
    const SceneObject b = volumeSurface(v, VolumeRepresentation{}, "fertility");
    EXPECT_EQ(b.primitiveCount(), 10344u);
    EXPECT_EQ(b.primitiveCount(), readMesh(path).front().primitiveCount());
}

TEST(VolumeReaders, HugeImageExtentIsRefusedBeforeAllocating) {
    test::TempDir dir;
    test::writeText(dir.file("big.vti"), R"(<?xml version="1.0"?>
<VTKFile type="ImageData" version="1.0"><ImageData WholeExtent="0 65535 0 65535 0 65535"><Piece/></ImageData></VTKFile>
)");
    try {
        readVolume(dir.file("big.vti"));
        ADD_FAILURE();
    } catch (const Error& e) {
        EXPECT_THAT(e.what(), HasSubstr("big.vti:2: WholeExtent holds 281474976710656 points"));
    }
}
