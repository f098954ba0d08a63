// CinemaWriter (the node) in a graph with a CinemaReader: every entry of a
// database shaded into a new one that reads back with the same parameters,
// PNG and EXR products, resume keeps complete entries, the lock keeps a
// second writer out, clear errors.
#include "test_support.h"

#include <darkroom/error.h>
#include <darkroom/data/cinema/database.h>
#include <darkroom/data/cinema/writer.h>
#include <darkroom/core/evaluator.h>
#include <darkroom/core/graph.h>
#include <darkroom/data/image_io.h>
#include <darkroom/core/run_filter.h>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <functional>

#include <sys/stat.h>

using namespace darkroom;
using ::testing::HasSubstr;
namespace fs = std::filesystem;

namespace {

// A source database: time x phi, each entry a constant grey of value time/10.
std::string sourceDatabase(const test::TempDir& dir) {
    const std::string path = dir.file("source.cdb");
    CinemaWriter w(path, {"time", "phi"});
    for (double t : {0.5, 1.5, 2.5})
        for (double phi : {-30.0, 30.0}) {
            auto img = test::makeImage(6, 4, {"Z", "R", "G", "B"}, [=](int x, int, int c) {
                return c == 0 ? 2.0f + 0.1f * float(x) : float(t) / 10.0f;
            });
            w.addEntry({{"time", CinemaValue(t)}, {"phi", CinemaValue(phi)}}, *img);
        }
    w.finish();
    return path;
}

struct Pipeline {
    Graph graph{test::pluginRegistry()};
    Pipeline(const std::string& source, const std::string& target, const std::string& format) {
        graph.addNode("read", "CinemaReader");
        graph.setParameter("read", "database", Value(source));
        graph.addNode("write", "CinemaWriter");
        graph.setParameter("write", "database", Value(target));
        graph.setParameter("write", "format", Value(format));
        graph.connect({"read", "image"}, {"write", "image"});
        graph.connect({"read", "row"}, {"write", "row"});
    }
    // What `darkroom run --foreach` does: one evaluation per source row, all
    // in one sequence; `beforeTheEnd` looks at the files before it ends.
    void foreachRow(Evaluator& ev, const std::string& source, std::size_t limit = 1000,
                    const std::function<void()>& beforeTheEnd = {}) {
        const auto db = CinemaDatabase::open(source);
        EvaluatorSequence sequence(ev, SequenceInfo{std::min(limit, db.rowCount())});
        for (std::size_t r = 0; r < db.rowCount() && r < limit; ++r) {
            graph.setParameter("read", "parameters", Value(db.formatParameters(r)));
            ev.run(graph);
        }
        if (beforeTheEnd) beforeTheEnd();
        sequence.end();
    }
};

}  // namespace

TEST(CinemaWriterNode, ShadesADatabaseIntoANewOneWithTheSameEntries) {
    test::TempDir dir;
    const std::string source = sourceDatabase(dir);
    for (const std::string format : {"png", "exr"}) {
        const std::string target = dir.file("shaded-" + format + ".cdb");
        Pipeline p(source, target, format);
        Evaluator ev;
        p.foreachRow(ev, source, 1000, [&] {
            // Locked while the sequence holds it.
            EXPECT_TRUE(fs::exists(target + "/.lock"));
            try {
                CinemaWriter intruder(target, {"time", "phi"}, CinemaWriterOptions{false, true, {}, ".png", {}, {}});
                ADD_FAILURE() << "a second writer got in";
            } catch (const Error& e) {
                EXPECT_THAT(e.what(), HasSubstr("being written by another process"));
            }
        });
        // The sequence ended: the lock is released though the node and its
        // evaluator live on (the editor, idle).
        EXPECT_FALSE(fs::exists(target + "/.lock"));
        const auto in = CinemaDatabase::open(source);
        const auto out = CinemaDatabase::open(target);
        ASSERT_EQ(out.rowCount(), in.rowCount());
        EXPECT_EQ(test::readText(target + "/data.csv").substr(0, 15), "time,phi,FILE\n0");
        for (std::size_t r = 0; r < in.rowCount(); ++r) {
            const auto match = out.find(in.formatParameters(r));
            EXPECT_TRUE(match.notes.empty());
            EXPECT_EQ(out.formatParameters(match.row), in.formatParameters(r));
            const auto image = readImage(out.productPath(match.row));
            const float want = float(in.number(r, in.column("time"))) / 10.0f;
            if (format == "png") {
                EXPECT_EQ(image->channelNames(), (std::vector<std::string>{"R", "G", "B"}));
                EXPECT_NEAR(image->hostFloat("G")[0], want, 0.004f);
            } else {
                EXPECT_EQ(image->hostFloat("G")[0], want);
                EXPECT_TRUE(image->hasChannel("Z"));
                EXPECT_FALSE(image->hasChannel("FILE"));
            }
        }
        // darkroom info's description reads every product without complaint.
        const auto d = out.describe();
        EXPECT_TRUE(d.warnings.empty());
        ASSERT_EQ(d.products.size(), 1u);
        EXPECT_EQ(d.products[0].width, 6);
        EXPECT_TRUE(d.products[0].error.empty());
    }
}

TEST(CinemaWriterNode, ResumeCompletesAnInterruptedRunAndCreateRefusesIt) {
    test::TempDir dir;
    const std::string source = sourceDatabase(dir);
    const std::string target = dir.file("shaded.cdb");
    {
        Pipeline p(source, target, "png");
        Evaluator ev;
        p.foreachRow(ev, source, 2);  // "interrupted" after two entries
    }
    const auto firstBytes = test::readText(target + "/time=0.5_phi=-30.png");
    const auto firstTime = fs::last_write_time(target + "/time=0.5_phi=-30.png");
    {
        Pipeline p(source, target, "png");
        Evaluator ev;
        try {
            p.foreachRow(ev, source);
            ADD_FAILURE() << "create over an existing database should fail";
        } catch (const Error& e) {
            EXPECT_THAT(e.what(), HasSubstr("already exists and is not empty"));
        }
    }
    {
        Pipeline p(source, target, "png");
        p.graph.setParameter("write", "mode", Value("resume"));
        Evaluator ev;
        p.foreachRow(ev, source);
    }
    EXPECT_EQ(CinemaDatabase::open(target).rowCount(), 6u);
    // The entries kept by the resume were not written again.
    EXPECT_EQ(fs::last_write_time(target + "/time=0.5_phi=-30.png"), firstTime);
    EXPECT_EQ(test::readText(target + "/time=0.5_phi=-30.png"), firstBytes);
}

TEST(CinemaWriterNode, ErrorsAreClear) {
    test::TempDir dir;
    auto writer = test::pluginRegistry().createFilter("CinemaWriter");
    const BufferPtr img = test::makeImage(2, 2, {"R", "G", "B"}, [](int, int, int) { return 0.5f; });
    auto message = [&](std::map<std::string, std::vector<Value>> in) {
        in["image"] = {Value(img)};
        try {
            runFilter(*writer, in);
        } catch (const Error& e) {
            return std::string(e.what());
        }
        return std::string("no error");
    };
    EXPECT_THAT(message({{"database", {Value(dir.file("a.cdb"))}}}), HasSubstr("'row' is empty"));
    EXPECT_THAT(message({{"row", {Value("phi=1")}}}), HasSubstr("no database given"));
    EXPECT_THAT(message({{"row", {Value("FILE=x.png")}}, {"database", {Value(dir.file("b.cdb"))}}}),
                HasSubstr("has no parameter columns"));
    EXPECT_EQ(message({{"row", {Value("phi=1")}}, {"database", {Value(dir.file("c.cdb"))}}}), "no error");
}

TEST(CinemaWriterNode, RowsOfAnotherKindAreRefusedWithinASequence) {
    test::TempDir dir;
    Pipeline p(sourceDatabase(dir), dir.file("c.cdb"), "png");
    p.graph.disconnect({"read", "row"}, {"write", "row"});
    Evaluator ev;
    EvaluatorSequence sequence(ev);
    p.graph.setParameter("write", "row", Value("phi=1"));
    ev.run(p.graph);
    p.graph.setParameter("write", "row", Value("theta=1"));
    try {
        ev.run(p.graph);
        ADD_FAILURE() << "a row with other columns was written into the database";
    } catch (const Error& e) {
        EXPECT_THAT(e.what(), HasSubstr("the columns theta but the database " + dir.file("c.cdb") +
                                            " was started with phi"));
    }
}

TEST(CinemaWriterNode, BetweenEvaluationsOutsideASequenceNoLockIsHeld) {
    // The editor evaluates without a sequence of its own: each evaluation is
    // one. After an edit the entry this node wrote is written again, even in
    // mode resume (which keeps only what earlier runs wrote).
    test::TempDir dir;
    const std::string source = sourceDatabase(dir), target = dir.file("shaded.cdb");
    Pipeline p(source, target, "png");
    p.graph.setParameter("write", "mode", Value("resume"));
    p.graph.setParameter("read", "parameters", Value(CinemaDatabase::open(source).formatParameters(0)));
    p.graph.addNode("resize", "Resize");
    p.graph.disconnect({"read", "image"}, {"write", "image"});
    p.graph.connect({"read", "image"}, {"resize", "image"});
    p.graph.connect({"resize", "image"}, {"write", "image"});
    Evaluator ev;
    ev.run(p.graph);
    EXPECT_FALSE(fs::exists(target + "/.lock"));
    const auto db = CinemaDatabase::open(target);
    ASSERT_EQ(db.rowCount(), 1u);
    const std::string product = db.productPath(0);
    struct stat first {};
    ASSERT_EQ(::stat(product.c_str(), &first), 0);
    p.graph.setParameter("resize", "scale", Value(2.0));  // an edit upstream: the writer runs again
    ev.run(p.graph);
    EXPECT_FALSE(fs::exists(target + "/.lock"));
    ASSERT_EQ(ev.executions("write"), 2u);
    struct stat second {};
    ASSERT_EQ(::stat(product.c_str(), &second), 0);
    EXPECT_NE(first.st_ino, second.st_ino) << "the entry was kept, not written again";
    EXPECT_EQ(CinemaDatabase::open(target).rowCount(), 1u);
}
