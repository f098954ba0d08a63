// Isosurface normals from the field's gradient, with known answers: a
// linear field's plane gets its exact normal in every cell type (least
// squares on unstructured cells, central differences on image data, also
// through a rotated, anisotropic grid); a sphere's vertices get the radial
// direction far more closely than its facets do; normals point from high to
// low values, as the triangles do.
#include "test_support.h"
#include "volume_test_meshes.h"

#include <darkroom/scene/vertex_normals.h>
#include <darkroom/scene/volume.h>

#include <gtest/gtest.h>

#include <cmath>

using namespace darkroom;
using darkroom::test::cubes;

namespace {

constexpr double kPi = 3.14159265358979323846;

VolumeRepresentation gradientIso(const std::string& field, double value) {
    VolumeRepresentation r;
    r.kind = VolumeRepresentation::Kind::Isosurface;
    r.contourBy = field;
    r.isovalues = {value};
    r.gradientNormals = true;
    return r;
}

Vec3 position(const SceneObject& o, std::size_t v) {
    return {o.vertices[4 * v], o.vertices[4 * v + 1], o.vertices[4 * v + 2]};
}

Vec3 normal(const SceneObject& o, std::size_t v) {
    return {o.field("N.x")->values[v], o.field("N.y")->values[v], o.field("N.z")->values[v]};
}

double degrees(const Vec3& a, const Vec3& b) { return std::atan2(length(cross(a, b)), dot(a, b)) * 180 / kPi; }

}  // namespace

TEST(VolumeNormals, LinearFieldGivesThePlanesExactNormalInEveryCellType) {
    const Vec3 g{0.3, -0.5, 0.8};  // the field's gradient; normals point down it
    for (const std::string kind : {"tet", "hex", "voxel", "wedge", "pyramid"}) {
        SCOPED_TRACE(kind);
        const VolumeMesh v = cubes(3, kind, {{"f", [&](const Vec3& p) { return dot(p, g); }}});
        const SceneObject o = volumeSurface(v, gradientIso("f", 1.3), "plane");
        ASSERT_GT(o.vertexCount(), 0u);
        for (std::size_t i = 0; i < o.vertexCount(); ++i) EXPECT_LT(degrees(normal(o, i), normalize(g) * -1.0), 1e-4);
        // The triangles agree: (v1 - v0) x (v2 - v0) points the same way.
        for (std::size_t t = 0; t < o.indices.size() / 3; ++t) {
            const Vec3 a = position(o, o.indices[3 * t]);
            const Vec3 n = cross(position(o, o.indices[3 * t + 1]) - a, position(o, o.indices[3 * t + 2]) - a);
            EXPECT_GT(dot(n, normal(o, o.indices[3 * t])), 0.0);
        }
    }
}

TEST(VolumeNormals, ImageDataThroughARotatedAnisotropicGridGivesTheWorldGradient) {
    VolumeMesh v;
    v.source = "image";
    v.dims = {6, 7, 8};
    v.origin = {1, -2, 0.5};
    v.spacing = {0.5, 0.25, 2};
    const double c = std::cos(0.4), s = std::sin(0.4);
    v.direction = {c, -s, 0, s, c, 0, 0, 0, 1};  // rotated about z
    const Vec3 g{1, 2, -0.5};
    VolumeArray f{"f", 1, {}};
    for (std::size_t i = 0; i < v.pointCount(); ++i) f.values.push_back(float(dot(v.point(i), g)));
    v.pointData.push_back(f);
    const double mid = dot(v.point(v.pointCount() / 2), g);
    const SceneObject o = volumeSurface(v, gradientIso("f", mid), "plane");
    ASSERT_GT(o.vertexCount(), 0u);
    for (std::size_t i = 0; i < o.vertexCount(); ++i) EXPECT_LT(degrees(normal(o, i), normalize(g) * -1.0), 1e-3);
}

TEST(VolumeNormals, SphereVerticesGetTheRadialDirection) {
    // f = |x - c| on a coarse grid: the facets are tilted by several degrees,
    // the gradient at the vertices by a fraction of one.
    VolumeMesh v;
    v.source = "image";
    const int n = 17;
    v.dims = {n, n, n};
    v.origin = {-1, -1, -1};
    v.spacing = {2.0 / (n - 1), 2.0 / (n - 1), 2.0 / (n - 1)};
    const Vec3 centre{0.05, -0.03, 0.02};
    VolumeArray r{"r", 1, {}};
    for (std::size_t i = 0; i < v.pointCount(); ++i) r.values.push_back(float(length(v.point(i) - centre)));
    v.pointData.push_back(r);
    const SceneObject o = volumeSurface(v, gradientIso("r", 0.7), "sphere");
    double worstVertex = 0, meanFace = 0;
    for (std::size_t i = 0; i < o.vertexCount(); ++i) {
        const Vec3 inwards = normalize(centre - position(o, i));  // high (outside) to low
        worstVertex = std::max(worstVertex, degrees(normal(o, i), inwards));
    }
    const std::size_t triangles = o.indices.size() / 3;
    for (std::size_t t = 0; t < triangles; ++t) {
        const Vec3 a = position(o, o.indices[3 * t]), b = position(o, o.indices[3 * t + 1]),
                   d = position(o, o.indices[3 * t + 2]);
        const Vec3 centroid = (a + b + d) * (1.0 / 3.0);
        meanFace += degrees(cross(b - a, d - a), normalize(centre - centroid)) / double(triangles);
    }
    EXPECT_LT(worstVertex, 2.0);
    EXPECT_GT(meanFace, 3.0 * worstVertex) << "the gradient is far closer than the facets";
}

TEST(VolumeNormals, OnlyWhenAskedAndNeverAsOrdinaryFields) {
    const VolumeMesh v = cubes(2, "hex", {{"f", [](const Vec3& p) { return p.x; }}});
    VolumeRepresentation r = gradientIso("f", 0.5);
    r.gradientNormals = false;
    const SceneObject plain = volumeSurface(v, r, "plane");
    EXPECT_EQ(plain.field("N.x"), nullptr);
    SceneObject with = volumeSurface(v, gradientIso("f", 0.5), "plane");
    EXPECT_EQ(with.fields.size(), plain.fields.size() + 3);
    EXPECT_EQ(takeVertexNormals(with).size(), 3 * with.vertexCount());
    EXPECT_EQ(with.fields.size(), plain.fields.size());
}
