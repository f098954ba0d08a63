// `darkroom validate PIPELINE`: everything that can be checked without
// running the pipeline (docs/cli.md, "What validate checks").
#include "commands.h"

#include <darkroom/core/pipeline.h>
#include <darkroom/workflows/pipeline_inputs.h>

#include <CLI/CLI.hpp>
#include <fmt/core.h>

namespace darkroom::cli {

namespace {

// The graph's own checks and the files it names, after what loading found.
void checkGraph(const Graph& g, const std::string& path, Diagnostics& d) {
    for (auto& x : g.validate()) {
        // Unknown types were already reported at their line.
        bool dup = false;
        for (const auto& y : d)
            if (!x.node.empty() && y.node == x.node && x.message.find("unknown type") != std::string::npos)
                dup = true;
        if (!dup) {
            x.where = path + ": " + x.where;
            d.push_back(x);
        }
    }
    for (auto& x : workflows::checkPipelineInputs(g, path)) d.push_back(std::move(x));
    // A placeholder is fine to keep but cannot run.
    for (auto& x : d)
        if (x.message.find("kept as a placeholder") != std::string::npos) x.severity = Diagnostic::Severity::Error;
}

int validatePipeline(const GlobalOptions& global, const std::string& path) {
    const Registry& r = loadRegistry(global);
    Diagnostics d;
    Graph g = loadPipeline(path, r, d);
    if (!hasErrors(d)) checkGraph(g, path, d);
    report(d);
    if (hasErrors(d)) return kBadInput;
    std::string sinks;
    for (const auto& n : g.sinks()) sinks += (sinks.empty() ? "" : ", ") + n;
    fmt::print("{}: OK ({} nodes, {} edges, outputs: {})\n", path, g.nodes().size(), g.edges().size(),
               sinks.empty() ? std::string("none") : sinks);
    return kOk;
}

}  // namespace

void addValidateCommand(CLI::App& app, GlobalOptions& global, Runner& run) {
    auto* cmd = app.add_subcommand("validate", "Check a pipeline file without running it: nodes, parameters, edges, "
                                               "and that the files, databases and colour maps it names exist");
    auto path = std::make_shared<std::string>();
    cmd->add_option("PIPELINE", *path, "Pipeline YAML file")->required();
    cmd->callback([&global, &run, path] { run = [&global, path] { return validatePipeline(global, *path); }; });
}

}  // namespace darkroom::cli
