// `darkroom capture` of a time series (docs/scene-format.md, "Time series"):
// 12 tetrahedral volumes written by another tool (meshio, through Debian's
// python3) that grow step by step, named by a ParaView .pvd, a glob or a
// Cinema database, captured by one command into one database.
#include "runner_process.h"
#include "test_support.h"

#include <darkroom/data/cinema/database.h>
#include <darkroom/data/image_io.h>

#include <gtest/gtest.h>

#include <chrono>
#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <sys/wait.h>
#include <thread>

#ifndef DARKROOM_PYTHON
#define DARKROOM_PYTHON "python3"
#endif

namespace fs = std::filesystem;
using namespace darkroom;
using darkroom::test::runDarkroom;

namespace {

constexpr int kSteps = 12;

// Step i: a box [0, 1 + 0.25 i] x [0, 1] x [0, 1] cut into tetrahedra (6 per
// cube of a 4 x 3 x 3 point grid), field f = x + y z + i; so its bounds grow
// and a camera framed on each step would move. Plus a ParaView collection
// timing step i at 0.1 i.
const char* kWriter = R"(import sys, numpy as np, meshio
out = sys.argv[1]
n = 12
entries = []
for i in range(n):
    xs, ys, zs = np.linspace(0, 1 + 0.25 * i, 4), np.linspace(0, 1, 3), np.linspace(0, 1, 3)
    pts = np.array([[x, y, z] for z in zs for y in ys for x in xs])
    idx = lambda a, b, c: a + 4 * (b + 3 * c)
    tets = []
    for c in range(2):
        for b in range(2):
            for a in range(3):
                v = [idx(a + (k & 1), b + ((k >> 1) & 1), c + (k >> 2)) for k in range(8)]
                for p in ([0, 1, 3, 7], [0, 1, 5, 7], [0, 2, 3, 7], [0, 2, 6, 7], [0, 4, 5, 7], [0, 4, 6, 7]):
                    tets.append([v[q] for q in p])
    f = pts[:, 0] + pts[:, 1] * pts[:, 2] + i
    name = "step_%02d.vtu" % i
    meshio.write(out + "/steps/" + name, meshio.Mesh(pts, [("tetra", np.array(tets))], point_data={"f": f}))
    entries.append('    <DataSet timestep="%g" part="0" file="steps/%s"/>' % (0.1 * i, name))
open(out + "/series.pvd", "w").write('<?xml version="1.0"?>\n<VTKFile type="Collection" version="0.1">\n'
    '  <Collection>\n' + "\n".join(entries) + '\n  </Collection>\n</VTKFile>\n')
)";

// Writes the 12 steps and series.pvd into `dir`; false when meshio is missing.
bool writeSeries(const test::TempDir& dir) {
    fs::create_directories(dir.file("steps"));
    test::writeText(dir.file("write_series.py"), kWriter);
    const std::string cmd =
        std::string(DARKROOM_PYTHON) + " " + dir.file("write_series.py") + " " + dir.path() + " 2>" + dir.file("py.err");
    return std::system(cmd.c_str()) == 0;
}

std::string scene(const std::string& file, const std::string& extra = "") {
    return "objects:\n  - name: field\n    file: " + file + "\n" + extra +
           "  - generator: particles\n    parameters: {count: 200, seed: 3}\n"
           "cameras:\n  resolution: [48, 32]\n  grid: {phi: 3, theta: [0, 30]}\n"
           "channels:\n  objectId: true\n";
}

struct DbRow {
    std::map<std::string, std::string> cells;
    std::string product;
};

std::vector<DbRow> rows(const std::string& db) {
    const CinemaDatabase d = CinemaDatabase::open(db);
    std::vector<DbRow> out;
    for (std::size_t r = 0; r < d.rowCount(); ++r) {
        DbRow row;
        for (std::size_t c : d.parameterColumns()) row.cells[d.columns()[c].name] = d.cell(r, c);
        row.product = d.productPath(r);
        out.push_back(std::move(row));
    }
    return out;
}

Camera cameraOf(const DbRow& row) {
    const auto image = readImage(row.product);
    EXPECT_TRUE(image->metadata().camera.has_value()) << row.product;
    return image->metadata().camera.value_or(Camera{});
}

// Pixels of object `id` in the product.
std::size_t pixelsOf(const DbRow& row, std::uint32_t id) {
    const auto image = readImage(row.product);
    const std::uint32_t* ids = image->hostUInt("objectId");
    std::size_t n = 0;
    for (std::size_t i = 0; ids && i < std::size_t(image->width()) * image->height(); ++i) n += ids[i] == id;
    return n;
}

// The collection's time of step i as data.csv writes it: "0.3" (i / 10).
std::string tenth(int i) { return i % 10 ? std::to_string(i / 10) + "." + std::to_string(i % 10) : std::to_string(i / 10); }

#define REQUIRE_SERIES(dir)                                                                                    \
    if (!writeSeries(dir)) GTEST_SKIP() << "meshio could not write the series: " << test::readText(dir.file("py.err"))

}  // namespace

TEST(CaptureSeries, PvdGivesOneDatabaseWithTimeAndCamerasThatStayPut) {
    test::TempDir dir;
    REQUIRE_SERIES(dir);
    test::writeText(dir.file("s.yaml"), scene("series.pvd"));
    const auto cap = runDarkroom({"capture", dir.file("s.yaml"), "-o", dir.file("out.cdb")});
    ASSERT_EQ(cap.exitCode, 0) << cap.err;
    const std::vector<DbRow> all = rows(dir.file("out.cdb"));
    ASSERT_EQ(all.size(), std::size_t(kSteps * 6));  // 12 steps x 3 phi x 2 theta
    std::map<std::string, int> perTime;
    std::map<std::string, Camera> first;  // per phi/theta
    std::map<std::string, std::size_t> staticPixels;  // per time, over all cameras
    for (const DbRow& r : all) {
        ASSERT_EQ(r.cells.size(), 3u);  // time, phi, theta
        ++perTime[r.cells.at("time")];
        const std::string view = r.cells.at("phi") + "/" + r.cells.at("theta");
        const Camera c = cameraOf(r);
        if (!first.count(view)) first[view] = c;
        EXPECT_EQ(c.position, first[view].position) << "time " << r.cells.at("time") << " view " << view;
        EXPECT_EQ(c.forward, first[view].forward);
        EXPECT_EQ(c.up, first[view].up);
        staticPixels[r.cells.at("time")] += pixelsOf(r, 1);
    }
    ASSERT_EQ(perTime.size(), std::size_t(kSteps));
    for (int i = 0; i < kSteps; ++i) {
        const std::string t = tenth(i);
        EXPECT_EQ(perTime[t], 6) << "time " << t;
        EXPECT_GT(staticPixels[t], 0u) << "the static particles are missing at time " << t;
    }
}

TEST(CaptureSeries, FramingPerStepMovesTheCameras) {
    test::TempDir dir;
    REQUIRE_SERIES(dir);
    std::string s = scene("series.pvd");
    s.replace(s.find("cameras:\n"), 9, "cameras:\n  framing: step\n");
    test::writeText(dir.file("s.yaml"), s);
    const auto cap = runDarkroom({"capture", dir.file("s.yaml"), "-o", dir.file("out.cdb")});
    ASSERT_EQ(cap.exitCode, 0) << cap.err;
    std::map<std::string, Camera> at0, at11;
    for (const DbRow& r : rows(dir.file("out.cdb"))) {
        const std::string view = r.cells.at("phi") + "/" + r.cells.at("theta");
        if (r.cells.at("time") == "0") at0[view] = cameraOf(r);
        if (r.cells.at("time") == tenth(11)) at11[view] = cameraOf(r);
    }
    ASSERT_EQ(at0.size(), 6u);
    ASSERT_EQ(at11.size(), 6u);
    for (const auto& [view, c] : at0) EXPECT_NE(c.position, at11[view].position) << view;
}

TEST(CaptureSeries, GlobTimesStepsByTheNumberInTheirNames) {
    test::TempDir dir;
    REQUIRE_SERIES(dir);
    test::writeText(dir.file("s.yaml"), scene("steps/step_*.vtu"));
    const auto cap = runDarkroom({"capture", dir.file("s.yaml"), "-o", dir.file("out.cdb")});
    ASSERT_EQ(cap.exitCode, 0) << cap.err;
    std::map<std::string, int> perTime;
    for (const DbRow& r : rows(dir.file("out.cdb"))) ++perTime[r.cells.at("time")];
    ASSERT_EQ(perTime.size(), std::size_t(kSteps));
    for (int i = 0; i < kSteps; ++i) EXPECT_EQ(perTime[std::to_string(i)], 6) << i;
}

TEST(CaptureSeries, CinemaDatabaseColumnsAreCarried) {
    test::TempDir dir;
    REQUIRE_SERIES(dir);
    fs::create_directories(dir.file("source.cdb"));
    std::string csv = "time,run,FILE\n";
    for (int i = 0; i < kSteps; ++i)
        csv += std::to_string(i * 2) + ",viscous," + "../steps/step_" + (i < 10 ? "0" : "") + std::to_string(i) + ".vtu\n";
    test::writeText(dir.file("source.cdb/data.csv"), csv);
    test::writeText(dir.file("s.yaml"), scene("source.cdb"));
    const auto cap = runDarkroom({"capture", dir.file("s.yaml"), "-o", dir.file("out.cdb")});
    ASSERT_EQ(cap.exitCode, 0) << cap.err;
    const std::vector<DbRow> all = rows(dir.file("out.cdb"));
    ASSERT_EQ(all.size(), std::size_t(kSteps * 6));
    std::map<std::string, int> perTime;
    for (const DbRow& r : all) {
        EXPECT_EQ(r.cells.at("run"), "viscous");
        ++perTime[r.cells.at("time")];
    }
    for (int i = 0; i < kSteps; ++i) EXPECT_EQ(perTime[std::to_string(2 * i)], 6) << i;
}

TEST(CaptureSeries, SeveralSeriesAreMatchedByTime) {
    test::TempDir dir;
    REQUIRE_SERIES(dir);
    // The glob times step i at i, the collection at 0.1 i: they do not match...
    std::string s = scene("series.pvd");
    s.insert(s.find("  - generator"), "  - name: copy\n    file: steps/step_*.vtu\n    translate: [0, 3, 0]\n");
    test::writeText(dir.file("s.yaml"), s);
    const auto bad = runDarkroom({"capture", dir.file("s.yaml"), "-o", dir.file("bad.cdb")});
    EXPECT_EQ(bad.exitCode, 2);
    EXPECT_NE(bad.err.find("object 'copy' has no step at time 0.1"), std::string::npos) << bad.err;
    // ... unless the glob is given the collection's times.
    std::string times = "    time: [";
    for (int i = 0; i < kSteps; ++i) times += (i ? ", " : "") + tenth(i);
    s.insert(s.find("    translate: [0, 3, 0]"), times + "]\n");
    test::writeText(dir.file("s.yaml"), s);
    const auto good = runDarkroom({"capture", dir.file("s.yaml"), "-o", dir.file("good.cdb")});
    ASSERT_EQ(good.exitCode, 0) << good.err;
    std::size_t copyPixels = 0;
    const std::vector<DbRow> all = rows(dir.file("good.cdb"));
    EXPECT_EQ(all.size(), std::size_t(kSteps * 6));
    for (const DbRow& r : all) copyPixels += pixelsOf(r, 1);
    EXPECT_GT(copyPixels, 0u);
}

TEST(CaptureSeries, ResumeRecapturesOnlyMissingSteps) {
    test::TempDir dir;
    REQUIRE_SERIES(dir);
    std::string s = scene("series.pvd");
    s.replace(s.find("[48, 32]"), 8, "[200, 150]");
    test::writeText(dir.file("s.yaml"), s);
    const std::string db = dir.file("out.cdb");
    const int pid = test::spawnDarkroom({"capture", dir.file("s.yaml"), "-o", db, "-j", "1"});
    ASSERT_GT(pid, 0);
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
    auto products = [&] {
        std::size_t n = 0;
        std::error_code ec;
        for (const auto& f : fs::directory_iterator(db, ec))
            n += f.path().extension() == ".exr" && f.path().filename().string().find(".tmp-") == std::string::npos;
        return n;
    };
    while (products() < 14 && std::chrono::steady_clock::now() < deadline)
        std::this_thread::sleep_for(std::chrono::milliseconds(2));
    ::kill(pid, SIGKILL);
    int status = 0;
    ::waitpid(pid, &status, 0);
    ASSERT_TRUE(WIFSIGNALED(status)) << "the capture finished before it could be killed";
    std::map<std::string, fs::file_time_type> before;
    for (const DbRow& r : rows(db)) before[r.product] = fs::last_write_time(r.product);
    ASSERT_GE(before.size(), 12u);  // two whole steps at least
    ASSERT_LT(before.size(), std::size_t(kSteps * 6));

    const auto resumed = runDarkroom({"capture", dir.file("s.yaml"), "-o", db, "--resume"});
    ASSERT_EQ(resumed.exitCode, 0) << resumed.err;
    const std::size_t rendered = kSteps * 6 - before.size();
    EXPECT_NE(resumed.err.find(std::to_string(rendered) + " entries rendered, " + std::to_string(before.size()) +
                               " kept"),
              std::string::npos)
        << resumed.err;
    const std::vector<DbRow> all = rows(db);
    EXPECT_EQ(all.size(), std::size_t(kSteps * 6));
    for (const auto& [product, time] : before) EXPECT_EQ(fs::last_write_time(product), time) << product << " rewritten";
}

TEST(CaptureSeries, BadSeriesAreReportedWithTheFileAndWhatWasExpected) {
    test::TempDir dir;
    REQUIRE_SERIES(dir);
    auto capture = [&](const std::string& file) {
        test::writeText(dir.file("s.yaml"), scene(file));
        return runDarkroom({"capture", dir.file("s.yaml"), "-o", dir.file("x.cdb")});
    };
    const auto none = capture("steps/nothing_*.vtu");
    EXPECT_EQ(none.exitCode, 2);
    EXPECT_NE(none.err.find("s.yaml:3:11: object 'field': no file matches"), std::string::npos) << none.err;
    EXPECT_NE(none.err.find("nothing_*.vtu"), std::string::npos) << none.err;

    std::string pvd = test::readText(dir.file("series.pvd"));
    pvd.replace(pvd.find("step_03.vtu"), 11, "missing.vtu");
    test::writeText(dir.file("missing.pvd"), pvd);
    const auto missing = capture("missing.pvd");
    EXPECT_EQ(missing.exitCode, 2);
    EXPECT_NE(missing.err.find("missing.pvd:7: DataSet at timestep 0.3 names"), std::string::npos) << missing.err;
    EXPECT_NE(missing.err.find("missing.vtu', which does not exist"), std::string::npos) << missing.err;

    test::writeText(dir.file("broken.pvd"), "<VTKFile type=\"Collection\"><Collection><DataSet timestep=\"0\"");
    const auto broken = capture("broken.pvd");
    EXPECT_EQ(broken.exitCode, 2);
    EXPECT_NE(broken.err.find("broken.pvd:1"), std::string::npos) << broken.err;
    EXPECT_NE(broken.err.find("expected a ParaView collection"), std::string::npos) << broken.err;
    EXPECT_FALSE(fs::exists(dir.file("x.cdb")));
}
