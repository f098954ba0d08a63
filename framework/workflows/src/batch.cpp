#include <darkroom/workflows/batch.h>

#include "batch_lanes.h"
#include "batch_plan.h"
#include "batch_staging.h"
#include "entry_ports.h"
#include "graph_edits.h"

#include <darkroom/error.h>

#include <algorithm>

namespace darkroom::workflows {

using namespace batch;

namespace {

// The positions every process shaded (on the lead), and whether any failed.
std::vector<std::string> gatherRecords(const std::string& mine, bool failedHere, ProcessGroup& group, bool& anyFailed) {
    anyFailed = !group.agreedError(failedHere ? "failed" : "").empty();
    std::vector<std::string> all = group.allGather(mine);
    if (!group.lead()) all.clear();
    return all;
}

// The sinks that run once after the last entry, on the lead, reading the
// databases the entries were written into (the graph is rewired for it).
void runFinalSinks(GraphEdits& g, Evaluator& ev, const Plan& p, ProcessGroup& group, const BatchCallbacks& cb,
                   std::exception_ptr& failure) {
    if (!group.lead() || p.finalSinks.empty()) return;
    for (const auto& [edge, database] : p.afterLast) {
        g.disconnect(edge);
        g.set(edge.to.node, edge.to.port, Value(database));
    }
    EvaluatorOptions o = p.options;
    o.onProgress = [&cb](double f, const std::string& node) {
        if (cb.progress) cb.progress(f, node);
    };
    ev.setOptions(o);
    try {
        cb.evaluate(ev, g.graph(), "after the last entry", p.finalSinks);
    } catch (const Cancelled&) {
        throw;
    } catch (const GraphError&) {
        failure = std::current_exception();
    } catch (const Error& e) {
        failure = std::make_exception_ptr(Error(std::string("after the last entry: ") + e.what(), e.node()));
    }
}

}  // namespace

BatchSummary shadeEntries(Graph& graph, Evaluator& evaluator, EvaluatorOptions options, const BatchSettings& settings,
                          ProcessGroup& group, const BatchCallbacks& callbacks) {
    BatchCallbacks cb = callbacks;
    if (!cb.evaluate)
        cb.evaluate = [](Evaluator& ev, const Graph& g, const std::string&, const std::vector<std::string>& sinks) {
            ev.run(g, sinks);
        };
    // Every process opens the same database and meets the same problems.
    const int lanes = lanesFor(graph, settings, group);
    const Plan p = planBatch(graph, settings, std::move(options), group.size(), lanes);
    const std::vector<std::size_t> todo = entriesToShade(settings, p, group);
    GraphEdits edits(graph);  // undone as this returns
    // The selection is "the whole database" to what spans every entry
    // (ColorMapping's database range), when the reader can say so.
    if (!settings.where.empty() && graph.ports(*graph.node(settings.reader)).input(kSelectionPort))
        edits.set(settings.reader, kSelectionPort, Value(settings.where));
    BatchSummary summary;
    summary.selected = p.rows.size();
    summary.kept = p.rows.size() - todo.size();
    summary.inFlight = lanesInFlight(lanes, todo.size());
    const std::string records =
        shadeOverLanes(graph, evaluator, settings, p, todo, group, cb, summary.inFlight, summary.failure);
    bool anyFailed = false;
    const std::vector<std::string> all = gatherRecords(records, bool(summary.failure), group, anyFailed);
    summary.failedElsewhere = anyFailed && !summary.failure;
    for (const auto& text : all) summary.shadedPerProcess.push_back(std::size_t(std::count(text.begin(), text.end(), '\n')));
    if (group.lead()) finishOnLead(settings, p, todo, all, summary.failure);
    if (!summary.failure && !anyFailed) runFinalSinks(edits, evaluator, p, group, cb, summary.failure);
    return summary;
}

}  // namespace darkroom::workflows
