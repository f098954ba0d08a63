#include "commands.h"
#include "progress_bar.h"

#include <darkroom/error.h>
#include <darkroom/framework/evaluator.h>
#include <darkroom/framework/pipeline.h>

#include <CLI/CLI.hpp>
#include <fmt/core.h>

#include <filesystem>

namespace darkroom::cli {

namespace {

// --set node.port=value, typed by the port.
bool applySet(Graph& g, const std::string& assignment) {
    const auto eq = assignment.find('=');
    const auto dot = assignment.find('.');
    if (eq == std::string::npos || dot == std::string::npos || dot > eq) {
        reportError("--set '" + assignment + "': expected node.port=value");
        return false;
    }
    const std::string node = assignment.substr(0, dot);
    const std::string port = assignment.substr(dot + 1, eq - dot - 1);
    const std::string text = assignment.substr(eq + 1);
    try {
        const Node* n = g.node(node);
        if (!n) throw Error("no node named '" + node + "' in the pipeline");
        const PortSpec* spec = g.ports(*n).input(port);
        if (!spec) throw Error("node '" + node + "' (" + n->type + ") has no input '" + port + "'");
        g.setParameter(node, port, parseValue(spec->type, text));
    } catch (const Error& e) {
        reportError("--set '" + assignment + "': " + e.what());
        return false;
    }
    return true;
}

}  // namespace

void addRunCommand(CLI::App& app, GlobalOptions& global, Runner& run) {
    auto* cmd = app.add_subcommand("run", "Run a pipeline: evaluate every output node (e.g. ImageWriter)");
    struct Args {
        std::string path;
        std::vector<std::string> sets;
        std::string output;
        int threads = 0;
    };
    auto a = std::make_shared<Args>();
    cmd->add_option("PIPELINE", a->path, "Pipeline YAML file")->required();
    cmd->add_option("--set", a->sets, "Override a parameter: node.port=value (repeatable)")->type_name("NODE.PORT=VALUE");
    cmd->add_option("-o,--output", a->output, "Directory for relative output paths (default: the pipeline's folder)")
        ->type_name("DIR");
    cmd->add_option("-j,--threads", a->threads, "Worker threads (default: all cores)")->check(CLI::NonNegativeNumber);
    cmd->callback([&global, &run, a] {
        run = [&global, a] {
            const Registry& r = loadRegistry(global);
            Diagnostics d;
            Graph g = loadPipeline(a->path, r, d);
            report(d);
            if (hasErrors(d)) return int(kBadInput);
            for (const auto& s : a->sets)
                if (!applySet(g, s)) return int(kBadInput);
            Diagnostics problems = g.validate();
            if (hasErrors(problems)) {
                for (auto& x : problems) x.where = a->path + ": " + x.where;
                report(problems);
                return int(kBadInput);
            }
            if (!a->output.empty()) std::filesystem::create_directories(a->output);
            EvaluatorOptions o;
            o.threads = a->threads;
            o.inputBase = std::filesystem::path(a->path).parent_path().string();
            o.outputDir = a->output;
            ProgressBar bar("run", !global.quiet && stderrIsTerminal());
            o.onProgress = [&bar](double f, const std::string& node) { bar.update(f, node); };
            o.onWarning = [&bar](const Diagnostic& w) {
                bar.finish();
                report({w});
            };
            Evaluator ev(o);
            try {
                ev.run(g);
            } catch (const GraphError& e) {
                bar.finish();
                report(e.diagnostics());
                return int(kBadInput);
            }
            bar.finish();
            return int(kOk);
        };
    });
}

}  // namespace darkroom::cli
