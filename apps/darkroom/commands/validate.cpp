#include "commands.h"

#include <darkroom/core/pipeline.h>

#include <CLI/CLI.hpp>
#include <fmt/core.h>

namespace darkroom::cli {

void addValidateCommand(CLI::App& app, GlobalOptions& global, Runner& run) {
    auto* cmd = app.add_subcommand("validate", "Check a pipeline file without running it");
    auto path = std::make_shared<std::string>();
    cmd->add_option("PIPELINE", *path, "Pipeline YAML file")->required();
    cmd->callback([&global, &run, path] {
        run = [&global, path] {
            const Registry& r = loadRegistry(global);
            Diagnostics d;
            Graph g = loadPipeline(*path, r, d);
            if (!hasErrors(d)) {
                for (auto& x : g.validate()) {
                    // Unknown types were already reported at their line.
                    bool dup = false;
                    for (const auto& y : d)
                        if (!x.node.empty() && y.node == x.node && x.message.find("unknown type") != std::string::npos)
                            dup = true;
                    if (!dup) {
                        x.where = *path + ": " + x.where;
                        d.push_back(x);
                    }
                }
                // A placeholder is fine to keep but cannot run.
                for (auto& x : d)
                    if (x.message.find("kept as a placeholder") != std::string::npos)
                        x.severity = Diagnostic::Severity::Error;
            }
            report(d);
            if (hasErrors(d)) return int(kBadInput);
            fmt::print("{}: OK ({} nodes, {} edges, outputs: {})\n", *path, g.nodes().size(), g.edges().size(),
                       [&] {
                           std::string s;
                           for (const auto& n : g.sinks()) s += (s.empty() ? "" : ", ") + n;
                           return s.empty() ? std::string("none") : s;
                       }());
            return int(kOk);
        };
    });
}

}  // namespace darkroom::cli
