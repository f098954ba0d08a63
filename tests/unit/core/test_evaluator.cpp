#include "test_filters.h"

#include <darkroom/core/evaluator.h>
#include <gtest/gtest.h>

#include <set>

using namespace darkroom;

namespace {

// src1 and src2 feed add, then noise, then sink.
Graph diamond() {
    Graph g(testfilters::registry());
    g.addNode("src1", "TestSource");
    g.addNode("src2", "TestSource");
    g.addNode("add", "TestAdd");
    g.addNode("noise", "TestNoise");
    g.addNode("sink", "TestSink");
    g.setParameter("src2", "value", Value(10.0));
    g.connect({"src1", "image"}, {"add", "a"});
    g.connect({"src2", "image"}, {"add", "b"});
    g.connect({"add", "image"}, {"noise", "image"});
    g.connect({"noise", "image"}, {"sink", "image"});
    return g;
}

float firstPixel(const BufferPtr& b) { return b->hostFloat("value")[0]; }

}  // namespace

TEST(Evaluator, PullsOnlyWhatAnOutputNeeds) {
    Graph g = diamond();
    Evaluator ev;
    const BufferPtr b = ev.evaluateImage(g, "add", "image");
    EXPECT_FLOAT_EQ(firstPixel(b), 11.0f);
    EXPECT_EQ(ev.executions("src1"), 1u);
    EXPECT_EQ(ev.executions("add"), 1u);
    EXPECT_EQ(ev.executions("noise"), 0u);
    EXPECT_EQ(ev.executions("sink"), 0u);
}

TEST(Evaluator, CachesAndInvalidatesDownstreamOnly) {
    Graph g = diamond();
    Evaluator ev;
    ev.run(g);
    for (const char* n : {"src1", "src2", "add", "noise", "sink"}) EXPECT_EQ(ev.executions(n), 1u) << n;

    ev.run(g);  // nothing changed: nothing runs
    for (const char* n : {"src1", "src2", "add", "noise", "sink"}) EXPECT_EQ(ev.executions(n), 1u) << n;

    g.setParameter("noise", "seed", Value(99));
    ev.run(g);
    EXPECT_EQ(ev.executions("src1"), 1u);
    EXPECT_EQ(ev.executions("src2"), 1u);
    EXPECT_EQ(ev.executions("add"), 1u);
    EXPECT_EQ(ev.executions("noise"), 2u);
    EXPECT_EQ(ev.executions("sink"), 2u);

    g.setParameter("src2", "value", Value(20.0));
    const BufferPtr out = ev.evaluateImage(g, "add", "image");
    EXPECT_FLOAT_EQ(firstPixel(out), 21.0f);
    EXPECT_EQ(ev.executions("src1"), 1u) << "sibling branch is not re-run";
    EXPECT_EQ(ev.executions("src2"), 2u);
    EXPECT_EQ(ev.executions("add"), 2u);
    EXPECT_EQ(ev.executions("noise"), 2u) << "not needed by this request";
}

// A UI asks the evaluator which nodes would run instead of modelling the
// cache (issue 27): before any run every node needed; after one, none; after
// an edit, the edited node and what depends on it, and what wouldRun said is
// what then ran.
TEST(Evaluator, SaysWhatWouldRunWithoutRunning) {
    Graph g = diamond();
    Evaluator ev;
    using Names = std::set<std::string>;
    EXPECT_EQ(ev.wouldRun(g, {"add"}), (Names{"src1", "src2", "add"}));
    ev.run(g);
    EXPECT_EQ(ev.wouldRun(g, {"sink"}), Names{});
    g.setParameter("src2", "value", Value(20.0));
    const Names predicted = ev.wouldRun(g, {"sink"});
    EXPECT_EQ(predicted, (Names{"src2", "add", "noise", "sink"}));
    EXPECT_EQ(ev.executions("src2"), 1u) << "asking runs nothing";
    ev.run(g);
    Names ran;
    for (const auto& p : ev.lastProfile())
        if (p.status == NodeProfile::Status::Ran) ran.insert(p.node);
    EXPECT_EQ(ran, predicted);
    g.disconnect({"src2", "image"}, {"add", "b"});  // rewired: add and below
    g.connect({"src1", "image"}, {"add", "b"});
    EXPECT_EQ(ev.wouldRun(g, {"sink"}), (Names{"add", "noise", "sink"}));
}

TEST(Evaluator, UnchangedNodesReturnTheSameBuffer) {
    Graph g = diamond();
    Evaluator ev;
    const BufferPtr a = ev.evaluateImage(g, "noise", "image");
    const BufferPtr b = ev.evaluateImage(g, "noise", "image");
    EXPECT_EQ(a.get(), b.get());
}

TEST(Evaluator, RewiringInvalidates) {
    Graph g = diamond();
    Evaluator ev;
    EXPECT_FLOAT_EQ(firstPixel(ev.evaluateImage(g, "add", "image")), 11.0f);
    g.disconnect({"src2", "image"}, {"add", "b"});
    g.connect({"src1", "image"}, {"add", "b"});
    EXPECT_FLOAT_EQ(firstPixel(ev.evaluateImage(g, "add", "image")), 2.0f);
}

TEST(Evaluator, ConnectedValuePortsDriveParameters) {
    Graph g = diamond();
    g.addNode("num", "TestNumber");
    g.setParameter("num", "x", Value(100.0));
    g.connect({"num", "value"}, {"add", "offset"});
    Evaluator ev;
    EXPECT_FLOAT_EQ(firstPixel(ev.evaluateImage(g, "add", "image")), 111.0f);
    g.setParameter("num", "x", Value(200.0));
    EXPECT_FLOAT_EQ(firstPixel(ev.evaluateImage(g, "add", "image")), 211.0f);
}

TEST(Evaluator, MultipleInputsArriveInEdgeOrder) {
    Graph g(testfilters::registry());
    g.addNode("a", "TestSource");
    g.addNode("b", "TestSource");
    g.addNode("c", "TestSource");
    g.addNode("sum", "TestSum");
    g.setParameter("b", "value", Value(5.0));
    g.connect({"a", "image"}, {"sum", "images"});
    g.connect({"b", "image"}, {"sum", "images"});
    g.connect({"c", "image"}, {"sum", "images"});
    std::string why;
    EXPECT_FALSE(g.canConnect({"c", "image"}, {"sum", "images"}, &why)) << "the same edge twice";
    Evaluator ev;
    EXPECT_FLOAT_EQ(firstPixel(ev.evaluateImage(g, "sum", "image")), 1.0f * 1 + 2.0f * 5 + 3.0f * 1);
}

TEST(Evaluator, InvalidGraphFailsBeforeAnythingRuns) {
    Graph g = diamond();
    g.addNode("broken", "TestAdd");  // inputs missing
    g.addNode("sink2", "TestSink");
    g.connect({"broken", "image"}, {"sink2", "image"});
    Evaluator ev;
    try {
        ev.run(g);
        FAIL() << "expected a GraphError";
    } catch (const GraphError& e) {
        EXPECT_NE(std::string(e.what()).find("node 'broken'"), std::string::npos) << e.what();
    }
    EXPECT_EQ(ev.executions("src1"), 0u) << "nothing ran";
    // The valid part of the graph still evaluates on its own.
    EXPECT_NO_THROW(ev.run(g, {"sink"}));
}

TEST(Evaluator, FilterExceptionsNameTheNode) {
    Graph g(testfilters::registry());
    g.addNode("bad", "TestThrow");
    g.addNode("sink", "TestSink");
    g.connect({"bad", "image"}, {"sink", "image"});
    Evaluator ev;
    try {
        ev.run(g);
        FAIL() << "expected an error";
    } catch (const GraphError&) {
        FAIL() << "the graph is valid";
    } catch (const Error& e) {
        EXPECT_EQ(std::string(e.what()), "node 'bad' (TestThrow): deliberate failure");
        EXPECT_EQ(e.node(), "bad") << "the node is named as data too, for a UI to mark it";
    }
}

TEST(Evaluator, AChannelMissingOnAnInputNamesTheNodeAsData) {
    Graph g(testfilters::registry());
    g.addNode("src", "TestSource");
    g.addNode("twice", "TestDoubleA");  // needs channel a, which TestSource lacks
    g.connect({"src", "image"}, {"twice", "image"});
    Evaluator ev;
    try {
        ev.run(g, {"twice"});
        FAIL() << "expected the missing channel to be refused";
    } catch (const Error& e) {
        EXPECT_EQ(e.node(), "twice") << e.what();
    }
}

TEST(Evaluator, MissingChannelIsReportedWithWhatExists) {
    Registry r;
    r.registerBuiltin("t", &testfilters::registerAll);
    r.registerBuiltin("needs", [](Registrar& reg) {
        struct NeedsZ final : Filter {
            PortList ports() const override {
                PortList p;
                p.imageIn("image", "", {"Z"});
                p.imageOut("image", "");
                return p;
            }
            void execute(Context& c) override { c.setOutput("image", c.requireImage("image")); }
        };
        reg.addFilter<NeedsZ>("NeedsZ", "Test", "");
    });
    Graph g(r);
    g.addNode("src", "TestSource");
    g.addNode("z", "NeedsZ");
    g.connect({"src", "image"}, {"z", "image"});
    Evaluator ev;
    try {
        ev.evaluate(g, "z", "image");
        FAIL();
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("input 'image': the image has no depth channel 'Z' (channels: value)"), std::string::npos)
            << e.what();
    }
}

TEST(Evaluator, IdenticalResultsForOneAndManyThreads) {
    Graph g = diamond();
    g.setParameter("src1", "width", Value(257));
    g.setParameter("src1", "height", Value(131));
    g.setParameter("src2", "width", Value(257));
    g.setParameter("src2", "height", Value(131));
    EvaluatorOptions one;
    one.threads = 1;
    EvaluatorOptions many;
    many.threads = 8;
    Evaluator a(one), b(many);
    const BufferPtr x = a.evaluateImage(g, "noise", "image");
    const BufferPtr y = b.evaluateImage(g, "noise", "image");
    EXPECT_TRUE(identical(*x, *y));
}

TEST(Evaluator, CancellationStopsTheRun) {
    Graph g = diamond();
    Evaluator ev;
    EvaluatorOptions o;
    o.onProgress = [&ev](double, const std::string&) { ev.cancel(); };
    ev.setOptions(o);
    EXPECT_THROW(ev.run(g), Cancelled);
    EXPECT_LT(ev.executions("sink"), 1u);
    // The next run starts afresh.
    ev.setOptions({});
    EXPECT_NO_THROW(ev.run(g));
    EXPECT_EQ(ev.executions("sink"), 1u);
}

TEST(Evaluator, ReportsProgressUpToOne) {
    Graph g = diamond();
    double last = -1;
    bool monotone = true;
    EvaluatorOptions o;
    o.threads = 1;
    o.onProgress = [&](double f, const std::string&) {
        monotone &= f >= last;
        last = f;
    };
    Evaluator ev(o);
    ev.run(g);
    EXPECT_TRUE(monotone);
    EXPECT_DOUBLE_EQ(last, 1.0);
}
