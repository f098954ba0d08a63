// Graphs far larger than any drawn by hand: loading, connecting and
// validating stay linear-ish (a 5,000-node chain used to take over 20 s to
// validate; bench/ or docs/performance.md has the timing). Correctness only.
#include "test_filters.h"

#include <darkroom/framework/pipeline.h>
#include <gtest/gtest.h>

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
    // A node renamed through the pointer node() returns is still found.
    g.node("a")->name = "source";
    ASSERT_NE(g.node("source"), nullptr);
}
