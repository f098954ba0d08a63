// Graphs far larger than any drawn by hand: loading, connecting and
// validating stay linear-ish (a 5,000-node chain used to take over 20 s to
// validate; bench/ or docs/performance.md has the timing). Correctness only.
#include "test_filters.h"

#include <darkroom/core/evaluator.h>
#include <darkroom/core/pipeline.h>
#include <gtest/gtest.h>

#include <pthread.h>

#include <string>

using namespace darkroom;

namespace {
constexpr int kChain = 5000;

std::string chainYaml(bool reversedEdges) {
    std::string y = "darkroom: 1\nnodes:\n  n0:\n    type: TestSource\n";
    for (int i = 1; i <= kChain; ++i) y += "  n" + std::to_string(i) + ":\n    type: TestForward\n";
    y += "  sink:\n    type: TestSink\nedges:\n";
    std::vector<std::string> edges;
    for (int i = 1; i <= kChain; ++i)
        edges.push_back("  - n" + std::to_string(i - 1) + ".image -> n" + std::to_string(i) + ".image\n");
    edges.push_back("  - n" + std::to_string(kChain) + ".image -> sink.image\n");
    if (reversedEdges) std::reverse(edges.begin(), edges.end());
    for (const auto& e : edges) y += e;
    return y;
}
}  // namespace

TEST(GraphScale, FiveThousandNodeChainLoadsAndValidates) {
    for (bool reversed : {false, true}) {
        Diagnostics d;
        Graph g = parsePipeline(chainYaml(reversed), "chain.yaml", testfilters::registry(), d);
        ASSERT_TRUE(d.empty()) << d.front().str();
        ASSERT_EQ(g.nodes().size(), std::size_t(kChain + 2));
        ASSERT_EQ(g.edges().size(), std::size_t(kChain + 1));
        EXPECT_TRUE(g.validate().empty());
        const auto order = g.topologicalOrder();
        ASSERT_EQ(order.size(), g.nodes().size());
        EXPECT_EQ(order.front(), "n0");
        EXPECT_EQ(order.back(), "sink");
        EXPECT_EQ(g.edgesInto("n2500").at(0).from.node, "n2499");
        // Closing the chain into a loop is still refused, however long it is.
        g.disconnect({"n0", "image"}, {"n1", "image"});
        std::string why;
        EXPECT_FALSE(g.canConnect({"n" + std::to_string(kChain), "image"}, {"n1", "image"}, &why));
        EXPECT_NE(why.find("cycle"), std::string::npos) << why;
    }
}

TEST(GraphScale, IndexFollowsRemovalsAndRenames) {
    Graph g(testfilters::registry());
    g.addNode("a", "TestSource");
    g.addNode("b", "TestForward");
    g.addNode("c", "TestSink");
    g.connect({"a", "image"}, {"b", "image"});
    g.connect({"b", "image"}, {"c", "image"});
    g.renameNode("b", "middle");
    EXPECT_EQ(g.node("b"), nullptr);
    ASSERT_NE(g.node("middle"), nullptr);
    EXPECT_EQ(g.edgesInto("c").at(0).from.node, "middle");
    EXPECT_FALSE(g.canConnect({"c", "image"}, {"a", "image"}));  // no output on a sink, and a cycle anyway
    g.removeNode("a");
    EXPECT_TRUE(g.edgesInto("middle").empty());
    EXPECT_EQ(g.node("c")->name, "c");
    g.disconnect({"middle", "image"}, {"c", "image"});
    EXPECT_TRUE(g.edgesInto("c").empty());
    g.addNode("a", "TestSource");
    g.connect({"a", "image"}, {"middle", "image"});
    g.connect({"middle", "image"}, {"c", "image"});
    EXPECT_TRUE(g.validate().empty());
    // Renamed only through the graph (nodes are handed out const), so the
    // index follows and the edges keep their ends.
    g.renameNode("a", "source");
    ASSERT_NE(g.node("source"), nullptr);
    EXPECT_EQ(g.node("a"), nullptr);
    EXPECT_EQ(g.edgesInto("middle").at(0).from.node, "source");
}

// The evaluator walks what a target needs with a stack of its own: it used to
// recurse once per node, and `darkroom run` of a million-node chain died of a
// stack overflow (SIGSEGV). Here a 100,000-node chain is evaluated on a
// thread whose stack (1 MiB) the old recursion overflowed at this depth.
TEST(GraphScale, ChainDeeperThanTheStackEvaluates) {
    constexpr int kDeep = 100000;
    Graph g(testfilters::registry());
    g.addNode("src", "TestSource");
    std::string previous = "src";
    for (int i = 0; i < kDeep; ++i) {
        const std::string name = "f" + std::to_string(i);
        g.addNode(name, "TestForward");
        g.connect({previous, "image"}, {name, "image"});
        previous = name;
    }
    struct Job {
        const Graph* graph = nullptr;
        std::string target;
        float value = -1.0f;
        std::string error;
    } job;
    job.graph = &g;
    job.target = previous;
    auto body = [](void* p) -> void* {
        auto* j = static_cast<Job*>(p);
        try {
            Evaluator ev;
            j->value = ev.evaluateImage(*j->graph, j->target, "image")->hostFloat("value")[0];
        } catch (const std::exception& e) {
            j->error = e.what();
        }
        return nullptr;
    };
    pthread_attr_t attr;
    ASSERT_EQ(pthread_attr_init(&attr), 0);
    ASSERT_EQ(pthread_attr_setstacksize(&attr, std::size_t(1) << 20), 0);
    pthread_t thread;
    ASSERT_EQ(pthread_create(&thread, &attr, body, &job), 0);
    pthread_join(thread, nullptr);
    pthread_attr_destroy(&attr);
    EXPECT_EQ(job.error, "");
    EXPECT_FLOAT_EQ(job.value, 1.0f);  // TestSource's default value, forwarded unchanged
}
