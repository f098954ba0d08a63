#include "preview_graph.h"

#include <darkroom/error.h>

#include <cmath>
#include <map>

namespace editor {
namespace {

bool readsImages(const darkroom::Graph& g, const darkroom::Node& n) {
    for (const auto& e : g.edgesInto(n.name)) {
        const darkroom::Node* up = g.node(e.from.node);
        const darkroom::PortSpec* spec = up && !up->placeholder ? g.ports(*up).output(e.from.port) : nullptr;
        if (spec && spec->isImage()) return true;
    }
    return false;
}

}  // namespace

std::string previewNodeName(const std::string& source, const std::string& port) {
    return "preview-" + source + "-" + port;
}

darkroom::Graph makePreviewGraph(const darkroom::Graph& graph, int level) {
    if (!graph.registry().filter("Resize"))
        throw darkroom::Error("reduced-resolution preview needs the Resize node type (image-utils plugin)");
    // Built afresh rather than rewired in place: edges keep their order (it
    // matters for inputs that take several images). The evaluator's cache
    // keys on values, so a level's preview reuses what the last one computed
    // wherever nothing changed.
    darkroom::Graph g(graph.registry());
    for (const auto& n : graph.nodes()) g.addCopy(n);
    std::map<std::string, std::string> resized;  // "source.port" -> Resize node
    const double scale = std::ldexp(1.0, -level);
    for (const auto& n : graph.nodes()) {
        if (n.placeholder || readsImages(graph, n)) continue;
        for (const auto& out : graph.ports(n).outputs) {
            if (!out.isImage()) continue;
            std::string name = previewNodeName(n.name, out.name);
            for (int i = 2; g.node(name); ++i) name = previewNodeName(n.name, out.name) + "-" + std::to_string(i);
            g.addNode(name, "Resize");
            g.setParameter(name, "scale", darkroom::Value(scale));
            g.addEdgeUnchecked({{n.name, out.name}, {name, "image"}});
            resized[n.name + "." + out.name] = name;
        }
    }
    for (const auto& e : graph.edges()) {
        const auto it = resized.find(e.from.str());
        g.addEdgeUnchecked(it == resized.end() ? e : darkroom::Edge{{it->second, "image"}, e.to});
    }
    return g;
}

}  // namespace editor
