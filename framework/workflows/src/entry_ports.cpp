#include "entry_ports.h"

#include <algorithm>

namespace darkroom::workflows {

const PortSpec* entryReaderDatabase(const Graph& g, const Node& n) {
    if (n.placeholder) return nullptr;
    const PortList& ports = g.ports(n);
    const auto isRow = [](const PortSpec& p) { return p.type == PortType::Row; };
    const PortSpec* entry = ports.input(kEntryPort);
    if (!entry || entry->type != PortType::Int || std::none_of(ports.outputs.begin(), ports.outputs.end(), isRow))
        return nullptr;
    const auto database = std::find_if(ports.inputs.begin(), ports.inputs.end(),
                                       [](const PortSpec& p) { return p.type == PortType::Path; });
    return database == ports.inputs.end() ? nullptr : &*database;
}

bool choosesEntry(const Graph& g, const Node& n, const PortSpec& input) {
    return (input.name == kEntryPort || input.name == "parameters" || input.name == kSelectionPort) &&
           entryReaderDatabase(g, n);
}

bool isFedARow(const Graph& g, const Node& n) {
    if (n.placeholder) return false;
    for (const PortSpec& in : g.ports(n).inputs)
        if (in.type == PortType::Row && !g.edgesInto(n.name, in.name).empty()) return true;
    return false;
}

const PortSpec* writerDatabase(const Graph& g, const Node& n) {
    for (const PortSpec& in : g.ports(n).inputs)
        if (in.type == PortType::OutputPath) return &in;
    return nullptr;
}

bool writesADatabaseThroughAnEdge(const Graph& g, const Node& n) {
    const PortSpec* database = isFedARow(g, n) ? writerDatabase(g, n) : nullptr;
    return database && !g.edgesInto(n.name, database->name).empty();
}

}  // namespace darkroom::workflows
