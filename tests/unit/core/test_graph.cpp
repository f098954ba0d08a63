#include "test_filters.h"

#include <darkroom/core/graph.h>
#include <gtest/gtest.h>

#include <type_traits>
#include <utility>

using namespace darkroom;

namespace {
bool mentions(const Diagnostics& d, const std::string& node, const std::string& text) {
    for (const auto& x : d)
        if (x.node == node && x.message.find(text) != std::string::npos) return true;
    return false;
}
}  // namespace

TEST(Graph, ConnectChecksPortsAndTypes) {
    Graph g(testfilters::registry());
    g.addNode("src", "TestSource");
    g.addNode("num", "TestNumber");
    g.addNode("add", "TestAdd");
    std::string why;
    EXPECT_FALSE(g.canConnect({"src", "nope"}, {"add", "a"}, &why));
    EXPECT_NE(why.find("has no output 'nope'"), std::string::npos) << why;
    EXPECT_FALSE(g.canConnect({"src", "image"}, {"add", "nope"}, &why));
    EXPECT_NE(why.find("has no input 'nope'"), std::string::npos) << why;
    EXPECT_FALSE(g.canConnect({"num", "value"}, {"add", "a"}, &why));
    EXPECT_NE(why.find("types differ"), std::string::npos) << why;
    EXPECT_TRUE(g.canConnect({"num", "value"}, {"add", "offset"}));
    g.connect({"src", "image"}, {"add", "a"});
    EXPECT_FALSE(g.canConnect({"src", "image"}, {"add", "a"}, &why));
    EXPECT_THROW(g.connect({"src", "image"}, {"add", "a"}), Error);
}

TEST(Graph, RefusesCycles) {
    Graph g(testfilters::registry());
    g.addNode("a", "TestNoise");
    g.addNode("b", "TestNoise");
    g.connect({"a", "image"}, {"b", "image"});
    std::string why;
    EXPECT_FALSE(g.canConnect({"b", "image"}, {"a", "image"}, &why));
    EXPECT_NE(why.find("cycle"), std::string::npos) << why;
    // A cycle that slipped in unchecked (e.g. from a file) is caught by validate().
    g.addEdgeUnchecked({{"b", "image"}, {"a", "image"}});
    const Diagnostics d = g.validate();
    bool found = false;
    for (const auto& x : d) found |= x.message.find("cycle in the graph") != std::string::npos;
    EXPECT_TRUE(found);
    EXPECT_THROW(g.topologicalOrder(), Error);
}

TEST(Graph, WalksUpstreamAndDownstreamThroughEdgesOnly) {
    // a -> b -> d, c -> d, e alone; a name with no node is ignored.
    Graph g(testfilters::registry());
    for (const char* n : {"a", "b", "c", "d", "e"}) g.addNode(n, "TestNoise");
    g.addNode("sum", "TestAdd");
    g.connect({"a", "image"}, {"b", "image"});
    g.connect({"b", "image"}, {"sum", "a"});
    g.connect({"c", "image"}, {"sum", "b"});
    g.connect({"sum", "image"}, {"d", "image"});
    using Names = std::set<std::string>;
    EXPECT_EQ(g.upstreamOf({"d"}), (Names{"a", "b", "c", "d", "sum"}));
    EXPECT_EQ(g.upstreamOf({"b", "e", "missing"}), (Names{"a", "b", "e"}));
    EXPECT_EQ(g.downstreamOf({"a"}), (Names{"a", "b", "d", "sum"}));
    EXPECT_EQ(g.downstreamOf({"c", "e"}), (Names{"c", "d", "e", "sum"}));
    // A cycle that slipped in unchecked ends the walk rather than looping.
    g.addEdgeUnchecked({{"d", "image"}, {"a", "image"}});
    EXPECT_EQ(g.downstreamOf({"b"}), (Names{"a", "b", "d", "sum"}));
}

TEST(Graph, ValidateReportsMissingInputsAndUnknownTypes) {
    Graph g(testfilters::registry());
    g.addNode("add", "TestAdd");
    g.addPlaceholder("mystery", "NotAType");
    const Diagnostics d = g.validate();
    EXPECT_TRUE(mentions(d, "add", "required input 'a'"));
    EXPECT_TRUE(mentions(d, "add", "required input 'b'"));
    EXPECT_TRUE(mentions(d, "mystery", "unknown type 'NotAType'"));
}

TEST(Graph, ValidateReportsTypeMismatchAddedUnchecked) {
    Graph g(testfilters::registry());
    g.addNode("num", "TestNumber");
    g.addNode("sink", "TestSink");
    g.addEdgeUnchecked({{"num", "value"}, {"sink", "image"}});
    EXPECT_TRUE(mentions(g.validate(), "sink", "cannot take num.value"));
}

TEST(Graph, ParametersAreCheckedAgainstPorts) {
    Graph g(testfilters::registry());
    g.addNode("src", "TestSource");
    EXPECT_THROW(g.setParameter("src", "width", Value(0)), Error);  // below range
    EXPECT_THROW(g.setParameter("src", "width", Value(2.5)), Error);  // not an int
    EXPECT_THROW(g.setParameter("src", "nope", Value(1)), Error);
    EXPECT_THROW(g.addNode("src", "TestSource"), Error);  // duplicate name
    EXPECT_THROW(g.addNode("x", "NotAType"), Error);
    g.setParameter("src", "value", Value(2));  // ints widen to float ports
    EXPECT_DOUBLE_EQ(g.node("src")->parameter("value")->asFloat(), 2.0);
}

TEST(Graph, ChangesOfWhatRunsBumpTheRevisionAndNothingElseDoes) {
    Graph g(testfilters::registry());
    g.addNode("src", "TestSource");
    g.addNode("noise", "TestNoise");
    g.connect({"src", "image"}, {"noise", "image"});
    const auto before = g.revision();
    g.setParameter("noise", "seed", Value(3));
    const auto changed = g.revision();
    EXPECT_GT(changed, before);
    g.setParameter("noise", "seed", Value(3));  // same value: no change
    EXPECT_EQ(g.revision(), changed);
    // Layout and source positions are not part of what runs.
    g.setExtra("noise", "ui", "{position: [1, 2]}");
    g.setSourceLocation("noise", 4, 3);
    EXPECT_EQ(g.revision(), changed);
    EXPECT_EQ(g.node("noise")->extras.at(0).second, "{position: [1, 2]}");
    EXPECT_EQ(g.node("noise")->line, 4);
    g.setExtra("noise", "ui", "{position: [5, 6]}");  // replaced in place
    ASSERT_EQ(g.node("noise")->extras.size(), 1u);
    EXPECT_EQ(g.node("noise")->extras.at(0).second, "{position: [5, 6]}");
    g.setExtra("noise", "ui", "");  // removed
    EXPECT_TRUE(g.node("noise")->extras.empty());
    EXPECT_THROW(g.setExtra("nowhere", "ui", "x"), Error);
    EXPECT_THROW(g.setRawParameter("noise", "seed", "3"), Error);  // not a placeholder
}

// Nodes are read-only outside the graph: every change goes through a
// mutator, so the name index and the edges cannot be bypassed.
static_assert(std::is_same_v<decltype(std::declval<Graph&>().node("x")), const Node*>);
static_assert(std::is_same_v<decltype(std::declval<Graph&>().addNode("x", "y")), const Node&>);

TEST(Graph, ACopiedNodeKeepsItsParametersExtrasAndPosition) {
    Graph a(testfilters::registry());
    a.addNode("noise", "TestNoise");
    a.setParameter("noise", "seed", Value(7));
    a.setExtra("noise", "ui", "{position: [1, 2]}");
    a.setSourceLocation("noise", 3, 5);
    a.addPlaceholder("later", "FromAPluginNotLoaded");
    a.setRawParameter("later", "strength", "0.5");
    Graph b(testfilters::registry());
    for (const Node& n : a.nodes()) b.addCopy(n);
    EXPECT_EQ(b.node("noise")->parameter("seed")->asInt(), 7);
    EXPECT_EQ(b.node("noise")->extras, a.node("noise")->extras);
    EXPECT_EQ(b.node("noise")->line, 3);
    EXPECT_TRUE(b.node("later")->placeholder);
    EXPECT_EQ(b.node("later")->rawParameters.at("strength"), "0.5");
    EXPECT_THROW(b.addCopy(*a.node("noise")), Error);  // the name is taken
}

TEST(Graph, RemoveNodeDropsItsEdges) {
    Graph g(testfilters::registry());
    g.addNode("src", "TestSource");
    g.addNode("sink", "TestSink");
    g.connect({"src", "image"}, {"sink", "image"});
    g.removeNode("src");
    EXPECT_TRUE(g.edges().empty());
    EXPECT_EQ(g.sinks(), std::vector<std::string>{"sink"});
    EXPECT_TRUE(mentions(g.validate(), "sink", "required input 'image'"));
}
