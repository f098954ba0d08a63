#include <darkroom/core/assignment.h>

#include <darkroom/error.h>
#include <darkroom/strings.h>

namespace darkroom {

void assignParameter(Graph& g, const std::string& assignment) {
    const auto eq = assignment.find('=');
    const auto dot = assignment.find('.');
    if (eq == std::string::npos || dot == std::string::npos || dot > eq)
        throw InputError("expected node.port=value");
    const std::string node = assignment.substr(0, dot);
    const std::string port = assignment.substr(dot + 1, eq - dot - 1);
    const std::string text = assignment.substr(eq + 1);
    const Node* n = g.node(node);
    if (!n) {
        std::vector<std::string> names;
        for (const auto& x : g.nodes()) names.push_back(x.name);
        throw InputError("no node named '" + node + "' in the pipeline" + didYouMean(node, names));
    }
    const PortSpec* spec = g.ports(*n).input(port);
    if (!spec) {
        // Image inputs take edges, not values: only the others are offered.
        std::vector<std::string> names;
        for (const auto& in : g.ports(*n).inputs)
            if (in.type != PortType::Image) names.push_back(in.name);
        throw InputError("node '" + node + "' (" + n->type + ") has no input '" + port + "'" + didYouMean(port, names) +
                         "; inputs that take a value: " + (names.empty() ? std::string("none") : join(names, ", ")));
    }
    if (const auto edges = g.edgesInto(node, port); !edges.empty())
        throw InputError("input '" + port + "' of node '" + node + "' is fed by " + edges.front().from.node + "." +
                         edges.front().from.port + ", so a value set here would be ignored; remove that edge from "
                         "the pipeline to set it");
    try {
        g.setParameter(node, port, parseValue(spec->type, text));
    } catch (const InputError&) {
        throw;
    } catch (const Error& e) {
        throw InputError(e.what());
    }
}

}  // namespace darkroom
