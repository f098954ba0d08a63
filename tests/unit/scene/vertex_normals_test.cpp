// Vertex normals with known answers: a cube keeps flat faces at a 30 degree
// feature angle (each corner split into one vertex per face, normals exactly
// along the axes) and gets its corners' diagonals without splitting; a
// tessellated sphere gets the radial direction; zero-area triangles, point
// fields of split vertices, a file's own normals and scaling.
#include "test_meshes.h"

#include <darkroom/scene/vertex_normals.h>

#include <gtest/gtest.h>

#include <cmath>
#include <set>

using namespace darkroom;

namespace {

constexpr double kPi = 3.14159265358979323846;

Vec3 position(const SceneObject& o, std::size_t v) {
    return {o.vertices[4 * v], o.vertices[4 * v + 1], o.vertices[4 * v + 2]};
}

Vec3 normal(const SceneObject& o, std::size_t v) {
    return {o.field("N.x")->values[v], o.field("N.y")->values[v], o.field("N.z")->values[v]};
}

Vec3 faceNormal(const SceneObject& o, std::size_t t) {
    const Vec3 a = position(o, o.indices[3 * t]);
    return normalize(cross(position(o, o.indices[3 * t + 1]) - a, position(o, o.indices[3 * t + 2]) - a));
}

double degrees(const Vec3& a, const Vec3& b) {
    return std::atan2(length(cross(a, b)), dot(a, b)) * 180 / kPi;
}

}  // namespace

TEST(VertexNormals, CubeKeepsFlatFacesAtThirtyDegrees) {
    SceneObject o = test::unitCube();
    averageVertexNormals(o, 30);
    // Each corner meets three faces at 90 degrees: three vertices a corner.
    EXPECT_EQ(o.vertexCount(), 24u);
    ASSERT_EQ(o.indices.size(), 36u);
    for (std::size_t t = 0; t < 12; ++t)
        for (int k = 0; k < 3; ++k) {
            const std::uint32_t v = o.indices[3 * t + std::size_t(k)];
            EXPECT_EQ(normal(o, v), faceNormal(o, t)) << "triangle " << t << " corner " << k;
        }
    for (std::size_t v = 0; v < o.vertexCount(); ++v) {
        const Vec3 n = normal(o, v);
        EXPECT_EQ(std::abs(n.x) + std::abs(n.y) + std::abs(n.z), 1.0) << "exactly one axis, exactly unit";
    }
}

TEST(VertexNormals, CubeWithoutSplittingPointsAlongTheDiagonalsWhateverTheTriangulation) {
    SceneObject o = test::unitCube();
    averageVertexNormals(o, 180);
    ASSERT_EQ(o.vertexCount(), 8u);
    // Some corners have one triangle of a face, others two: angle weights
    // give each face the same share (90 degrees) all the same.
    for (std::size_t v = 0; v < 8; ++v) {
        const Vec3 p = position(o, v);
        const Vec3 diagonal = normalize(p * 2.0 - Vec3{1, 1, 1});
        EXPECT_LT(degrees(normal(o, v), diagonal), 1e-5) << "corner " << v;
    }
}

TEST(VertexNormals, TessellatedSphereGetsTheRadialDirection) {
    SceneObject o = test::uvSphere(24, 48, 2.0);
    const std::size_t before = o.vertexCount();
    averageVertexNormals(o, 30);
    EXPECT_EQ(o.vertexCount(), before) << "a smooth sphere has no feature edges";
    double worstVertex = 0, worstFace = 0;
    for (std::size_t v = 0; v < o.vertexCount(); ++v) worstVertex = std::max(worstVertex, degrees(normal(o, v), normalize(position(o, v))));
    for (std::size_t t = 0; t < o.indices.size() / 3; ++t)
        worstFace = std::max(worstFace, degrees(faceNormal(o, t), normalize(position(o, o.indices[3 * t]))));
    EXPECT_LT(worstVertex, 0.5);  // 0.15 measured: a UV sphere's fans are not symmetric
    EXPECT_GT(worstFace, 3.0) << "the facets themselves are visibly tilted";
}

TEST(VertexNormals, SplitCopiesCarryTheirPointFieldsAndCellsStay) {
    SceneObject o = test::unitCube();
    ScalarField height{"height", ScalarField::Association::Point, {}};
    for (std::size_t v = 0; v < 8; ++v) height.values.push_back(float(position(o, v).z));
    o.fields.push_back(height);
    o.fields.push_back({"face", ScalarField::Association::Cell, std::vector<float>(12, 1.0f)});
    averageVertexNormals(o, 30);
    for (std::size_t v = 0; v < o.vertexCount(); ++v) EXPECT_EQ(o.field("height")->values[v], float(position(o, v).z));
    EXPECT_EQ(o.field("face")->values.size(), 12u);
}

TEST(VertexNormals, ZeroAreaTrianglesAndUnusedVerticesTakeNoPart) {
    // A flat square of two triangles plus a sliver with a repeated vertex,
    // and a vertex nothing uses.
    SceneObject o = test::triangleMesh({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {5, 5, 5}}, {0, 1, 2, 0, 2, 3, 0, 0, 2});
    averageVertexNormals(o, 30);
    EXPECT_EQ(o.vertexCount(), 5u);
    for (std::size_t v = 0; v < 4; ++v) EXPECT_EQ(normal(o, v), (Vec3{0, 0, 1}));
    EXPECT_EQ(normal(o, 4), (Vec3{0, 0, 0})) << "no triangle: no normal";
}

TEST(VertexNormals, InconsistentWindingIsAFeatureEdge) {
    // Two coplanar triangles wound against each other: their normals are
    // 180 degrees apart, so the shared vertices split instead of cancelling.
    SceneObject o = test::triangleMesh({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}}, {0, 1, 2, 0, 3, 2});
    averageVertexNormals(o, 30);
    EXPECT_EQ(o.vertexCount(), 6u);
    for (std::size_t t = 0; t < 2; ++t)
        for (int k = 0; k < 3; ++k) EXPECT_EQ(normal(o, o.indices[3 * t + std::size_t(k)]), faceNormal(o, t));
}

TEST(VertexNormals, AFilesOwnNormalsAreFoundByTheReadersNames) {
    SceneObject o = test::triangleMesh({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {0, 1, 2});
    EXPECT_TRUE(fileVertexNormals(o).empty());
    for (const char* n : {"nx", "ny", "nz"}) o.fields.push_back({n, ScalarField::Association::Point, {0, 0, 0}});
    o.fields[2].values = {2, 2, 2};  // nz, not unit: normalised
    EXPECT_EQ(fileVertexNormals(o), (VertexNormals{0, 0, 1, 0, 0, 1, 0, 0, 1}));
    SceneObject vtk = test::triangleMesh({{0, 0, 0}}, {});
    for (const char* n : {"Normals_0", "Normals_1", "Normals_2"}) vtk.fields.push_back({n, ScalarField::Association::Point, {0}});
    vtk.fields[0].values = {-3};
    EXPECT_EQ(fileVertexNormals(vtk), (VertexNormals{-1, 0, 0}));
}

TEST(VertexNormals, TakeAndSetMoveThemInAndOutOfTheFields) {
    SceneObject o = test::triangleMesh({{0, 0, 0}, {1, 0, 0}}, {});
    o.fields.push_back({"t", ScalarField::Association::Point, {1, 2}});
    setVertexNormals(o, {1, 0, 0, 0, 1, 0});
    EXPECT_EQ(o.fields.size(), 4u);
    EXPECT_EQ(takeVertexNormals(o), (VertexNormals{1, 0, 0, 0, 1, 0}));
    ASSERT_EQ(o.fields.size(), 1u);
    EXPECT_EQ(o.fields[0].name, "t");
    EXPECT_TRUE(takeVertexNormals(o).empty());
}

TEST(VertexNormals, ScalingTransformsThemAsGradients) {
    // The plane x + y = c scaled by (2, 1, 1) becomes x/2 + y = c: normal (1/2, 1, 0).
    const double s = std::sqrt(0.5);
    VertexNormals n{float(s), float(s), 0};
    scaleVertexNormals(n, {2, 1, 1});
    const Vec3 expected = normalize(Vec3{0.5, 1, 0});
    EXPECT_NEAR(n[0], expected.x, 1e-7);
    EXPECT_NEAR(n[1], expected.y, 1e-7);
    EXPECT_EQ(n[2], 0.0f);
    VertexNormals mirrored{0, 0, 1};
    scaleVertexNormals(mirrored, {1, 1, -1});
    EXPECT_EQ(mirrored, (VertexNormals{0, 0, -1}));
}
