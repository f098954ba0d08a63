#include "test_filters.h"
#include "test_support.h"

#include <darkroom/core/pipeline.h>
#include <gtest/gtest.h>

using namespace darkroom;

namespace {
const char* kCanonical = R"(darkroom: 1
nodes:
  src:
    type: TestSource
    parameters:
      width: 8
      value: 0.25
  other:
    type: TestSource
  add:
    type: TestAdd
    parameters:
      offset: -1.5e-07
    ui: {position: [120, 40]}
  mystery:
    type: FutureFilter
    parameters:
      colour: [1, 0, 0]
      mode: "yes"
  sink:
    type: TestSink
edges:
  - src.image -> add.a
  - other.image -> add.b
  - add.image -> sink.image
  - add.image -> mystery.input
)";

Graph parse(const std::string& text, Diagnostics& d) {
    return parsePipeline(text, "test.yaml", testfilters::registry(), d);
}

std::string firstError(const Diagnostics& d) {
    for (const auto& x : d)
        if (x.severity == Diagnostic::Severity::Error) return x.str();
    return "";
}
}  // namespace

TEST(PipelineYaml, CanonicalTextRoundTripsByteForByte) {
    Diagnostics d;
    Graph g = parse(kCanonical, d);
    EXPECT_FALSE(hasErrors(d)) << firstError(d);
    ASSERT_EQ(d.size(), 1u) << "one warning for the unknown type";
    EXPECT_NE(d[0].message.find("FutureFilter"), std::string::npos);
    EXPECT_EQ(serializePipeline(g), kCanonical);
}

TEST(PipelineYaml, UnknownTypesArePlaceholdersNotDropped) {
    Diagnostics d;
    Graph g = parse(kCanonical, d);
    const Node* m = g.node("mystery");
    ASSERT_NE(m, nullptr);
    EXPECT_TRUE(m->placeholder);
    EXPECT_EQ(m->type, "FutureFilter");
    EXPECT_EQ(g.edges().size(), 4u);
    EXPECT_EQ(d[0].where, "test.yaml:16:11");
}

TEST(PipelineYaml, SaveLoadReproducesTheGraph) {
    Graph g(testfilters::registry());
    g.addNode("a", "TestSource");
    g.addNode("n", "TestNumber");
    g.addNode("b", "TestAdd");
    g.setParameter("a", "value", Value(1.0 / 3.0));
    g.setParameter("n", "x", Value(-0.0));
    g.connect({"a", "image"}, {"b", "a"});
    g.connect({"a", "image"}, {"b", "b"});
    g.connect({"n", "value"}, {"b", "offset"});
    test::TempDir dir;
    savePipeline(g, dir.file("p.yaml"));
    Diagnostics d;
    Graph back = loadPipeline(dir.file("p.yaml"), testfilters::registry(), d);
    EXPECT_TRUE(d.empty()) << firstError(d);
    EXPECT_EQ(back.node("a")->parameter("value")->asFloat(), 1.0 / 3.0);
    EXPECT_TRUE(std::signbit(back.node("n")->parameter("x")->asFloat()));
    EXPECT_EQ(back.edges(), g.edges());
    EXPECT_EQ(serializePipeline(back), serializePipeline(g));
}

TEST(PipelineYaml, StringsThatLookLikeOtherTypesAreQuoted) {
    Registry r;
    r.registerBuiltin("strings", [](Registrar& reg) {
        struct S final : Filter {
            PortList ports() const override {
                PortList p;
                p.stringIn("s", "", "text");
                return p;
            }
            void execute(Context&) override {}
        };
        reg.addFilter<S>("Strings", "Test", "");
    });
    for (const std::string s : {"true", "1.5", "", " lead", "a: b", "#x", "null", "it's \"q\"", "1e3", "-"}) {
        Graph g(r);
        g.addNode("n", "Strings");
        g.setParameter("n", "s", Value(s));
        Diagnostics d;
        Graph back = parsePipeline(serializePipeline(g), "t", r, d);
        ASSERT_FALSE(hasErrors(d)) << s << ": " << firstError(d);
        EXPECT_EQ(back.node("n")->parameter("s")->asString(), s);
    }
}

TEST(PipelineYaml, MalformedYamlNamesLineAndColumn) {
    Diagnostics d;
    parse("darkroom: 1\nnodes:\n  a:\n    type: [TestSource\n", d);
    ASSERT_TRUE(hasErrors(d));
    EXPECT_EQ(firstError(d).rfind("test.yaml:", 0), 0u) << firstError(d);
    EXPECT_NE(firstError(d).find("malformed YAML"), std::string::npos);
}

TEST(PipelineYaml, ErrorsPointAtTheOffendingValue) {
    struct Case {
        std::string text;
        std::string where;
        std::string what;
    };
    const std::vector<Case> cases = {
        {"darkroom: 1\nnodes:\n  a:\n    type: TestSource\n    parameters:\n      width: wide\n", "test.yaml:6:14",
         "expected an integer"},
        {"darkroom: 1\nnodes:\n  a:\n    type: TestSource\n    parameters:\n      width: 0\n", "test.yaml:6:14",
         "outside the allowed range"},
        {"darkroom: 1\nnodes:\n  a:\n    type: TestSource\n    parameters:\n      colour: 1\n", "test.yaml:6:7",
         "has no parameter 'colour'"},
        {"darkroom: 1\nnodes:\n  a:\n    type: TestSource\nedges:\n  - a.image -> b.image\n", "test.yaml:6:5",
         "does not exist"},
        {"darkroom: 1\nnodes:\n  a:\n    type: TestSource\n  b:\n    type: TestSink\nedges:\n  - a.image => b.image\n",
         "test.yaml:8:5", "expected 'node.port -> node.port'"},
        {"nodes: {}\n", "test.yaml:1:1", "missing the format version"},
        {"darkroom: 7\nnodes: {}\n", "test.yaml:1:11", "newer than this Darkroom supports"},
        {"darkroom: 1\nnodes:\n  a:\n    parameters: {}\n", "test.yaml:4:5", "needs a 'type'"},
    };
    for (const auto& c : cases) {
        Diagnostics d;
        parse(c.text, d);
        const std::string e = firstError(d);
        EXPECT_EQ(e.rfind(c.where + ": error: ", 0), 0u) << "expected at " << c.where << ", got: " << e;
        EXPECT_NE(e.find(c.what), std::string::npos) << e;
    }
}

TEST(PipelineYaml, MissingFileIsAnError) {
    Diagnostics d;
    loadPipeline("/nonexistent/pipeline.yaml", testfilters::registry(), d);
    ASSERT_TRUE(hasErrors(d));
    EXPECT_EQ(d[0].where, "/nonexistent/pipeline.yaml");
}

// A placeholder's parameters are written back as read, in flow form: a value
// holding a comma (so it must be quoted in a flow sequence) and a quote or a
// backslash came out as `"a, "b" \ c"`, which is no YAML; now it is escaped
// and the file loads again with the same value.
TEST(PipelineYaml, PlaceholderValuesWithCommasAndQuotesSurviveASave) {
    const std::string text = "darkroom: 1\nnodes:\n  later:\n    type: FutureFilter\n    parameters:\n"
                             "      labels: ['a, \"b\" \\ c', plain, 'x,y']\n";
    Diagnostics d;
    Graph g = parse(text, d);
    ASSERT_FALSE(hasErrors(d)) << firstError(d);
    const std::string saved = serializePipeline(g);
    Diagnostics again;
    Graph back = parse(saved, again);
    ASSERT_FALSE(hasErrors(again)) << firstError(again) << "\n" << saved;
    EXPECT_EQ(serializePipeline(back), saved);
    EXPECT_NE(saved.find(R"("a, \"b\" \\ c")"), std::string::npos) << saved;
}
