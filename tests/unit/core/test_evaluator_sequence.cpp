// The sequence bracket (filter.h, Evaluator::beginSequence): an evaluation
// alone is a sequence of its own; an explicit sequence spans evaluations;
// every filter that began is ended, early when something failed; a filter
// that fails to let go is named and does not keep the others holding on.
#include "test_filters.h"

#include <darkroom/core/evaluator.h>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

using namespace darkroom;
using Log = std::vector<std::string>;
using testfilters::bracketLog;

namespace {

Graph bracketed(int sinks = 1) {
    Graph g(testfilters::registry());
    g.addNode("src", "TestSource");
    for (int i = 0; i < sinks; ++i) {
        const std::string name = "sink" + std::to_string(i);
        g.addNode(name, "TestBracketed");
        g.connect({"src", "image"}, {name, "image"});
    }
    return g;
}

}  // namespace

TEST(EvaluatorSequence, AnEvaluationAloneIsASequenceOfItsOwn) {
    Graph g = bracketed();
    Evaluator ev;
    bracketLog().clear();
    ev.run(g);
    EXPECT_EQ(bracketLog(), (Log{"begin 0", "execute 0", "end completed"}));
    EXPECT_FALSE(ev.inSequence());
    // A cached result runs nothing, so nothing is begun.
    bracketLog().clear();
    ev.run(g);
    EXPECT_EQ(bracketLog(), Log{});
}

TEST(EvaluatorSequence, AnExplicitSequenceSpansEvaluations) {
    Graph g = bracketed();
    Evaluator ev;
    bracketLog().clear();
    {
        EvaluatorSequence sequence(ev, SequenceInfo{3});
        for (int tag : {1, 2, 3}) {
            g.setParameter("sink0", "tag", Value(tag));
            ev.run(g);
        }
        EXPECT_EQ(bracketLog().back(), "execute 3") << "nothing ends before the sequence does";
        sequence.end();
    }
    EXPECT_EQ(bracketLog(), (Log{"begin 3", "execute 1", "execute 2", "execute 3", "end completed"}));
    ev.endSequence();  // none open: nothing to end
    EXPECT_EQ(bracketLog().size(), 5u);
}

TEST(EvaluatorSequence, AFailureEndsTheSequenceEarly) {
    Graph g = bracketed();
    g.addNode("broken", "TestThrow");
    g.connect({"src", "image"}, {"broken", "image"});
    Evaluator ev;
    bracketLog().clear();
    EXPECT_THROW(ev.run(g, {"sink0", "broken"}), Error);
    EXPECT_EQ(bracketLog(), (Log{"begin 0", "execute 0", "end early"}));
    EXPECT_FALSE(ev.inSequence());
}

TEST(EvaluatorSequence, AFilterThatCannotLetGoIsNamedAndTheOthersAreEnded) {
    Graph g = bracketed(2);
    g.setParameter("sink0", "failEnd", Value(true));
    Evaluator ev;
    bracketLog().clear();
    try {
        ev.run(g);
        ADD_FAILURE() << "the failed endSequence was not reported";
    } catch (const Error& e) {
        EXPECT_THAT(e.what(), ::testing::HasSubstr("node 'sink0' (TestBracketed): could not let go"));
    }
    EXPECT_EQ(std::count(bracketLog().begin(), bracketLog().end(), "end completed"), 2);
}

TEST(EvaluatorSequence, DroppingTheCacheOrANodeInASequenceEndsItsFilter) {
    Graph g = bracketed(2);
    Evaluator ev;
    bracketLog().clear();
    ev.beginSequence();
    ev.run(g);
    g.removeNode("sink1");
    ev.run(g, {"sink0"});
    EXPECT_EQ(std::count(bracketLog().begin(), bracketLog().end(), "end early"), 1) << "sink1's state was freed";
    ev.clearCache();
    EXPECT_EQ(std::count(bracketLog().begin(), bracketLog().end(), "end early"), 2) << "sink0's too";
    EXPECT_TRUE(ev.inSequence());
    EXPECT_THROW(ev.beginSequence(), Error) << "sequences do not nest";
    ev.endSequence();
    EXPECT_EQ(std::count(bracketLog().begin(), bracketLog().end(), "end completed"), 0);
}
