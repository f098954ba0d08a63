// The batch-shading workflow called directly, without the runner: a
// database shaded entry by entry into another, what a resume skips, what is
// refused before any shading, how a failing entry is reported. (Over
// processes it is tested through mpirun: mpi/tests/foreach_over_ranks_test.cpp
// and cinema_writer_over_ranks_test.cpp.)
#include "test_support.h"
#include "time_series_database.h"

#include <darkroom/error.h>
#include <darkroom/core/pipeline.h>
#include <darkroom/data/cinema/database.h>
#include <darkroom/workflows/batch.h>
#include <darkroom/workflows/pipeline_record.h>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <atomic>
#include <filesystem>

using namespace darkroom;
using ::testing::HasSubstr;
namespace fs = std::filesystem;

namespace {

const char* kPipeline = R"(darkroom: 1
nodes:
  read:
    type: CinemaReader
    parameters: {database: source.cdb}
  write:
    type: CinemaWriter
    parameters: {database: shaded.cdb, format: exr}
edges:
  - read.image -> write.image
  - read.row -> write.row
)";

struct Batch {
    test::TempDir dir;
    Graph graph = loadShading();
    EvaluatorOptions options;
    Batch() {
        test::writeTimeSeriesDatabase(dir.file("source.cdb"), {1.0, 2.0, 3.0});
        options.inputBase = dir.path();
        options.outputDir = dir.file("out");
        options.retainIntermediate = true;
    }
    static Graph loadShading() {
        Diagnostics d;
        Graph g = parsePipeline(kPipeline, "shade.yaml", test::pluginRegistry(), d);
        workflows::describeUpstreamPipelines(g);
        return g;
    }
    workflows::BatchSummary shade(workflows::BatchSettings s = {}, const workflows::BatchCallbacks& cb = {}) {
        if (s.reader.empty()) s.reader = "read";
        Evaluator ev(options);
        SingleProcess alone;
        return workflows::shadeEntries(graph, ev, options, s, alone, cb);
    }
};

}  // namespace

TEST(BatchWorkflow, ShadesEveryEntryIntoTheDatabaseAndWritesTheIndex) {
    Batch b;
    workflows::BatchSettings s;
    s.index = b.dir.file("out/index.csv");
    const auto summary = b.shade(s);
    ASSERT_FALSE(summary.failure);
    EXPECT_EQ(summary.selected, 3u);
    EXPECT_EQ(summary.kept, 0u);
    EXPECT_EQ(summary.shadedPerProcess, (std::vector<std::size_t>{3}));
    EXPECT_EQ(CinemaDatabase::open(b.dir.file("out/shaded.cdb")).rowCount(), 3u);
    EXPECT_EQ(test::readText(b.dir.file("out/index.csv")),
              "time,FILE\n1,shaded.cdb/time=1.exr\n2,shaded.cdb/time=2.exr\n3,shaded.cdb/time=3.exr\n");
    // The batch's edits of the graph (each entry's row number) are undone.
    EXPECT_EQ(b.graph.node("read")->parameter("entry"), nullptr);
    EXPECT_EQ(b.graph.node("read")->parameter("parameters"), nullptr);
}

TEST(BatchWorkflow, AResumeShadesOnlyWhatTheDatabaseLacks) {
    Batch b;
    ASSERT_FALSE(b.shade().failure);
    fs::remove(b.dir.file("out/shaded.cdb/time=2.exr"));
    b.graph.setParameter("write", "mode", Value(std::string("resume")));
    workflows::BatchSettings s;
    s.resume = true;
    const auto summary = b.shade(s);
    ASSERT_FALSE(summary.failure);
    EXPECT_EQ(summary.kept, 2u);
    EXPECT_EQ(summary.shadedPerProcess, (std::vector<std::size_t>{1}));
    EXPECT_TRUE(fs::is_regular_file(b.dir.file("out/shaded.cdb/time=2.exr")));
}

TEST(BatchWorkflow, WhatIsRefusedIsAnInputErrorBeforeAnyShading) {
    Batch b;
    workflows::BatchSettings s;
    s.where = "time > 5";
    EXPECT_THROW(b.shade(s), InputError);
    s.where.clear();
    s.reader = "write";  // not an entry reader: it has no row output
    try {
        b.shade(s);
        FAIL() << "a writer was taken for a reader";
    } catch (const InputError& e) {
        EXPECT_THAT(e.what(), HasSubstr("expected the name of a node that reads a database entry by entry"));
    }
    // The database written over the one read (D1 of issue 26).
    b.graph.setParameter("write", "database", Value(b.dir.file("source.cdb")));
    try {
        b.shade();
        FAIL() << "not refused";
    } catch (const InputError& e) {
        EXPECT_THAT(e.what(), HasSubstr("writing there would destroy the input"));
    }
    EXPECT_EQ(CinemaDatabase::open(b.dir.file("source.cdb")).rowCount(), 3u);
    EXPECT_FALSE(fs::exists(b.dir.file("out/shaded.cdb")));
}

// The reader is driven by its row number, which overrides a choice by
// values the pipeline was saved with (the editor's browser writes one);
// the nodes fed its row see each entry's typed row.
TEST(BatchWorkflow, TheReaderGetsEachEntrysRowNumberOverItsParameters) {
    Batch b;
    b.graph.setParameter("read", "parameters", Value(std::string("time=2")));
    ASSERT_FALSE(b.shade().failure);
    const CinemaDatabase out = CinemaDatabase::open(b.dir.file("out/shaded.cdb"));
    ASSERT_EQ(out.rowCount(), 3u);
    for (std::size_t r = 0; r < 3; ++r) EXPECT_EQ(out.cell(r, out.column("time")), std::to_string(r + 1));
    EXPECT_EQ(b.graph.node("read")->parameter("parameters")->asString(), "time=2");  // left as it was
}

TEST(BatchWorkflow, AFailingEntryIsReportedWithTheEntryAndTheRestIsKept) {
    for (const int inFlight : {1, 3}) {
        SCOPED_TRACE("entries in flight: " + std::to_string(inFlight));
        Batch b;
        test::writeText(b.dir.file("source.cdb/time=2.exr"), "not an image");
        workflows::BatchSettings s;
        s.inFlight = inFlight;
        const auto summary = b.shade(s);
        ASSERT_TRUE(summary.failure);
        EXPECT_FALSE(summary.failedElsewhere);
        try {
            std::rethrow_exception(summary.failure);
        } catch (const Error& e) {
            EXPECT_THAT(e.what(), HasSubstr("entry time=2: "));
        }
        // The entry before it is in the database (entries in flight beside it
        // may be too, and their staging is merged); a resume completes it.
        const CinemaDatabase out = CinemaDatabase::open(b.dir.file("out/shaded.cdb"));
        EXPECT_TRUE(fs::is_regular_file(b.dir.file("out/shaded.cdb/time=1.exr")));
        EXPECT_FALSE(fs::exists(b.dir.file("out/shaded.cdb/time=2.exr")));
        EXPECT_FALSE(fs::exists(b.dir.file("out/shaded.cdb.staging")));
        if (inFlight == 1) {
            EXPECT_EQ(out.rowCount(), 1u);
        }
    }
}

// With entries in flight, the progress is every finished entry and each
// lane's part of the one it shades: it never goes back, and the callbacks
// come one at a time.
TEST(BatchWorkflow, ProgressWithEntriesInFlightNeverGoesBack) {
    Batch b;
    fs::remove_all(b.dir.file("source.cdb"));
    test::writeTimeSeriesDatabase(b.dir.file("source.cdb"), {1, 2, 3, 4, 5, 6, 7, 8, 9});
    std::vector<double> seen;
    std::atomic<int> inside{0};
    bool overlapped = false;
    workflows::BatchCallbacks cb;
    cb.progress = [&](double f, const std::string&) {
        overlapped = overlapped || inside.fetch_add(1) != 0;
        seen.push_back(f);
        inside.fetch_sub(1);
    };
    workflows::BatchSettings s;
    s.inFlight = 3;
    const auto summary = b.shade(s, cb);
    ASSERT_FALSE(summary.failure);
    EXPECT_EQ(summary.inFlight, 3);
    EXPECT_EQ(CinemaDatabase::open(b.dir.file("out/shaded.cdb")).rowCount(), 9u);
    ASSERT_FALSE(seen.empty());
    EXPECT_FALSE(overlapped);
    for (std::size_t k = 1; k < seen.size(); ++k) EXPECT_GE(seen[k], seen[k - 1]) << "at call " << k;
    EXPECT_LE(seen.back(), 1.0);
}
