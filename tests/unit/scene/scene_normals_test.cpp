// The scene file's `channels: normals` and `featureAngle`: which surfaces
// get vertex normals and where they come from (an isosurface's gradient, a
// file's own normals, averaging), that they never become scalar channels
// nor fall to an object's `fields:` list, that nothing is computed when
// normals are off or geometric, and the errors.
#include "mesh_test_files.h"
#include "test_support.h"

#include <darkroom/scene/generators.h>
#include <darkroom/scene/scene_file.h>
#include <darkroom/scene/vertex_normals.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

using namespace darkroom;
using darkroom::test::expectError;

namespace {

// The unit cube as an OBJ, a triangle fan per face (outwards), and a
// polyline; a PLY triangle carrying normals of its own.
void writeFiles(const test::TempDir& dir) {
    test::writeText(dir.file("cube.obj"),
                    "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nv 0 0 1\nv 1 0 1\nv 0 1 1\nv 1 1 1\n"
                    "f 1 3 4 2\nf 5 6 8 7\nf 1 2 6 5\nf 3 7 8 4\nf 1 5 7 3\nf 2 4 8 6\nl 1 8\n");
    test::writeText(dir.file("tri.ply"),
                    "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                    "property float z\nproperty float nx\nproperty float ny\nproperty float nz\n"
                    "element face 1\nproperty list uchar int vertex_indices\nend_header\n"
                    "0 0 0 0 0.6 0.8\n1 0 0 0 0.6 0.8\n0 1 0 0 0.6 0.8\n3 0 1 2\n");
}

SceneDescription parse(const test::TempDir& dir, const std::string& yaml, const SceneLoadOptions& options = {}) {
    writeFiles(dir);
    return parseSceneFile(yaml, dir.file("scene.yaml"), dir.path(), options);
}

bool hasNormals(const SceneObject& o) { return o.field("N.x") && o.field("N.y") && o.field("N.z"); }

Vec3 normal(const SceneObject& o, std::size_t v) {
    return {o.field("N.x")->values[v], o.field("N.y")->values[v], o.field("N.z")->values[v]};
}

}  // namespace

TEST(SceneNormals, SmoothIsTheDefaultStyleOfNormalsTrue) {
    test::TempDir dir;
    const auto d = parse(dir, "objects: [{file: cube.obj}]\nchannels: {normals: true}\n");
    EXPECT_TRUE(d.request.normals);
    EXPECT_EQ(d.normals.style, NormalsOptions::Style::Smooth);
    EXPECT_EQ(d.normals.featureAngle, 30);
    ASSERT_EQ(d.scene->objects.size(), 2u);
    const SceneObject& cube = d.scene->objects[0];
    ASSERT_TRUE(hasNormals(cube));
    EXPECT_EQ(cube.vertexCount(), 24u) << "the feature angle splits every corner three ways";
    for (std::size_t v = 0; v < cube.vertexCount(); ++v) {
        const Vec3 n = normal(cube, v);
        EXPECT_EQ(std::abs(n.x) + std::abs(n.y) + std::abs(n.z), 1.0);
    }
    EXPECT_FALSE(hasNormals(d.scene->objects[1])) << "tubes have exact normals of their own";
}

TEST(SceneNormals, FeatureAngleAndGeometricAndOff) {
    test::TempDir dir;
    const auto wide = parse(dir, "objects: [{file: cube.obj}]\nchannels: {normals: smooth, featureAngle: 120}\n");
    EXPECT_EQ(wide.normals.featureAngle, 120);
    EXPECT_EQ(wide.scene->objects[0].vertexCount(), 8u) << "90 degree edges are below 120: no split";
    for (const char* off : {"normals: geometric", "normals: false", "featureAngle: 10"}) {
        SCOPED_TRACE(off);
        const auto d = parse(dir, std::string("objects: [{file: cube.obj}]\nchannels: {") + off + "}\n");
        EXPECT_FALSE(hasNormals(d.scene->objects[0])) << "nothing computed that is not stored smooth";
        EXPECT_EQ(d.scene->objects[0].vertexCount(), 8u);
    }
    const auto geometric = parse(dir, "objects: [{file: cube.obj}]\nchannels: {normals: geometric}\n");
    EXPECT_TRUE(geometric.request.normals);
    EXPECT_EQ(geometric.normals.style, NormalsOptions::Style::Geometric);
}

TEST(SceneNormals, ALoaderMayAskForThemWhenTheFileLeavesThemOff) {
    test::TempDir dir;
    SceneLoadOptions options;
    options.normals = true;
    const auto d = parse(dir, "objects: [{file: cube.obj}]\nchannels: {featureAngle: 100}\n", options);
    EXPECT_FALSE(d.request.normals) << "the request stays the file's";
    EXPECT_TRUE(hasNormals(d.scene->objects[0]));
    EXPECT_EQ(d.scene->objects[0].vertexCount(), 8u);
    const auto geometric = parse(dir, "objects: [{file: cube.obj}]\nchannels: {normals: geometric}\n", options);
    EXPECT_FALSE(hasNormals(geometric.scene->objects[0]));
}

TEST(SceneNormals, IsosurfacesKeepTheirGradientWhateverTheirFieldsAndScale) {
    test::TempDir dir;
    const auto d = parse(dir,
                         "objects:\n"
                         "  - {generator: isosurface, parameters: {resolution: 12}, fields: [height], scale: [2, 1, 1]}\n"
                         "channels: {normals: true}\n");
    const SceneObject& iso = d.scene->objects[0];
    ASSERT_TRUE(hasNormals(iso));
    EXPECT_EQ(d.request.scalars, (std::vector<std::string>{"height"})) << "normals are not scalar channels";
    // The demo field's gradient at the vertex, reversed (f falls outwards)
    // and transformed as a gradient: p = S q, so n is S^-1 times -grad f(q).
    double worst = 0;
    for (std::size_t v = 0; v < iso.vertexCount(); ++v) {
        const Vec3 q{iso.vertices[4 * v] / 2.0, iso.vertices[4 * v + 1], iso.vertices[4 * v + 2]};
        const Vec3 g = generators::demoFieldGradient(q);
        const Vec3 expected = normalize(Vec3{-g.x / 2.0, -g.y, -g.z});
        worst = std::max(worst, length(cross(expected, normal(iso, v))));
    }
    EXPECT_LT(worst, 1e-5);
}

TEST(SceneNormals, AFilesOwnNormalsAreUsed) {
    test::TempDir dir;
    const auto d = parse(dir, "objects: [{file: tri.ply, fields: []}]\nchannels: {normals: true}\n");
    const SceneObject& tri = d.scene->objects[0];
    ASSERT_TRUE(hasNormals(tri));
    for (std::size_t v = 0; v < 3; ++v) EXPECT_EQ(normal(tri, v), (Vec3{0, 0.6f, 0.8f}));
    EXPECT_TRUE(d.request.scalars.empty());
}

TEST(SceneNormals, VtkNormalsArraysAreUsed) {
    test::TempDir dir;
    test::writeText(dir.file("tri.vtk"),
                    "# vtk DataFile Version 3.0\ntri\nASCII\nDATASET POLYDATA\nPOINTS 3 float\n0 0 0 1 0 0 0 1 0\n"
                    "POLYGONS 1 4\n3 0 1 2\nPOINT_DATA 3\nNORMALS Normals float\n0 0 -1 0 0 -1 0 0 -1\n");
    const auto d = parse(dir, "objects: [{file: tri.vtk}]\nchannels: {normals: true}\n");
    const SceneObject& tri = d.scene->objects[0];
    ASSERT_TRUE(hasNormals(tri));
    for (std::size_t v = 0; v < 3; ++v) EXPECT_EQ(normal(tri, v), (Vec3{0, 0, -1})) << "the file's, not the winding's";
}

TEST(SceneNormals, Errors) {
    test::TempDir dir;
    const std::string f = dir.file("scene.yaml");
    expectError([&] { parse(dir, "objects: [{file: cube.obj}]\nchannels: {normals: shiny}\n"); },
                {f + ":2:21:", "normals must be smooth", "geometric"});
    expectError([&] { parse(dir, "objects: [{file: cube.obj}]\nchannels: {normals: geometric, featureAngle: 20}\n"); },
                {f + ":2:46:", "'featureAngle' only applies to smooth normals"});
    expectError([&] { parse(dir, "objects: [{file: cube.obj}]\nchannels: {featureAngle: 200}\n"); },
                {f + ":2:26:", "featureAngle must lie in [0, 180]"});
    expectError([&] { parse(dir, "objects: [{file: cube.obj}]\nchannels: {featureAngel: 20}\n"); },
                {f + ":2:12:", "unknown key 'featureAngel'", "did you mean 'featureAngle'"});
}
