#include "mesh_test_files.h"
#include "test_support.h"

#include <darkroom/scene/scene_file.h>

#include <cmath>

using namespace darkroom;
using darkroom::test::expectError;

namespace {

// A unit square (two triangles) with a point field "h" and a cell field "c",
// plus a polyline: an ASCII legacy VTK file with a surface and a lines part.
void writeSquare(const std::string& path) {
    test::writeText(path,
                    "# vtk DataFile Version 3.0\nsq\nASCII\nDATASET POLYDATA\nPOINTS 4 float\n"
                    "-1 -1 0 1 -1 0 1 1 0 -1 1 0\n"
                    "LINES 1 3\n2 0 2\n"
                    "POLYGONS 1 5\n4 0 1 2 3\n"
                    "POINT_DATA 4\nSCALARS h float\nLOOKUP_TABLE default\n0 1 2 3\n"
                    "CELL_DATA 2\nSCALARS c float\nLOOKUP_TABLE default\n7 8\n");
}

SceneDescription parseIn(const test::TempDir& dir, const std::string& yaml) {
    writeSquare(dir.file("square.vtk"));
    return parseSceneFile(yaml, dir.file("scene.yaml"), dir.path());
}

}  // namespace

TEST(SceneFile, GridCountsGiveCinemaAngles) {
    test::TempDir dir;
    const auto d = parseIn(dir,
                           "objects:\n"
                           "  - file: square.vtk\n"
                           "cameras:\n"
                           "  resolution: [64, 32]\n"
                           "  grid: {phi: 4, theta: 3}\n");
    ASSERT_EQ(d.cameras.size(), 12u);
    std::vector<double> phis, thetas;
    for (const auto& c : d.cameras) {
        ASSERT_EQ(c.parameters.size(), 2u);
        EXPECT_EQ(c.parameters[0].first, "phi");
        EXPECT_EQ(c.parameters[1].first, "theta");
        phis.push_back(c.parameters[0].second);
        thetas.push_back(c.parameters[1].second);
        EXPECT_EQ(c.camera.width, 64);
        EXPECT_EQ(c.camera.height, 32);
    }
    EXPECT_EQ(phis[0], -180);
    EXPECT_EQ(phis[3], -90);
    EXPECT_EQ(phis[6], 0);
    EXPECT_EQ(phis[9], 90);
    EXPECT_EQ((std::vector<double>{thetas[0], thetas[1], thetas[2]}), (std::vector<double>{-90, 0, 90}));
    // phi = 0, theta = 0 looks along -Z from +Z (ParaView's default view, up +Y);
    // phi = 90 moves the camera to +X; theta = 90 to the top (+Y).
    const Vec3 c = d.scene->bounds().center();
    const Camera& front = d.cameras[7].camera;
    EXPECT_NEAR(front.forward.z, -1, 1e-12);
    EXPECT_NEAR(front.up.y, 1, 1e-12);
    EXPECT_GT(d.cameras[10].camera.position.x - c.x, 0);
    EXPECT_NEAR(d.cameras[10].camera.forward.x, -1, 1e-12);
    const Camera& top = d.cameras[8].camera;
    EXPECT_NEAR(top.forward.y, -1, 1e-12);
    EXPECT_NEAR(length(cross(top.forward, top.up)), 1, 1e-12);  // the pole is still a valid frame
}

TEST(SceneFile, ExplicitAnglesUpDistanceAndOrthographic) {
    test::TempDir dir;
    const auto d = parseIn(dir,
                           "objects: [{file: square.vtk}]\n"
                           "cameras:\n"
                           "  projection: orthographic\n"
                           "  height: 3\n"
                           "  grid:\n"
                           "    phi: [0, 45]\n"
                           "    theta: [30]\n"
                           "    distance: 10\n"
                           "    up: [0, 0, 1]\n"
                           "    target: [0, 0, 0]\n");
    ASSERT_EQ(d.cameras.size(), 2u);
    EXPECT_EQ(d.cameras[1].parameters[0].second, 45);
    EXPECT_EQ(d.cameras[1].parameters[1].second, 30);
    for (const auto& s : d.cameras) {
        EXPECT_EQ(s.camera.projection, Camera::Projection::Orthographic);
        EXPECT_EQ(s.camera.viewHeight, 3);
        EXPECT_NEAR(length(s.camera.position), 10, 1e-9);
        // Elevation 30 degrees above the plane normal to up (+Z).
        EXPECT_NEAR(s.camera.position.z, 10 * std::sin(30 * M_PI / 180), 1e-9);
    }
    // Up +Z: phi = 0 places the camera on -Y (front view).
    EXPECT_LT(d.cameras[0].camera.position.y, -1);
    EXPECT_NEAR(d.cameras[0].camera.position.x, 0, 1e-9);
}

TEST(SceneFile, DefaultDistanceFitsTheBoundingSphere) {
    test::TempDir dir;
    const auto d = parseIn(dir,
                           "objects: [{file: square.vtk, translate: [5, 0, 0], scale: 2}]\n"
                           "cameras: {fov: 40, resolution: [100, 50], grid: {phi: 8, theta: 3}}\n");
    const Bounds b = d.scene->bounds();
    EXPECT_NEAR(b.center().x, 5, 1e-6);
    const double r = b.radius();
    EXPECT_NEAR(r, std::sqrt(8.0), 0.05);  // 4 x 4 square (scaled by 2), plus the tube radius
    for (const auto& s : d.cameras) {
        const Camera& c = s.camera;
        const double dist = length(c.position - b.center());
        // The sphere lies in front of the camera and inside the vertical view
        // (height is the narrower side here): r / dist == sin(fov / 2).
        EXPECT_GT(dist, r);
        EXPECT_NEAR(r / dist, std::sin(20 * M_PI / 180), 1e-9);
        EXPECT_NEAR(dot(normalize(b.center() - c.position), normalize(c.forward)), 1, 1e-9);
    }
}

TEST(SceneFile, CameraListAndChannels) {
    test::TempDir dir;
    const auto d = parseIn(dir,
                           "objects:\n"
                           "  - {file: square.vtk, name: sq, fields: [c], radius: 0.25}\n"
                           "cameras:\n"
                           "  fov: 50\n"
                           "  list:\n"
                           "    - {position: [0, 0, 5], target: [0, 0, 0]}\n"
                           "    - {position: [5, 0, 0], forward: [-1, 0, 0], up: [0, 0, 1]}\n"
                           "channels: {normals: true, objectId: yes, primitiveId: false}\n"
                           "backend: embree\n");
    ASSERT_EQ(d.cameras.size(), 2u);
    EXPECT_EQ(d.cameras[1].parameters, (std::vector<std::pair<std::string, double>>{{"camera", 1}}));
    EXPECT_EQ(d.cameras[0].camera.fovYDegrees, 50);
    EXPECT_EQ(d.cameras[1].camera.up, Vec3(0, 0, 1));
    EXPECT_EQ(d.request.scalars, (std::vector<std::string>{"c"}));
    EXPECT_TRUE(d.request.normals);
    EXPECT_TRUE(d.request.objectId);
    EXPECT_FALSE(d.request.primitiveId);
    ASSERT_EQ(d.scene->objects.size(), 2u);
    EXPECT_EQ(d.scene->objects[0].name, "sq/surface");
    EXPECT_EQ(d.scene->objects[1].name, "sq/lines");
    for (const auto& o : d.scene->objects) {
        // "h" was not listed: dropped. The surface's smooth normals ride
        // along as N.x, N.y, N.z (vertex_normals.h), after the fields.
        const std::size_t normals = o.representation == Representation::Surface ? 3 : 0;
        ASSERT_EQ(o.fields.size(), 1u + normals);
        EXPECT_EQ(o.fields[0].name, "c");
    }
    EXPECT_EQ(d.scene->objects[1].vertices[3], 0.25f);
    EXPECT_EQ(d.backend, "embree");
}

// channels: {layers: K}, the K nearest surface crossings per pixel
// (darkroom/layers.h): 1 unless asked, 1 to 16, an error naming the line.
TEST(SceneFile, LayersChannel) {
    test::TempDir dir;
    const std::string f = dir.file("scene.yaml");
    EXPECT_EQ(parseIn(dir, "objects: [{file: square.vtk}]\n").request.layers, 1);
    EXPECT_EQ(parseIn(dir, "objects: [{file: square.vtk}]\nchannels: {layers: 4}\n").request.layers, 4);
    EXPECT_EQ(parseIn(dir, "objects: [{file: square.vtk}]\nchannels: {layers: 16}\n").request.layers, 16);
    for (const char* bad : {"0", "17", "two", "2.5"})
        expectError([&] { parseIn(dir, std::string("objects: [{file: square.vtk}]\nchannels:\n  layers: ") + bad + "\n"); },
                    {f + ":3:11:", "layers (surface crossings per pixel) must be an integer from 1 to 16"});
}

TEST(SceneFile, RepresentationsAndDefaultScalars) {
    test::TempDir dir;
    const auto d = parseIn(dir,
                           "objects:\n"
                           "  - {file: square.vtk, representation: points}\n"
                           "  - {file: square.vtk, representation: lines}\n");
    ASSERT_EQ(d.scene->objects.size(), 4u);
    const SceneObject& pts = d.scene->objects[0];
    EXPECT_EQ(pts.representation, Representation::Points);
    EXPECT_EQ(test::primitives(pts), 4u);
    EXPECT_EQ(pts.field("c"), nullptr);  // cell data cannot follow single vertices
    EXPECT_NE(pts.field("h"), nullptr);
    const SceneObject& wire = d.scene->objects[2];
    EXPECT_EQ(wire.representation, Representation::Lines);
    EXPECT_EQ(test::primitives(wire), 5u);  // 4 sides and the fan diagonal
    EXPECT_EQ(wire.primitiveCell.size(), 5u);
    EXPECT_EQ(wire.field("c")->values, (std::vector<float>{8}));
    // No radius given: 0.5% of the scene's bounding radius.
    EXPECT_NEAR(pts.vertices[3], 0.005 * std::sqrt(2.0), 1e-6);
    EXPECT_EQ(d.request.scalars, (std::vector<std::string>{"h", "c"}));
    EXPECT_EQ(d.cameras.size(), 8u);  // default grid: 8 azimuths at the equator
}

TEST(SceneFile, GeneratorObjects) {
    test::TempDir dir;
    const auto d = parseIn(dir,
                           "objects:\n"
                           "  - {generator: particles, parameters: {count: 50}}\n");
    ASSERT_EQ(d.scene->objects.size(), 1u);
    EXPECT_EQ(d.scene->objects[0].representation, Representation::Points);
    EXPECT_EQ(test::primitives(d.scene->objects[0]), 50u);
    expectError([&] { parseIn(dir, "objects:\n  - {generator: nosuch}\n"); },
                {dir.file("scene.yaml") + ":2:17:", "object 'nosuch'", "unknown generator"});
}

TEST(SceneFile, ErrorsNameLineAndColumn) {
    test::TempDir dir;
    const std::string f = dir.file("scene.yaml");
    expectError([&] { parseIn(dir, "objects:\n  - file: square.vtk\n    fields: [c, nope]\n"); },
                {f + ":3:17:", "no field 'nope'", "available: h, c"});
    expectError([&] { parseIn(dir, "objects: [\n"); }, {f + ":"});
    expectError([&] { parseIn(dir, "objects:\n  - file: square.vtk\n  bad: [1, 2\n"); }, {f + ":3:"});
    expectError([&] { parseIn(dir, "objects:\n  - {file: missing.obj}\n"); },
                {f + ":2:12:", "missing.obj", "cannot open"});
    expectError([&] { parseIn(dir, "objects:\n  - file: square.vtk\n    representaton: lines\n"); },
                {f + ":3:5:", "unknown key 'representaton'"});
    expectError([&] { parseIn(dir, "objects: [{file: square.vtk}]\ncameras:\n  grid: {phi: 0}\n"); },
                {f + ":3:15:", "phi"});
    expectError([&] { parseIn(dir, "objects: [{file: square.vtk}]\ncameras:\n  resolution: [10, big]\n"); },
                {f + ":3:20:", "height", "'big'"});
    expectError([&] { parseIn(dir, "objects: [{file: square.vtk}]\nchannels: {scalars: [q]}\n"); },
                {f + ":2:22:", "'q'"});
    expectError([&] { parseIn(dir, "cameras: {}\n"); }, {f + ":1:1:", "missing 'objects'"});
}

TEST(SceneFile, LoadResolvesFilesNextToTheSceneFile) {
    test::TempDir dir;
    writeSquare(dir.file("square.vtk"));
    test::writeText(dir.file("scene.yaml"), "objects: [{file: square.vtk, fields: []}]\ncameras: {grid: {phi: 2}}\n");
    const auto d = loadSceneFile(dir.file("scene.yaml"));
    EXPECT_EQ(d.path, dir.file("scene.yaml"));
    EXPECT_EQ(d.cameras.size(), 2u);
    EXPECT_TRUE(d.request.scalars.empty());
    expectError([&] { loadSceneFile(dir.file("none.yaml")); }, {dir.file("none.yaml"), "cannot read scene file"});
}
