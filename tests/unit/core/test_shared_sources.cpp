// Sources shared between evaluators (the editor's full-resolution and
// preview evaluators): a node that reads no image runs once for both; a
// changed value or file runs it again; the share holds images weakly, so it
// keeps nothing alive that no evaluator's cache holds; nodes that read
// images are never shared; two evaluators on two threads agree.
#include "test_filters.h"
#include "test_support.h"

#include <darkroom/core/evaluator.h>
#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <thread>

using namespace darkroom;

namespace {

// two -> double
Graph sourceAndReader() {
    Graph g(testfilters::registry());
    g.addNode("two", "TestTwoPlanes");
    g.addNode("double", "TestDoubleA");
    g.connect({"two", "image"}, {"double", "image"});
    return g;
}

EvaluatorOptions sharing(const std::shared_ptr<SharedSources>& shared) {
    EvaluatorOptions o;
    o.sharedSources = shared;
    return o;
}

}  // namespace

TEST(SharedSources, ASourceRunsOnceForTwoEvaluators) {
    const auto shared = std::make_shared<SharedSources>();
    Evaluator a(sharing(shared)), b(sharing(shared));
    const Graph g = sourceAndReader();
    const BufferPtr fromA = a.evaluateImage(g, "two", "image");
    EXPECT_EQ(b.wouldRun(g, {"double"}), std::set<std::string>{"double"});  // "two" comes from the share
    const BufferPtr fromB = b.evaluateImage(g, "double", "image");
    EXPECT_EQ(a.executions("two"), 1u);
    EXPECT_EQ(b.executions("two"), 0u);
    EXPECT_EQ(fromB->plane("a"), fromA->plane("a"));  // the same planes, not a copy
    EXPECT_EQ(b.executions("double"), 1u);            // what reads an image runs in each
    EXPECT_EQ(shared->hits(), 1u);
    // The other way round: b's own cache now holds it, a's too.
    b.evaluateImage(g, "two", "image");
    EXPECT_EQ(shared->hits(), 1u);
}

TEST(SharedSources, AChangedValueOrFileRunsTheSourceAgain) {
    test::TempDir dir;
    const std::string file = dir.file("number.txt");
    test::writeText(file, "1.5");
    Graph g(testfilters::registry());
    g.addNode("read", "TestFileNumber");
    g.setParameter("read", "path", Value(file));
    const auto shared = std::make_shared<SharedSources>();
    Evaluator a(sharing(shared)), b(sharing(shared));
    a.evaluateImage(g, "read", "image");
    EXPECT_FLOAT_EQ(b.evaluateImage(g, "read", "image")->requireFloat("value")[0], 1.5f);
    EXPECT_EQ(b.executions("read"), 0u);

    test::writeText(file, "3.25");
    std::filesystem::last_write_time(file, std::filesystem::last_write_time(file) + std::chrono::seconds(2));
    EXPECT_FLOAT_EQ(b.evaluateImage(g, "read", "image")->requireFloat("value")[0], 3.25f);
    EXPECT_EQ(b.executions("read"), 1u);  // the stale entry was not used
    EXPECT_FLOAT_EQ(a.evaluateImage(g, "read", "image")->requireFloat("value")[0], 3.25f);
    EXPECT_EQ(a.executions("read"), 1u);  // b's fresh result, shared

    Graph other = sourceAndReader();
    a.evaluateImage(other, "two", "image");
    other.setParameter("two", "a", Value(7.0));
    EXPECT_FLOAT_EQ(b.evaluateImage(other, "two", "image")->requireFloat("a")[0], 7.0f);
    EXPECT_EQ(b.executions("two"), 1u);
}

TEST(SharedSources, TheShareKeepsNothingAlive) {
    const auto shared = std::make_shared<SharedSources>();
    const Graph g = sourceAndReader();
    std::weak_ptr<const Buffer> seen;
    {
        Evaluator a(sharing(shared));
        seen = a.evaluateImage(g, "two", "image");
        EXPECT_EQ(shared->liveEntries(), 1u);
    }
    EXPECT_TRUE(seen.expired());  // the evaluator's cache was the only holder
    EXPECT_EQ(shared->liveEntries(), 0u);
    Evaluator b(sharing(shared));
    b.evaluateImage(g, "two", "image");
    EXPECT_EQ(b.executions("two"), 1u);  // nothing to take: it ran
}

TEST(SharedSources, TwoThreadsAgree) {
    const auto shared = std::make_shared<SharedSources>();
    Evaluator a(sharing(shared)), b(sharing(shared));
    Graph ga = sourceAndReader(), gb = sourceAndReader();
    for (int i = 0; i < 50; ++i) {
        ga.setParameter("two", "a", Value(double(i % 5)));
        gb.setParameter("two", "a", Value(double(i % 5)));
        BufferPtr ra, rb;
        std::thread ta([&] { ra = a.evaluateImage(ga, "double", "image"); });
        std::thread tb([&] { rb = b.evaluateImage(gb, "double", "image"); });
        ta.join();
        tb.join();
        EXPECT_FLOAT_EQ(ra->requireFloat("c")[0], 2.0f * float(i % 5));
        EXPECT_FLOAT_EQ(rb->requireFloat("c")[0], 2.0f * float(i % 5));
    }
    // Five distinct keys: whichever ran first, the other mostly took its result.
    EXPECT_LE(a.executions("two") + b.executions("two"), 100u);
}
