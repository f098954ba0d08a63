#include <darkroom/workflows/pipeline_record.h>

#include "content_hash.h"
#include "entry_ports.h"

#include <darkroom/value.h>

#include <set>
#include <vector>

namespace darkroom::workflows {

namespace {

std::string digestOf(const Graph& g, const Node& n) {
    ContentHash h;
    h.add(n.type);
    for (const PortSpec& in : g.ports(n).inputs) {
        if (choosesEntry(g, n, in)) continue;  // per entry: the same pipeline for every entry
        h.add(in.name);
        const std::vector<Edge> edges = g.edgesInto(n.name, in.name);
        for (const Edge& e : edges) h.add("<- " + e.from.str());
        if (!edges.empty() || in.type == PortType::Image) continue;
        const Value* v = n.parameter(in.name);
        h.add(formatValue(in.type, v ? *v : in.defaultValue));
    }
    return h.hex();
}

}  // namespace

std::string upstreamPipeline(const Graph& g, const std::string& sink) {
    std::string out;
    std::set<std::string> upstream = g.upstreamOf({sink});
    upstream.erase(sink);
    for (const std::string& name : upstream) {
        const Node* n = g.node(name);
        out += "node '" + n->name + "' (" + n->type + ")\t" + digestOf(g, *n) + "\n";
    }
    return out;
}

void describeUpstreamPipelines(Graph& g) {
    std::vector<std::string> writers;
    for (const Node& n : g.nodes()) {
        const PortSpec* p = g.ports(n).input("pipeline");
        if (p && p->type == PortType::String && !n.parameter("pipeline") && g.edgesInto(n.name, "pipeline").empty())
            writers.push_back(n.name);
    }
    for (const auto& w : writers) g.setParameter(w, "pipeline", Value(upstreamPipeline(g, w)));
}

}  // namespace darkroom::workflows
