// Pipeline YAML that yaml-cpp accepts but Darkroom must not: recursive
// aliases, alias bombs, repeated keys, extra documents, misspelt keys and
// NaN or infinite values for ranged parameters (issue 18).
#include "test_filters.h"
#include "test_support.h"

#include <darkroom/core/pipeline.h>
#include <gtest/gtest.h>

using namespace darkroom;

namespace {

Graph parse(const std::string& text, Diagnostics& d) {
    return parsePipeline(text, "p.yaml", testfilters::registry(), d);
}

std::string errors(const Diagnostics& d) {
    std::string s;
    for (const auto& x : d)
        if (x.severity == Diagnostic::Severity::Error) s += x.str() + "\n";
    return s;
}

// The first error, which must exist and contain every piece.
void expectError(const std::string& text, std::initializer_list<const char*> pieces) {
    Diagnostics d;
    (void)parse(text, d);
    const std::string e = errors(d);
    ASSERT_FALSE(e.empty()) << "accepted:\n" << text;
    for (const char* p : pieces) EXPECT_NE(e.find(p), std::string::npos) << "missing '" << p << "' in: " << e;
}

const char* kHead = "darkroom: 1\nnodes:\n  src:\n    type: TestSource\n";

}  // namespace

TEST(PipelineGuard, SelfReferencingAliasIsRefusedNotRecursedInto) {
    // Kept as editor layout (flowText), which used to recurse without end.
    expectError(std::string(kHead) + "    ui: &a [1, *a]\nedges: []\n",
                {"p.yaml:5:", "recursive alias", "*a"});
    expectError(std::string(kHead) + "    ui: &m {x: *m}\nedges: []\n", {"p.yaml:5:", "recursive alias"});
}

TEST(PipelineGuard, AliasBombUnderUiIsRefusedAtItsLine) {
    std::string bomb = std::string(kHead) + "    ui:\n      a: &a [x, x, x, x, x, x, x, x, x, x]\n";
    char prev = 'a';
    for (char c = 'b'; c <= 'j'; ++c) {
        bomb += std::string("      ") + c + ": &" + c + " [";
        for (int i = 0; i < 10; ++i) bomb += std::string(i ? ", " : "") + "*" + prev;
        bomb += "]\n";
        prev = c;
    }
    bomb += "edges: []\n";
    ASSERT_LT(bomb.size(), 1000u);  // 10^10 nodes when expanded
    expectError(bomb, {"p.yaml:", "aliases expand to more than"});
}

TEST(PipelineGuard, ModestAliasesStillLoad) {
    Diagnostics d;
    Graph g = parse(std::string(kHead) + "    parameters: {value: &v 0.5}\n    ui: {a: &p [1, 2], b: *p}\n"
                                         "  other:\n    type: TestSource\n    parameters: {value: *v}\nedges: []\n",
                    d);
    EXPECT_EQ(errors(d), "");
    ASSERT_NE(g.node("other"), nullptr);
    EXPECT_EQ(g.node("other")->parameter("value")->asFloat(), 0.5);
    EXPECT_EQ(g.node("src")->extras.at(0).second, "{a: [1, 2], b: [1, 2]}");
}

TEST(PipelineGuard, DuplicateKeysAreErrorsNamingBothLines) {
    expectError(std::string(kHead) + "    parameters:\n      value: 1\n      value: 2\nedges: []\n",
                {"p.yaml:7:", "duplicate key 'value'", "first at line 6"});
    expectError(std::string(kHead) + "  src:\n    type: TestSink\nedges: []\n", {"p.yaml:5:", "duplicate key 'src'"});
    expectError(std::string(kHead) + "edges: []\nedges: []\n", {"p.yaml:6:", "duplicate key 'edges'"});
}

TEST(PipelineGuard, ASecondDocumentIsRefused) {
    expectError(std::string(kHead) + "edges: []\n---\ndarkroom: 1\n", {"p.yaml:", "second YAML document"});
}

TEST(PipelineGuard, MisspeltKeysNameTheNearestValidKey) {
    expectError(std::string(kHead) + "    paramters:\n      value: 2\nedges: []\n",
                {"p.yaml:5:", "unknown key 'paramters'", "did you mean 'parameters'"});
    expectError(std::string(kHead) + "egdes: []\n", {"p.yaml:5:", "unknown top-level key 'egdes'", "'edges'"});
    expectError(std::string(kHead) + "    parameters: {valeu: 2}\nedges: []\n",
                {"p.yaml:5:", "no parameter 'valeu'", "did you mean 'value'"});
    // Keys that resemble nothing the host reads are the editor's (ui:) and are kept.
    Diagnostics d;
    Graph g = parse(std::string(kHead) + "    ui: {position: [1, 2]}\nedges: []\n", d);
    EXPECT_EQ(errors(d), "");
}

TEST(PipelineGuard, NanAndInfinityFailRangedParameters) {
    expectError(std::string(kHead) + "    parameters: {value: .nan}\nedges: []\n",
                {"p.yaml:5:", "'value'", "nan", "not a number in the allowed range"});
    expectError(std::string(kHead) + "    parameters: {value: .inf}\nedges: []\n", {"p.yaml:5:", "'value'"});
    expectError(std::string(kHead) + "    parameters: {value: -.inf}\nedges: []\n", {"p.yaml:5:", "'value'"});
    // The same through the API (the editor, --set).
    Graph g(testfilters::registry());
    g.addNode("s", "TestSource");
    EXPECT_THROW(g.setParameter("s", "value", Value(std::nan(""))), Error);
    g.setParameter("s", "value", Value(2.5));
    EXPECT_EQ(g.node("s")->parameter("value")->asFloat(), 2.5);
}
