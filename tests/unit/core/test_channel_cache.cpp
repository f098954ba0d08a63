// Channel-granular evaluation: planes are shared, not copied; a node is keyed
// on what it read; a node whose read planes are unchanged is not executed, and
// its output is re-assembled around new planes it only passed on; files on
// disk are part of the key; states of removed nodes are freed; the cache is
// capped; a run that starts cancelled runs nothing.
#include "test_filters.h"
#include "test_support.h"

#include <darkroom/core/evaluator.h>
#include <darkroom/core/run_filter.h>
#include <gtest/gtest.h>

#include <chrono>
#include <cstring>
#include <filesystem>
#include <thread>

using namespace darkroom;

namespace {

// two -> doubleA -> copyA -> increment
Graph chain() {
    Graph g(testfilters::registry());
    g.addNode("two", "TestTwoPlanes");
    g.addNode("double", "TestDoubleA");
    g.addNode("copy", "TestCopyAReadingB");
    g.addNode("inc", "TestIncrementC");
    g.connect({"two", "image"}, {"double", "image"});
    g.connect({"two", "image"}, {"copy", "image"});
    g.connect({"copy", "image"}, {"inc", "image"});
    return g;
}

NodeProfile::Status statusOf(const Evaluator& ev, const std::string& node) {
    for (const auto& p : ev.lastProfile())
        if (p.node == node) return p.status;
    ADD_FAILURE() << node << " is not in the last profile";
    return NodeProfile::Status::Cached;
}

float at(const BufferPtr& b, const char* channel) { return b->requireFloat(channel)[0]; }

}  // namespace

TEST(ChannelCache, DerivedOutputsShareTheInputPlanes) {
    Graph g = chain();
    Evaluator ev;
    const BufferPtr in = ev.evaluateImage(g, "two", "image");
    const BufferPtr out = ev.evaluateImage(g, "double", "image");
    EXPECT_EQ(out->plane("a"), in->plane("a"));
    EXPECT_EQ(out->plane("b"), in->plane("b"));
    EXPECT_NE(out->plane("c"), nullptr);
    EXPECT_FLOAT_EQ(at(out, "c"), 2.0f);
}

TEST(ChannelCache, AnEditOfAPlaneANodeOnlyPassesOnDoesNotRunIt) {
    Graph g = chain();
    Evaluator ev;
    ev.evaluateImage(g, "double", "image");
    EXPECT_EQ(ev.executions("double"), 1u);

    g.setParameter("two", "b", Value(5.0));  // double reads only a
    const BufferPtr out = ev.evaluateImage(g, "double", "image");
    EXPECT_EQ(ev.executions("two"), 2u);
    EXPECT_EQ(ev.executions("double"), 1u);
    EXPECT_EQ(statusOf(ev, "double"), NodeProfile::Status::Reassembled);
    EXPECT_FLOAT_EQ(at(out, "b"), 5.0f);  // the new plane, passed on
    EXPECT_FLOAT_EQ(at(out, "c"), 2.0f);  // the cached one

    g.setParameter("two", "a", Value(3.0));  // what it reads
    const BufferPtr again = ev.evaluateImage(g, "double", "image");
    EXPECT_EQ(ev.executions("double"), 2u);
    EXPECT_EQ(statusOf(ev, "double"), NodeProfile::Status::Ran);
    EXPECT_FLOAT_EQ(at(again, "c"), 6.0f);
}

TEST(ChannelCache, ABitIdenticalRecomputedPlaneKeepsDownstreamCached) {
    Graph g = chain();
    Evaluator ev;
    ev.evaluateImage(g, "inc", "image");
    const BufferPtr before = ev.evaluateImage(g, "copy", "image");
    g.setParameter("two", "b", Value(7.0));  // copy reads b, so it runs, but makes the same c
    const BufferPtr out = ev.evaluateImage(g, "inc", "image");
    EXPECT_EQ(ev.executions("copy"), 2u);
    EXPECT_EQ(ev.executions("inc"), 1u);
    EXPECT_EQ(statusOf(ev, "inc"), NodeProfile::Status::Cached);
    EXPECT_EQ(ev.evaluateImage(g, "copy", "image"), before);  // the previous buffer itself
    EXPECT_FLOAT_EQ(at(out, "d"), 2.0f);
}

TEST(ChannelCache, AnUnchangedGraphRunsNothing) {
    Graph g = chain();
    Evaluator ev;
    ev.evaluateImage(g, "inc", "image");
    ev.evaluateImage(g, "inc", "image");
    for (const auto& p : ev.lastProfile()) EXPECT_EQ(p.status, NodeProfile::Status::Cached) << p.node;
}

TEST(ChannelCache, AForwardingNodePublishesItsInputPointer) {
    Graph g(testfilters::registry());
    g.addNode("two", "TestTwoPlanes");
    g.addNode("fwd", "TestForward");
    g.connect({"two", "image"}, {"fwd", "image"});
    Evaluator ev;
    const BufferPtr in = ev.evaluateImage(g, "two", "image");
    EXPECT_EQ(ev.evaluateImage(g, "fwd", "image"), in);
    g.setParameter("two", "a", Value(9.0));
    const BufferPtr now = ev.evaluateImage(g, "fwd", "image");
    EXPECT_EQ(now, ev.evaluateImage(g, "two", "image"));
    EXPECT_EQ(ev.executions("fwd"), 1u);  // it read nothing: re-assembled, not run
}

TEST(ChannelCache, AChangedFileIsReadAgain) {
    test::TempDir dir;
    const std::string file = dir.file("number.txt");
    test::writeText(file, "1.5");
    Graph g(testfilters::registry());
    g.addNode("read", "TestFileNumber");
    g.setParameter("read", "path", Value(file));
    Evaluator ev;
    EXPECT_FLOAT_EQ(at(ev.evaluateImage(g, "read", "image"), "value"), 1.5f);
    EXPECT_FLOAT_EQ(at(ev.evaluateImage(g, "read", "image"), "value"), 1.5f);
    EXPECT_EQ(ev.executions("read"), 1u);
    test::writeText(file, "2.25");  // other size
    EXPECT_FLOAT_EQ(at(ev.evaluateImage(g, "read", "image"), "value"), 2.25f);
    test::writeText(file, "3.25");  // same size, later modification time
    std::filesystem::last_write_time(file, std::filesystem::last_write_time(file) + std::chrono::seconds(2));
    EXPECT_FLOAT_EQ(at(ev.evaluateImage(g, "read", "image"), "value"), 3.25f);
    EXPECT_EQ(ev.executions("read"), 3u);
}

TEST(ChannelCache, StatesOfRemovedAndRenamedNodesAreFreed) {
    Graph g = chain();
    Evaluator ev;
    ev.evaluateImage(g, "inc", "image");
    const std::size_t held = ev.cachedBytes();
    EXPECT_GT(held, 0u);
    g.removeNode("inc");
    ev.evaluateImage(g, "copy", "image");
    EXPECT_EQ(ev.executions("inc"), 0u);
    EXPECT_LT(ev.cachedBytes(), held);
    g.renameNode("copy", "copied");
    ev.evaluateImage(g, "copied", "image");
    EXPECT_EQ(ev.executions("copy"), 0u);
}

TEST(ChannelCache, TheCacheIsCappedLeastRecentlyUsedFirst) {
    Graph g = chain();
    EvaluatorOptions o;
    o.cacheBytes = 1;  // nothing but what was asked for last survives
    Evaluator ev(o);
    ev.evaluateImage(g, "inc", "image");
    ev.evaluateImage(g, "double", "image");
    // inc's chain was evicted: asking again runs it.
    ev.evaluateImage(g, "inc", "image");
    EXPECT_EQ(ev.executions("inc"), 2u);
}

TEST(ChannelCache, AOneShotRunKeepsOnlyItsTargets) {
    Graph g = chain();
    EvaluatorOptions o;
    o.retainIntermediate = false;
    Evaluator ev(o);
    const BufferPtr out = ev.evaluateImage(g, "inc", "image");
    // Only inc's output is held: c (copy's plane, shared) and d, two planes
    // of 4x3 floats.
    EXPECT_EQ(ev.cachedBytes(), 2u * 12u * 4u);
    EXPECT_FLOAT_EQ(at(out, "d"), 2.0f);
}

TEST(ChannelCache, ARunWhoseFlagIsSetBeforeItStartsRunsNothing) {
    Graph g = chain();
    Evaluator ev;
    std::atomic<bool> cancel{true};
    EXPECT_THROW(ev.evaluateImage(g, "inc", "image", &cancel), Cancelled);
    EXPECT_EQ(ev.executions("two"), 0u);
    // cancel() before a run (without its own flag) cancels that run too.
    ev.cancel();
    EXPECT_THROW(ev.evaluateImage(g, "inc", "image"), Cancelled);
    EXPECT_NO_THROW(ev.evaluateImage(g, "inc", "image"));
}

TEST(NodeRunner, AnErrorNamesTheNodeOnce) {
    Graph g(testfilters::registry());
    g.addNode("grumpy", "TestComplains");
    Evaluator ev;
    try {
        ev.evaluateImage(g, "grumpy", "image");
        FAIL() << "expected an error";
    } catch (const Error& e) {
        const std::string m = e.what();
        EXPECT_EQ(m, "node 'grumpy' (TestComplains): the input is not what was expected");
    }
    // runFilter goes through the same runner.
    auto f = testfilters::registry().createFilter("TestComplains");
    FilterRunOptions o;
    o.nodeName = "alone";
    o.nodeType = "TestComplains";
    try {
        runFilter(*f, {}, o);
        FAIL() << "expected an error";
    } catch (const Error& e) {
        EXPECT_EQ(std::string(e.what()), "node 'alone' (TestComplains): the input is not what was expected");
    }
}

TEST(NodeRunner, PoisonRevealsPixelsAPassLeftUnwritten) {
    auto f = testfilters::registry().createFilter("TestForgetsToWrite");
    const BufferPtr out = runFilter(*f, {}).outputs.at("image").asImage();
    std::uint32_t bits;
    std::memcpy(&bits, out->hostFloat("value"), 4);
    EXPECT_EQ(bits, 0x7fbadbadu);
}

TEST(NodeRunner, PublishedPlanesAreSealed) {
    auto f = testfilters::registry().createFilter("TestTwoPlanes");
    const BufferPtr out = runFilter(*f, {}).outputs.at("image").asImage();
    // A buffer derived from a published one cannot write the shared planes.
    auto copy = makeHostBuffer(out->width(), out->height());
    copy->setPlane({"a"}, out->plane("a"));
    EXPECT_THROW(copy->writeFloat("a"), Error);
    EXPECT_EQ(copy->hostFloat("a"), out->hostFloat("a"));  // reading is fine
}
