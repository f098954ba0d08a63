// A capture keeps the demo's maxima as a CSV point list beside each entry
// (store: pointList); `darkroom info` describes it; the Spheres node, finding it
// through CinemaReader's row, draws the same depth and normals as capturing the
// maxima as geometry with Embree.
#include "../../../tests/integration/runner/runner_process.h"
#include "test_support.h"

#include <darkroom/data/cinema/database.h>
#include <darkroom/core/evaluator.h>
#include <darkroom/core/graph.h>
#include <darkroom/scene/generators.h>
#include <darkroom/scene/point_list.h>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>

using namespace darkroom;
using ::testing::HasSubstr;

namespace {

std::string scene(bool asPointList) {
    return std::string("objects:\n"
                       "  - generator: isosurface\n"
                       "    parameters: {resolution: 32}\n"
                       "    fields: [height]\n"
                       "  - generator: maxima\n"
                       "    fields: [value]\n") +
           (asPointList ? "    store: pointList\n" : "") +
           "cameras:\n"
           "  resolution: [240, 200]\n"
           "  grid: {phi: [0, 60], theta: [20], distance: 4.6, target: [0, 0, 0], up: [0, 0, 1]}\n"
           "channels:\n"
           "  normals: true\n";
}

}  // namespace

TEST(PointListCapture, StoredBesideEachEntryAndDrawnLikeEmbreesSpheres) {
    test::TempDir dir;
    test::writeText(dir.file("kept.yaml"), scene(true));
    test::writeText(dir.file("traced.yaml"), scene(false));
    for (const char* name : {"kept", "traced"}) {
        const auto r = test::runDarkroom({"-q", "capture", dir.file(std::string(name) + ".yaml"), "-o",
                                          dir.file(std::string(name) + ".cdb")});
        ASSERT_EQ(r.exitCode, 0) << r.err;
    }
    EXPECT_EQ(test::readText(dir.file("kept.cdb/data.csv")).substr(0, 26), "phi,theta,FILE,FILE_maxima");
    const auto info = test::runDarkroom({"info", dir.file("kept.cdb")});
    EXPECT_EQ(info.exitCode, 0) << info.err;
    const std::vector<SceneObject> maxima = generate("maxima", {});
    ASSERT_EQ(maxima.size(), 1u);
    EXPECT_THAT(info.out, HasSubstr("point list: " + std::to_string(maxima[0].vertexCount()) +
                                    " points, columns x, y, z, radius, value"));

    // The CSV holds the generator's spheres exactly (floats round-trip).
    const auto db = CinemaDatabase::open(dir.file("kept.cdb"));
    const PointList list = readPointList(db.productPath(0, "FILE_maxima"));
    ASSERT_EQ(list.size(), maxima[0].vertexCount());
    for (std::size_t i = 0; i < list.size(); ++i) {
        EXPECT_EQ(float(list.centers[i].x), maxima[0].vertices[4 * i]);
        EXPECT_EQ(float(list.centers[i].z), maxima[0].vertices[4 * i + 2]);
        EXPECT_EQ(list.radii[i], maxima[0].vertices[4 * i + 3]);
    }

    // Isosurface (kept) + Spheres from the row, composited, against the capture
    // that traced the maxima as geometry.
    Graph g(test::pluginRegistry());
    g.addNode("read", "CinemaReader");
    g.setParameter("read", "database", Value(dir.file("kept.cdb")));
    g.addNode("balls", "Spheres");
    g.setParameter("balls", "points", Value("{FILE_maxima}"));
    g.addNode("merge", "Compositing");
    g.connect({"read", "image"}, {"balls", "image"});
    g.connect({"read", "row"}, {"balls", "row"});
    g.connect({"read", "image"}, {"merge", "images"});
    g.connect({"balls", "image"}, {"merge", "images"});
    g.addNode("traced", "CinemaReader");
    g.setParameter("traced", "database", Value(dir.file("traced.cdb")));
    Evaluator ev;
    for (const char* entry : {"phi=0, theta=20", "phi=60, theta=20"}) {
        g.setParameter("read", "parameters", Value(entry));
        g.setParameter("traced", "parameters", Value(entry));
        const BufferPtr ours = ev.evaluateImage(g, "merge", "image");
        const BufferPtr embree = ev.evaluateImage(g, "traced", "image");
        int compared = 0, onSpheres = 0, grazing = 0;
        for (std::size_t i = 0; i < ours->pixelCount(); ++i) {
            const float a = ours->hostFloat("Z")[i], b = embree->hostFloat("Z")[i];
            if (std::isinf(a) != std::isinf(b) || std::fabs(a - b) > 1e-3f * b) {
                ++grazing;  // a ray grazing a silhouette, decided by single precision
                continue;
            }
            if (std::isinf(a)) continue;
            ++compared;
            onSpheres += std::isfinite(embree->hostFloat("value")[i]) ? 1 : 0;  // only the maxima carry `value`
            EXPECT_NEAR(ours->hostFloat("N.z")[i], embree->hostFloat("N.z")[i], 2e-3) << entry << " " << i;
            EXPECT_EQ(std::isfinite(ours->hostFloat("value")[i]), std::isfinite(embree->hostFloat("value")[i]));
        }
        EXPECT_GT(compared, 3000) << entry;
        EXPECT_GT(onSpheres, 50) << entry;  // many maxima lie inside the surface
        EXPECT_LE(grazing, 4) << entry;
    }
}

TEST(PointListCapture, LinesKeptAsAListKeepTheirPolylines) {
    test::TempDir dir;
    test::writeText(dir.file("lines.yaml"),
                    "objects:\n"
                    "  - generator: isosurface\n"
                    "    parameters: {resolution: 24}\n"
                    "  - generator: streamlines\n"
                    "    parameters: {count: 6}\n"
                    "    store: pointList\n"
                    "cameras:\n"
                    "  resolution: [64, 48]\n"
                    "  grid: {phi: [0], theta: [20], distance: 4.6, target: [0, 0, 0], up: [0, 0, 1]}\n");
    const auto r = test::runDarkroom({"-q", "capture", dir.file("lines.yaml"), "-o", dir.file("lines.cdb")});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const std::vector<SceneObject> lines = generate("streamlines", {{"count", "6"}});
    ASSERT_EQ(lines.size(), 1u);
    const auto db = CinemaDatabase::open(dir.file("lines.cdb"));
    const PointList list = readPointList(db.productPath(0, "FILE_streamlines"));
    ASSERT_EQ(list.size(), lines[0].vertexCount());
    const ScalarField* line = nullptr;
    for (const ScalarField& f : list.fields)
        if (f.name == "line") line = &f;
    ASSERT_NE(line, nullptr) << "no line column";
    // Every segment of the object joins two consecutive rows of one line, and
    // there are as many lines as polylines.
    for (const std::uint32_t s : lines[0].indices) EXPECT_EQ(line->values[s], line->values[s + 1]) << s;
    const float lastLine = *std::max_element(line->values.begin(), line->values.end());
    EXPECT_EQ(lastLine, 5.0f);
}
