#include "commands.h"
#include "foreach_run.h"
#include "processes.h"
#include "profile_report.h"
#include "progress_bar.h"

#include <darkroom/error.h>
#include <darkroom/core/evaluator.h>
#include <darkroom/core/pipeline.h>

#include <CLI/CLI.hpp>
#include <fmt/core.h>

#include <chrono>
#include <filesystem>
#include <set>

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
        // A value on a connected port would be silently ignored: the edge wins.
        if (const auto edges = g.edgesInto(node, port); !edges.empty())
            throw Error("input '" + port + "' of node '" + node + "' is fed by " + edges.front().from.node + "." +
                        edges.front().from.port + ", so a value set here would be ignored; remove that edge from "
                        "the pipeline to set it");
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
        std::string foreach;
        std::string where;
        std::string index;
        bool resume = false;
        bool profile = false;
        double cacheMB = 2048;
    };
    auto a = std::make_shared<Args>();
    cmd->add_option("PIPELINE", a->path, "Pipeline YAML file")->required();
    cmd->add_option("--set", a->sets, "Override a parameter: node.port=value (repeatable)")->type_name("NODE.PORT=VALUE");
    cmd->add_option("-o,--output", a->output, "Directory for relative output paths (default: the pipeline's folder)")
        ->type_name("DIR");
    auto* fe = cmd->add_option("--foreach", a->foreach,
                               "Run once per entry of the Cinema database read by NODE (a CinemaReader); "
                               "output paths get the entry's parameters, or replace {entry} (sinks fed the "
                               "reader's row, e.g. CinemaWriter, name entries themselves); sinks that do not "
                               "depend on NODE run once, after the last entry")
                   ->type_name("NODE");
    cmd->add_option("--where", a->where, "With --foreach: only entries matching, e.g. \"theta=0, phi=30\" or SQL \"phi > 0 AND theta = 0\"")
        ->needs(fe)
        ->type_name("QUERY");
    cmd->add_option("--index", a->index,
                    "With --foreach: write a CSV of the entries shaded (their parameters) and the files written "
                    "for each, merged over MPI ranks")
        ->needs(fe)
        ->type_name("FILE.csv");
    cmd->add_flag("--resume", a->resume,
                  "With --foreach: skip entries whose output files all exist and that every CinemaWriter in "
                  "mode resume already holds (complete an interrupted run)")
        ->needs(fe);
    cmd->add_option("-j,--threads", a->threads,
                    "Worker threads (default: all cores; under mpirun the node's cores shared among its ranks)")
        ->check(CLI::NonNegativeNumber);
    cmd->add_flag("--profile", a->profile,
                  "Print each node's time, whether it ran or came from the cache, and the memory it allocated "
                  "(per entry with --foreach)");
    cmd->add_option("--cache-memory", a->cacheMB,
                    "With --foreach: memory for results kept between entries, in MiB (least recently used "
                    "dropped first; default 2048)")
        ->check(CLI::NonNegativeNumber)
        ->type_name("MB");
    cmd->callback([&global, &run, a] {
        run = [&global, a] {
            const Registry& r = loadRegistry(global);
            Diagnostics d;
            Graph g = loadPipeline(a->path, r, d);
            // Every rank meets the same problems in the same files: one says so.
            if (processes().root()) report(d);
            if (hasErrors(d)) return int(kBadInput);
            for (const auto& s : a->sets)
                if (!applySet(g, s)) return int(kBadInput);
            Diagnostics problems = g.validate();
            if (hasErrors(problems)) {
                for (auto& x : problems) x.where = a->path + ": " + x.where;
                if (processes().root()) report(problems);
                return int(kBadInput);
            }
            if (!a->output.empty()) std::filesystem::create_directories(a->output);
            EvaluatorOptions o;
            o.threads = a->threads ? a->threads : defaultThreads();
            o.inputBase = std::filesystem::path(a->path).parent_path().string();
            o.outputDir = a->output;
            o.cacheBytes = std::size_t(a->cacheMB * 1024 * 1024);
            // One evaluation needs no cache: results are dropped as soon as
            // nothing downstream needs them. Entries of --foreach share what
            // does not depend on the entry.
            o.retainIntermediate = !a->foreach.empty();
            // Under mpirun, rank 0 alone draws the bar.
            ProgressBar bar("run", showProgress(global));
            o.onProgress = [&bar](double f, const std::string& node) { bar.update(f, node); };
            o.onWarning = [&bar](const Diagnostic& w) {
                bar.finish();
                report({w});
            };
            Evaluator ev(o);
            auto evaluate = [&](const std::string& title, std::vector<std::string> sinks = {}) {
                const auto t0 = std::chrono::steady_clock::now();
                ev.run(g, std::move(sinks));
                if (a->profile) {
                    bar.finish();
                    printProfile(title, ev.lastProfile(),
                                 std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
                }
            };
            try {
                if (a->foreach.empty()) {
                    // One evaluation is not shared out: rank 0 runs it.
                    if (processes().size > 1) {
                        if (!processes().root()) return int(kOk);
                        if (!global.quiet)
                            fmt::print(stderr, "darkroom: note: without --foreach there is one evaluation; rank 0 "
                                               "runs it and the other {} ranks have nothing to do\n",
                                       processes().size - 1);
                    }
                    evaluate(a->path);
                } else {
                    const int code = runForeach(g, ev, o, bar, {a->foreach, a->where, a->index, a->resume, global.quiet}, evaluate);
                    if (code != kOk) return code;
                }
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
