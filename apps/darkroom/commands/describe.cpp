#include "commands.h"

#include <darkroom/error.h>
#include <darkroom/strings.h>

#include <CLI/CLI.hpp>
#include <fmt/core.h>

#include <algorithm>

namespace darkroom::cli {

namespace {

std::string portLine(const PortSpec& p) {
    std::string s = fmt::format("  {:<14} {:<9}", p.name, toString(p.type));
    if (p.type == PortType::Image) {
        if (p.multiple) s += " any number, in edge order;";
        else if (p.optional) s += " optional;";
        if (!p.channels.empty()) {
            s += " channels:";
            for (const auto& c : p.channels) s += " " + c;
            s += ";";
        }
    } else if (!p.defaultValue.empty()) {
        const std::string text = formatValue(p.type, p.defaultValue);
        s += " default " + (text.empty() ? std::string("\"\"") : text) + ";";
    }
    if (p.minimum && p.maximum)
        s += " range [" + formatValue(PortType::Float, *p.minimum) + ", " + formatValue(PortType::Float, *p.maximum) + "];";
    if (p.type == PortType::Enum && !p.choices.empty()) {
        s += " one of:";
        for (std::size_t i = 0; i < p.choices.size(); ++i) s += (i ? ", " : " ") + p.choices[i];
        s += ";";
    }
    if (!p.doc.empty()) s += " " + p.doc;
    return s;
}

}  // namespace

void addDescribeCommand(CLI::App& app, GlobalOptions& global, Runner& run) {
    auto* cmd = app.add_subcommand("describe", "Show a node type's ports: types, defaults, ranges and documentation");
    auto type = std::make_shared<std::string>();
    cmd->add_option("TYPE", *type, "Node type or capture backend, e.g. ColorMapping")->required();
    cmd->callback([&global, &run, type] {
        run = [&global, type] {
            const Registry& r = loadRegistry(global);
            if (const auto* b = r.backend(*type); b && !r.filter(*type)) {
                fmt::print("{} (capture backend, from {} {})\n\n{}\n", *type, b->origin.plugin, b->origin.version,
                           b->info.doc);
                return int(kOk);
            }
            const RegisteredFilter* f = r.filter(*type);
            if (!f) {
                reportError("unknown node type '" + *type + "'" + didYouMean(*type, r.typeNames(true)) +
                            "; `darkroom plugins` lists the available types");
                return int(kBadInput);
            }
            const PortList& ports = r.ports(*type);
            fmt::print("{}  [{}]  from plugin {} {}\n\n{}\n\nInputs:\n", f->info.type, f->info.category,
                       f->origin.plugin, f->origin.version, f->info.doc);
            for (const auto& p : ports.inputs) fmt::print("{}\n", portLine(p));
            if (ports.inputs.empty()) fmt::print("  (none)\n");
            fmt::print("\nOutputs:\n");
            for (const auto& p : ports.outputs) fmt::print("{}\n", portLine(p));
            // As Graph::sinks decides: no outputs, or files written.
            const bool writes = std::any_of(ports.inputs.begin(), ports.inputs.end(),
                                            [](const PortSpec& p) { return p.type == PortType::OutputPath; });
            if (ports.outputs.empty()) fmt::print("  (none: this node is an output of the pipeline)\n");
            else if (writes) fmt::print("  (this node writes files: it is an output of the pipeline)\n");
            return int(kOk);
        };
    });
}

}  // namespace darkroom::cli
