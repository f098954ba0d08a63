// Smooth normals through the whole capture, with known answers: scene file
// in, the embree backend's G-buffer out.
// - A sphere isosurface of f = |x - c| on a coarse grid: at every hit the
//   smooth normal is within a degree or two of the sphere's (hit - c) / r,
//   while the facets' geometric normals are off by several.
// - A cube at feature angle 30: every normal exactly along an axis.
// - A tessellated sphere mesh: smooth, like the isosurface.
// - The styles differ only in N.*: depth, fields and ids are the same bits;
//   the geometric normals are each triangle's, and bit for bit what the
//   backend writes for a scene without vertex normals (the code before).
// - Smooth normals never face away from the camera; trace() agrees with render().
#include "test_meshes.h"
#include "test_support.h"

#include <darkroom/capture_backend.h>
#include <darkroom/error.h>
#include <darkroom/core/run_filter.h>
#include <darkroom/scene/scene_file.h>
#include <darkroom/scene/vertex_normals.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <sstream>

using namespace darkroom;

namespace {

constexpr double kPi = 3.14159265358979323846;

struct Capture {
    SceneDescription scene;
    BufferPtr image;
};

BufferPtr render(const std::shared_ptr<const Scene>& scene, const Camera& camera, const CaptureRequest& request) {
    auto backend = test::pluginRegistry().createBackend("embree");
    if (!backend) throw Error("the embree capture backend is not built");
    backend->setScene(scene);
    FilterRunOptions o;
    o.threads = 2;
    o.registry = &test::pluginRegistry();
    return backend->render(camera, request, *makeStandaloneContext(o, "smooth_normals"));
}

// `objects` and `channels` of a scene file in `dir`, one camera looking at
// `target` from `from`.
Capture capture(const test::TempDir& dir, const std::string& objects, const std::string& channels,
                const Vec3& from = {1.7, 2.3, 3.1}, const Vec3& target = {0, 0, 0}) {
    std::ostringstream yaml;
    yaml << "objects:\n" << objects << "cameras:\n  resolution: [160, 160]\n  fov: 40\n  list:\n"
         << "    - {position: [" << from.x << ", " << from.y << ", " << from.z << "], target: [" << target.x << ", "
         << target.y << ", " << target.z << "]}\n"
         << "channels: {" << channels << ", objectId: true, primitiveId: true}\n";
    Capture c{parseSceneFile(yaml.str(), dir.file("scene.yaml"), dir.path()), nullptr};
    c.image = render(c.scene.scene, c.scene.cameras.at(0).camera, c.scene.request);
    return c;
}

// f = |x - c| on a 17^3 grid over [-1, 1]^3: an ASCII ImageData file.
const Vec3 kCentre{0.05, -0.03, 0.02};
void writeDistanceVolume(const std::string& path) {
    const int n = 17;
    std::ostringstream s;
    s << "<?xml version=\"1.0\"?>\n<VTKFile type=\"ImageData\" version=\"1.0\">\n"
      << "<ImageData WholeExtent=\"0 16 0 16 0 16\" Origin=\"-1 -1 -1\" Spacing=\"0.125 0.125 0.125\">\n"
      << "<Piece Extent=\"0 16 0 16 0 16\"><PointData><DataArray type=\"Float32\" Name=\"r\" format=\"ascii\">\n";
    s.precision(9);
    for (int k = 0; k < n; ++k)
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i) s << length(Vec3{-1 + 0.125 * i, -1 + 0.125 * j, -1 + 0.125 * k} - kCentre) << ' ';
    s << "\n</DataArray></PointData></Piece></ImageData></VTKFile>\n";
    test::writeText(path, s.str());
}

Vec3 normalAt(const Buffer& b, std::size_t i) {
    return {b.hostFloat("N.x")[i], b.hostFloat("N.y")[i], b.hostFloat("N.z")[i]};
}

double degrees(const Vec3& a, const Vec3& b) { return std::atan2(length(cross(a, b)), dot(a, b)) * 180 / kPi; }

// Angles between the captured normals and a sphere's about `centre`, over
// the pixels that hit it where the sphere's normal faces the camera by more
// than 3 degrees: at the rim a facet can stand out past the sphere's
// silhouette, where the sphere's normal faces away and the capture's (by
// design) cannot.
struct AngleErrors {
    double mean = 0, max = 0;
    std::size_t hits = 0, rim = 0;
};
AngleErrors sphereErrors(const Capture& c, const Vec3& centre) {
    const Buffer& b = *c.image;
    const Camera& cam = c.scene.cameras.at(0).camera;
    AngleErrors e;
    for (int y = 0; y < b.height(); ++y)
        for (int x = 0; x < b.width(); ++x) {
            const std::size_t i = std::size_t(y) * std::size_t(b.width()) + std::size_t(x);
            const float z = b.hostFloat("Z")[i];
            if (!std::isfinite(z)) continue;
            const Vec3 hit = cam.worldPosition(x + 0.5, y + 0.5, z), sphere = normalize(hit - centre);
            if (dot(sphere, normalize(hit - cam.position)) > -std::sin(3 * kPi / 180)) {
                ++e.rim;
                continue;
            }
            const double a = degrees(normalAt(b, i), sphere);
            e.mean += a;
            e.max = std::max(e.max, a);
            ++e.hits;
        }
    e.mean /= double(std::max<std::size_t>(e.hits, 1));
    return e;
}

// The same bits in a channel of both captures.
bool sameBits(const Buffer& a, const Buffer& b, const std::string& channel) {
    const std::size_t n = std::size_t(a.width()) * std::size_t(a.height());
    const bool floats = a.channelType(channel) == ChannelType::Float32;
    const void* pa = floats ? static_cast<const void*>(a.hostFloat(channel)) : a.hostUInt(channel);
    const void* pb = floats ? static_cast<const void*>(b.hostFloat(channel)) : b.hostUInt(channel);
    return pa && pb && std::memcmp(pa, pb, 4 * n) == 0;
}

const std::string kIsosurface = "  - {file: r.vti, representation: isosurface, contourBy: r, isosurfaces: [0.7]}\n";

}  // namespace

TEST(SmoothNormals, SphereIsosurfaceFollowsTheSphereNotTheFacets) {
    test::TempDir dir;
    writeDistanceVolume(dir.file("r.vti"));
    const Capture smooth = capture(dir, kIsosurface, "normals: smooth");
    const Capture geometric = capture(dir, kIsosurface, "normals: geometric");
    const AngleErrors s = sphereErrors(smooth, kCentre), g = sphereErrors(geometric, kCentre);
    std::printf("sphere isosurface, 16 cells across, r = 0.7, %zu hits (%zu at the rim left out): smooth mean %.3f "
                "max %.3f degrees; geometric mean %.3f max %.3f degrees\n", s.hits, s.rim, s.mean, s.max, g.mean, g.max);
    ASSERT_GT(s.hits, 3000u);
    EXPECT_LT(s.max, 1.0);
    EXPECT_LT(s.mean, 0.5);
    EXPECT_GT(g.mean, 5 * s.mean) << "smooth normals are far closer than the facets'";
    EXPECT_GT(g.max, 5.0);
}

TEST(SmoothNormals, CubeKeepsExactlyFlatFacesAtThirtyDegrees) {
    test::TempDir dir;
    test::writeObj(dir.file("cube.obj"), test::unitCube({-0.5, -0.5, -0.5}));
    const Capture smooth = capture(dir, "  - {file: cube.obj}\n", "normals: smooth, featureAngle: 30");
    const Capture geometric = capture(dir, "  - {file: cube.obj}\n", "normals: geometric");
    const Buffer& b = *smooth.image;
    std::size_t hits = 0;
    for (std::size_t i = 0; i < std::size_t(b.width()) * std::size_t(b.height()); ++i) {
        if (!std::isfinite(b.hostFloat("Z")[i])) continue;
        ++hits;
        const Vec3 n = normalAt(b, i);
        EXPECT_EQ(std::abs(n.x) + std::abs(n.y) + std::abs(n.z), 1.0) << "pixel " << i << ": not along one axis";
        EXPECT_EQ(n, normalAt(*geometric.image, i)) << "pixel " << i << ": not the face's normal";
    }
    EXPECT_GT(hits, 3000u);
}

TEST(SmoothNormals, TessellatedSphereMeshIsSmooth) {
    test::TempDir dir;
    const Vec3 centre{0.1, 0, -0.05};
    test::writeObj(dir.file("sphere.obj"), test::uvSphere(12, 24, 0.8, centre));
    const Capture smooth = capture(dir, "  - {file: sphere.obj}\n", "normals: true", {1.7, 2.3, 3.1}, centre);
    const Capture geometric = capture(dir, "  - {file: sphere.obj}\n", "normals: geometric", {1.7, 2.3, 3.1}, centre);
    const AngleErrors s = sphereErrors(smooth, centre), g = sphereErrors(geometric, centre);
    std::printf("UV sphere mesh 12 x 24, %zu hits (%zu at the rim left out): smooth mean %.3f max %.3f degrees; "
                "geometric mean %.3f max %.3f degrees\n", s.hits, s.rim, s.mean, s.max, g.mean, g.max);
    ASSERT_GT(s.hits, 3000u);
    EXPECT_LT(s.max, 2.0);
    EXPECT_GT(g.mean, 4 * s.mean);
}

TEST(SmoothNormals, StylesDifferOnlyInNormalsAndGeometricIsTheFacets) {
    test::TempDir dir;
    writeDistanceVolume(dir.file("r.vti"));
    const std::string objects = kIsosurface + "  - {file: r.vti, representation: isosurface, contourBy: r, "
                                              "isosurfaces: [0.3], translate: [0.9, 0.2, 0]}\n";
    const Capture smooth = capture(dir, objects, "normals: smooth, scalars: [r]");
    const Capture geometric = capture(dir, objects, "normals: geometric, scalars: [r]");
    for (const char* c : {"Z", "r", "objectId", "primitiveId"})
        EXPECT_TRUE(sameBits(*smooth.image, *geometric.image, c)) << c;
    EXPECT_FALSE(sameBits(*smooth.image, *geometric.image, "N.x"));
    // Without its vertex normals the smooth scene renders the geometric
    // capture's bits: the style changes nothing else, and geometric is the
    // path every capture took before smooth normals.
    auto stripped = std::make_shared<Scene>(*smooth.scene.scene);
    for (auto& o : stripped->objects) takeVertexNormals(o);
    const BufferPtr plain = render(stripped, smooth.scene.cameras.at(0).camera, smooth.scene.request);
    for (const char* c : {"Z", "r", "N.x", "N.y", "N.z", "objectId", "primitiveId"})
        EXPECT_TRUE(sameBits(*plain, *geometric.image, c)) << c;
    // And the geometric normal is the hit triangle's, facing the camera.
    const Buffer& b = *geometric.image;
    const Camera& cam = geometric.scene.cameras.at(0).camera;
    for (int y = 0; y < b.height(); y += 3)
        for (int x = 0; x < b.width(); x += 3) {
            const std::size_t i = std::size_t(y) * std::size_t(b.width()) + std::size_t(x);
            if (!std::isfinite(b.hostFloat("Z")[i])) continue;
            const SceneObject& o = geometric.scene.scene->objects.at(b.hostUInt("objectId")[i]);
            const std::uint32_t* t = &o.indices[3 * std::size_t(b.hostUInt("primitiveId")[i])];
            auto p = [&](int k) { return Vec3{o.vertices[4 * t[k]], o.vertices[4 * t[k] + 1], o.vertices[4 * t[k] + 2]}; };
            Vec3 n = normalize(cross(p(1) - p(0), p(2) - p(0)));
            if (dot(n, cam.worldPosition(x + 0.5, y + 0.5, 1) - cam.position) > 0) n = n * -1.0;
            // Embree's normal is a cross product in single precision: slivers
            // of the contour lose a few digits.
            EXPECT_LT(length(normalAt(b, i) - n), 2e-4) << "pixel " << x << ", " << y;
        }
}

TEST(SmoothNormals, NeverFaceAwayAndTraceAgreesWithRender) {
    test::TempDir dir;
    writeDistanceVolume(dir.file("r.vti"));
    const Capture c = capture(dir, kIsosurface, "normals: smooth");
    const Buffer& b = *c.image;
    const Camera& cam = c.scene.cameras.at(0).camera;
    RayBatch rays;
    std::vector<std::size_t> pixels;
    for (int y = 0; y < b.height(); ++y)
        for (int x = 0; x < b.width(); ++x) {
            const std::size_t i = std::size_t(y) * std::size_t(b.width()) + std::size_t(x);
            if (!std::isfinite(b.hostFloat("Z")[i])) continue;
            Vec3 o, d;
            cam.ray(x + 0.5, y + 0.5, o, d);
            EXPECT_LT(dot(normalAt(b, i), d), 0.0) << "pixel " << x << ", " << y << " faces away";
            if ((x + y) % 7 == 0) {
                rays.add(o, d);
                pixels.push_back(i);
            }
        }
    auto backend = test::pluginRegistry().createBackend("embree");
    backend->setScene(c.scene.scene);
    FilterRunOptions o;
    o.threads = 2;
    CaptureRequest r;
    r.normals = true;
    const BufferPtr traced = backend->trace(rays, r, *makeStandaloneContext(o, "smooth_normals"));
    for (std::size_t k = 0; k < pixels.size(); ++k)
        EXPECT_LT(length(normalAt(*traced, k) - normalAt(b, pixels[k])), 1e-4) << "pixel " << pixels[k];
}
