// The in situ API (darkroom/insitu.h) in one process: a session's database
// equals `darkroom capture` of the same geometry read from a file, byte for
// byte; the arrays are shared, not copied (a change made after handing them
// over shows in the capture); mistakes are refused with a message.
#include "test_support.h"
#include "vtk_test_files.h"

#include <darkroom/data/image_io.h>
#include <darkroom/insitu.h>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>

namespace darkroom::test {
namespace {

std::string runnerOutput(const std::string& args) {
    const std::string command = std::string("DARKROOM_PLUGIN_PATH= ") + DARKROOM_RUNNER + " " + args + " 2>&1";
    std::string out;
    if (FILE* p = popen(command.c_str(), "r")) {
        char buf[4096];
        for (std::size_t n; (n = fread(buf, 1, sizeof buf, p)) > 0;) out.append(buf, n);
        const int status = pclose(p);
        if (status != 0) out += "\n(exit status " + std::to_string(status) + ")";
    }
    return out;
}

// One piece of test geometry as the in situ API wants it: x, y, z, radius
// records, triangles from the quads (fanned as the readers do), polylines as
// segment starts, vertex cells as points.
struct Arrays {
    std::vector<float> surface, lineVertices, pointVertices, height, lineHeight, pointHeight;
    std::vector<std::uint32_t> triangles, segments;
};

Arrays arraysOf(const VtpPiece& piece, float radius) {
    // The scene file's transform (scale 1, offset 0) turns -0 into +0; so
    // does this, so that both captures see the same coordinates.
    VtpPiece p = piece;
    for (float& x : p.points) x += 0.0f;
    Arrays a;
    // The reader keeps only the points the triangles use, in order of first use.
    std::vector<std::int64_t> map(p.points.size() / 3, -1);
    auto surfaceVertex = [&](std::uint32_t i) {
        if (map[i] < 0) {
            map[i] = std::int64_t(a.surface.size() / 4);
            a.surface.insert(a.surface.end(), {p.points[3 * i], p.points[3 * i + 1], p.points[3 * i + 2], 0.0f});
            a.height.push_back(p.pointData[0].second[i]);
        }
        return std::uint32_t(map[i]);
    };
    for (const auto& quad : p.polys)
        for (std::size_t k = 1; k + 1 < quad.size(); ++k)
            for (auto v : {quad[0], quad[k], quad[k + 1]}) a.triangles.push_back(surfaceVertex(v));
    for (const auto& line : p.lines) {
        const auto base = std::uint32_t(a.lineVertices.size() / 4);
        for (std::size_t k = 0; k < line.size(); ++k) {
            const auto i = line[k];
            a.lineVertices.insert(a.lineVertices.end(), {p.points[3 * i], p.points[3 * i + 1], p.points[3 * i + 2], radius});
            a.lineHeight.push_back(p.pointData[0].second[i]);
            if (k + 1 < line.size()) a.segments.push_back(base + std::uint32_t(k));
        }
    }
    for (const auto& vert : p.verts)
        for (auto i : vert) {
            a.pointVertices.insert(a.pointVertices.end(), {p.points[3 * i], p.points[3 * i + 1], p.points[3 * i + 2], radius});
            a.pointHeight.push_back(p.pointData[0].second[i]);
        }
    return a;
}

const double kCameras[2][3][3] = {{{0.3, -2.5, 2.0}, {0, 0, 0}, {0, 0, 1}}, {{2.2, 1.0, 1.5}, {0, 0.1, 0}, {0, 0, 1}}};

TEST(InSitu, ASessionWritesWhatDarkroomCaptureWritesForTheSameGeometry) {
    TempDir dir;
    // The last band has a polyline and vertex cells besides its quads.
    const VtpPiece piece = heightFieldPieces(9, 13, 3)[2];
    writeVtp(dir.file("field.vtp"), piece);
    writeText(dir.file("scene.yaml"),
              "objects:\n"
              "  - file: field.vtp\n"
              "    radius: 0.04\n"
              "    fields: [height]\n"
              "cameras:\n"
              "  resolution: [40, 30]\n"
              "  fov: 35\n"
              // Unused by a perspective camera but stored with it: the
              // session keeps the default 2, the scene file's default
              // depends on the bounds.
              "  height: 2\n"
              "  list:\n"
              "    - {position: [0.3, -2.5, 2], target: [0, 0, 0], up: [0, 0, 1]}\n"
              "    - {position: [2.2, 1.0, 1.5], target: [0, 0.1, 0], up: [0, 0, 1]}\n"
              "channels:\n"
              "  scalars: [height]\n"
              "  normals: geometric\n"  // what the in situ API stores (docs/insitu.md, Normals)
              "  objectId: true\n"
              "  primitiveId: true\n");
    const std::string captured = runnerOutput("capture " + dir.file("scene.yaml") + " -o " + dir.file("file.cdb") + " -q");
    ASSERT_EQ(captured, "");

    Arrays a = arraysOf(piece, 0.04f);
    darkroom_insitu* s = darkroom_insitu_open(dir.file("insitu.cdb").c_str(), DARKROOM_INSITU_CREATE);
    ASSERT_EQ(darkroom_insitu_set_image(s, 40, 30, 35.0, 0.0), DARKROOM_INSITU_OK);
    for (const auto& c : kCameras) ASSERT_EQ(darkroom_insitu_add_camera(s, c[0], c[1], c[2]), DARKROOM_INSITU_OK);
    ASSERT_EQ(darkroom_insitu_request_field(s, "height"), DARKROOM_INSITU_OK);
    ASSERT_EQ(darkroom_insitu_request_normals(s, 1), DARKROOM_INSITU_OK);
    ASSERT_EQ(darkroom_insitu_request_ids(s, 1, 1), DARKROOM_INSITU_OK);
    ASSERT_EQ(darkroom_insitu_begin_step(s, 0.0), DARKROOM_INSITU_OK);
    // The order of the reader's parts: surface, lines, points.
    ASSERT_EQ(darkroom_insitu_triangles(s, "field/surface", a.surface.data(), 16, std::int64_t(a.surface.size() / 4),
                                        a.triangles.data(), std::int64_t(a.triangles.size() / 3)),
              DARKROOM_INSITU_OK);
    ASSERT_EQ(darkroom_insitu_field(s, "field/surface", "height", a.height.data(), std::int64_t(a.height.size()),
                                    DARKROOM_INSITU_POINT_DATA),
              DARKROOM_INSITU_OK);
    ASSERT_EQ(darkroom_insitu_lines(s, "field/lines", a.lineVertices.data(), 16, std::int64_t(a.lineVertices.size() / 4),
                                    a.segments.data(), std::int64_t(a.segments.size()), nullptr, 0.0f),
              DARKROOM_INSITU_OK);
    ASSERT_EQ(darkroom_insitu_field(s, "field/lines", "height", a.lineHeight.data(), std::int64_t(a.lineHeight.size()),
                                    DARKROOM_INSITU_POINT_DATA),
              DARKROOM_INSITU_OK);
    ASSERT_EQ(darkroom_insitu_points(s, "field/points", a.pointVertices.data(), 16,
                                     std::int64_t(a.pointVertices.size() / 4), nullptr, 0.0f),
              DARKROOM_INSITU_OK);
    ASSERT_EQ(darkroom_insitu_field(s, "field/points", "height", a.pointHeight.data(),
                                    std::int64_t(a.pointHeight.size()), DARKROOM_INSITU_POINT_DATA),
              DARKROOM_INSITU_OK);
    ASSERT_EQ(darkroom_insitu_capture(s), DARKROOM_INSITU_OK) << darkroom_insitu_error(s);
    EXPECT_EQ(darkroom_insitu_rows_written(s), 2);
    EXPECT_EQ(darkroom_insitu_copied_bytes(s), 0);
    ASSERT_EQ(darkroom_insitu_close(s), DARKROOM_INSITU_OK);

    for (int c = 0; c < 2; ++c) {
        const std::string file = dir.file("file.cdb/camera=" + std::to_string(c) + ".exr");
        const std::string insitu = dir.file("insitu.cdb/time=0_camera=" + std::to_string(c) + ".exr");
        ASSERT_TRUE(std::filesystem::exists(insitu)) << insitu;
        EXPECT_TRUE(identical(*readImage(file), *readImage(insitu))) << "camera " << c;
        EXPECT_TRUE(readText(file) == readText(insitu)) << "camera " << c << ": the products differ in bytes";
    }
    const std::string info = runnerOutput("info --strict " + dir.file("insitu.cdb"));
    EXPECT_NE(info.find("2 rows, 3 columns"), std::string::npos) << info;
}

TEST(InSitu, ArraysAreSharedNotCopied) {
    TempDir dir;
    // One sphere, handed over, then moved before the capture: the capture
    // sees where it is then, since the ray tracer reads the same memory.
    std::vector<float> sphere = {0.0f, 0.0f, 0.0f, 0.5f};
    darkroom_insitu* s = darkroom_insitu_open(dir.file("db.cdb").c_str(), DARKROOM_INSITU_CREATE);
    ASSERT_EQ(darkroom_insitu_set_image(s, 21, 21, 0.0, 4.0), DARKROOM_INSITU_OK);
    const double at[3] = {0, 0, 5}, to[3] = {0, 0, 0}, up[3] = {0, 1, 0};
    ASSERT_EQ(darkroom_insitu_add_camera(s, at, to, up), DARKROOM_INSITU_OK);
    ASSERT_EQ(darkroom_insitu_begin_step(s, 1.0), DARKROOM_INSITU_OK);
    ASSERT_EQ(darkroom_insitu_points(s, "ball", sphere.data(), 16, 1, nullptr, 0.0f), DARKROOM_INSITU_OK);
    sphere[2] = 1.0f;  // towards the camera
    ASSERT_EQ(darkroom_insitu_capture(s), DARKROOM_INSITU_OK) << darkroom_insitu_error(s);
    EXPECT_EQ(darkroom_insitu_copied_bytes(s), 0);
    // Radii apart from the positions must be joined to them: counted.
    const float radius = 0.5f;
    ASSERT_EQ(darkroom_insitu_begin_step(s, 2.0), DARKROOM_INSITU_OK);
    ASSERT_EQ(darkroom_insitu_points(s, "ball", sphere.data(), 16, 1, &radius, 0.0f), DARKROOM_INSITU_OK);
    EXPECT_EQ(darkroom_insitu_copied_bytes(s), 16);
    ASSERT_EQ(darkroom_insitu_close(s), DARKROOM_INSITU_OK);
    const auto image = readImage(dir.file("db.cdb/time=1_camera=0.exr"));
    // Orthographic from z = 5: the sphere's front at z = 1.5 lies at depth 3.5.
    EXPECT_NEAR(image->hostFloat("Z")[10 * 21 + 10], 3.5f, 1e-5f);
}

TEST(InSitu, RecordsNotSixteenByteAlignedAreCopiedForEmbree) {
    // Embree reads the x, y, z, radius records of tubes and spheres with
    // aligned 16-byte loads: records at an address or a stride that is not a
    // multiple of 16 segfaulted inside the BVH build (found by the insitu
    // fuzz harness). They are joined into aligned records, counted as copied.
    TempDir dir;
    alignas(16) float storage[4 + 2 * 8] = {};
    float* misaligned = storage + 1;                       // 4 bytes past a 16-byte boundary
    auto record = [&](float* base, std::size_t stride, int i, float x) {
        float* r = reinterpret_cast<float*>(reinterpret_cast<char*>(base) + std::size_t(i) * stride);
        r[0] = x, r[1] = 0.0f, r[2] = 0.0f, r[3] = 0.4f;
    };
    darkroom_insitu* s = darkroom_insitu_open(dir.file("db.cdb").c_str(), DARKROOM_INSITU_CREATE);
    ASSERT_EQ(darkroom_insitu_set_image(s, 21, 21, 0.0, 4.0), DARKROOM_INSITU_OK);
    const double at[3] = {0, 0, 5}, to[3] = {0, 0, 0}, up[3] = {0, 1, 0};
    ASSERT_EQ(darkroom_insitu_add_camera(s, at, to, up), DARKROOM_INSITU_OK);
    const std::uint32_t segment[1] = {0};
    for (const auto& [base, stride] : {std::pair{misaligned, std::size_t(16)}, std::pair{storage, std::size_t(20)}}) {
        record(base, stride, 0, -1.0f);
        record(base, stride, 1, 1.0f);
        const std::int64_t before = darkroom_insitu_copied_bytes(s);
        ASSERT_EQ(darkroom_insitu_begin_step(s, stride == 16 ? 0.0 : 1.0), DARKROOM_INSITU_OK);
        ASSERT_EQ(darkroom_insitu_points(s, "balls", base, stride, 2, nullptr, 0.0f), DARKROOM_INSITU_OK);
        ASSERT_EQ(darkroom_insitu_lines(s, "tube", base, stride, 2, segment, 1, nullptr, 0.0f), DARKROOM_INSITU_OK);
        EXPECT_EQ(darkroom_insitu_copied_bytes(s) - before, 2 * 2 * 16) << "stride " << stride;
        ASSERT_EQ(darkroom_insitu_capture(s), DARKROOM_INSITU_OK) << darkroom_insitu_error(s);
    }
    ASSERT_EQ(darkroom_insitu_close(s), DARKROOM_INSITU_OK);
    for (const char* file : {"db.cdb/time=0_camera=0.exr", "db.cdb/time=1_camera=0.exr"}) {
        // Orthographic from z = 5, 4 units high: the sphere at x = 1 (radius
        // 0.4) has its front at z = 0.4 under pixel (15, 10).
        const auto image = readImage(dir.file(file));
        EXPECT_NEAR(image->hostFloat("Z")[10 * 21 + 15], 4.6f, 1e-4f) << file;
    }
}

TEST(InSitu, MistakesAreRefusedWithAMessage) {
    TempDir dir;
    darkroom_insitu* s = darkroom_insitu_open(dir.file("db.cdb").c_str(), DARKROOM_INSITU_CREATE);
    EXPECT_EQ(darkroom_insitu_capture(s), DARKROOM_INSITU_BAD_INPUT);
    EXPECT_NE(std::string(darkroom_insitu_error(s)).find("no cameras"), std::string::npos);
    EXPECT_EQ(darkroom_insitu_set_image(s, 0, 10, 30.0, 0.0), DARKROOM_INSITU_BAD_INPUT);
    const double target[3] = {0, 0, 0}, up[3] = {0, 0, 0}, phi[1] = {0}, theta[1] = {0};
    EXPECT_EQ(darkroom_insitu_camera_orbit(s, target, 3.0, up, phi, 1, theta, 1), DARKROOM_INSITU_BAD_INPUT);
    EXPECT_NE(std::string(darkroom_insitu_error(s)).find("up must not be zero"), std::string::npos);
    float v[12] = {};
    const std::uint32_t tri[3] = {0, 1, 5};
    EXPECT_EQ(darkroom_insitu_triangles(s, "t", v, 16, 3, tri, 1), DARKROOM_INSITU_BAD_INPUT);
    EXPECT_NE(std::string(darkroom_insitu_error(s)).find("begin_step"), std::string::npos);
    ASSERT_EQ(darkroom_insitu_begin_step(s, 0.0), DARKROOM_INSITU_OK);
    ASSERT_EQ(darkroom_insitu_triangles(s, "t", v, 16, 3, tri, 1), DARKROOM_INSITU_OK);
    const float values[2] = {1, 2};
    EXPECT_EQ(darkroom_insitu_field(s, "t", "f", values, 2, DARKROOM_INSITU_POINT_DATA), DARKROOM_INSITU_BAD_INPUT);
    EXPECT_NE(std::string(darkroom_insitu_error(s)).find("has 2 values; expected one per vertex (3)"), std::string::npos)
        << darkroom_insitu_error(s);
    const double pos[3] = {0, 0, 3}, upY[3] = {0, 1, 0};
    ASSERT_EQ(darkroom_insitu_add_camera(s, pos, target, upY), DARKROOM_INSITU_OK);
    // Vertex 5 of 3: caught before Embree would read out of bounds.
    EXPECT_EQ(darkroom_insitu_capture(s), DARKROOM_INSITU_FAILED);
    EXPECT_NE(std::string(darkroom_insitu_error(s)).find("triangle 0 uses vertex 5 but there are only 3"), std::string::npos)
        << darkroom_insitu_error(s);
    // Without MPI_Init there is no communicator to share.
    EXPECT_EQ(darkroom_insitu_set_mpi_comm(s, 0), DARKROOM_INSITU_FAILED);
    EXPECT_NE(std::string(darkroom_insitu_error(s)).find("MPI"), std::string::npos) << darkroom_insitu_error(s);
    EXPECT_EQ(darkroom_insitu_close(s), DARKROOM_INSITU_OK);
    // A bad mode: the session carries the error into every call.
    darkroom_insitu* bad = darkroom_insitu_open(dir.file("x.cdb").c_str(), 7);
    EXPECT_EQ(darkroom_insitu_begin_step(bad, 0.0), DARKROOM_INSITU_BAD_INPUT);
    EXPECT_NE(std::string(darkroom_insitu_error(bad)).find("mode 7"), std::string::npos);
    EXPECT_EQ(darkroom_insitu_close(bad), DARKROOM_INSITU_BAD_INPUT);
}

TEST(InSitu, AResumedSessionKeepsItsRowsAndAnExistingDatabaseIsRefused) {
    TempDir dir;
    const std::string db = dir.file("db.cdb");
    std::vector<float> sphere = {0.0f, 0.0f, 0.0f, 0.5f};
    auto session = [&](int mode, double time, int& code) {
        darkroom_insitu* s = darkroom_insitu_open(db.c_str(), mode);
        const double at[3] = {0, 0, 5}, to[3] = {0, 0, 0}, up[3] = {0, 1, 0};
        darkroom_insitu_add_camera(s, at, to, up);
        darkroom_insitu_set_image(s, 8, 8, 30.0, 0.0);
        darkroom_insitu_begin_step(s, time);
        darkroom_insitu_points(s, "ball", sphere.data(), 16, 1, nullptr, 0.0f);
        code = darkroom_insitu_capture(s);
        const std::string error = darkroom_insitu_error(s);
        const auto rows = darkroom_insitu_rows_written(s);
        darkroom_insitu_close(s);
        return std::make_pair(rows, error);
    };
    int code = -1;
    EXPECT_EQ(session(DARKROOM_INSITU_CREATE, 0.0, code).first, 1);
    EXPECT_EQ(code, DARKROOM_INSITU_OK);
    const auto refused = session(DARKROOM_INSITU_CREATE, 1.0, code);
    EXPECT_EQ(code, DARKROOM_INSITU_FAILED);
    EXPECT_NE(refused.second.find("already exists"), std::string::npos) << refused.second;
    EXPECT_EQ(session(DARKROOM_INSITU_RESUME, 0.0, code).first, 0);  // time 0 is there already
    EXPECT_EQ(session(DARKROOM_INSITU_RESUME, 1.0, code).first, 1);
    EXPECT_NE(readText(db + "/data.csv").find("1,0,time=1_camera=0.exr"), std::string::npos) << readText(db + "/data.csv");
}

}  // namespace
}  // namespace darkroom::test
