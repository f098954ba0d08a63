#include "commands.h"
#include "profile_report.h"
#include "progress_bar.h"

#include <darkroom/error.h>
#include <darkroom/framework/cinema/database.h>
#include <darkroom/framework/evaluator.h>
#include <darkroom/framework/pipeline.h>

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
        g.setParameter(node, port, parseValue(spec->type, text));
    } catch (const Error& e) {
        reportError("--set '" + assignment + "': " + e.what());
        return false;
    }
    return true;
}

// out.png -> out_phi=30_theta=45.png, or the {entry} placeholder replaced.
std::string perEntryPath(const std::string& path, const std::string& entry) {
    std::string out = path;
    const std::string tag = "{entry}";
    if (out.find(tag) != std::string::npos) {
        for (auto pos = out.find(tag); pos != std::string::npos; pos = out.find(tag, pos + entry.size()))
            out.replace(pos, tag.size(), entry);
        return out;
    }
    const std::filesystem::path p(path);
    return (p.parent_path() / (p.stem().string() + "_" + entry + p.extension().string())).string();
}

// Every node that depends on `source` through edges (source included).
std::set<std::string> downstreamOf(const Graph& g, const std::string& source) {
    std::set<std::string> seen{source};
    std::vector<std::string> todo{source};
    while (!todo.empty()) {
        const std::string n = todo.back();
        todo.pop_back();
        for (const Edge& e : g.edges())
            if (e.from.node == n && seen.insert(e.to.node).second) todo.push_back(e.to.node);
    }
    return seen;
}

// The Path parameters of the output nodes that run per entry, to rename per
// entry. A sink fed the entry's row (a `row` input connected, as CinemaWriter
// has) names its entries itself: its paths stay as given.
std::vector<std::pair<std::string, std::string>> outputPathPorts(const Graph& g, const std::vector<std::string>& sinks) {
    std::vector<std::pair<std::string, std::string>> out;
    for (const auto& name : sinks) {
        const Node* n = g.node(name);
        if (g.ports(*n).input("row") && !g.edgesInto(name, "row").empty()) continue;
        for (const auto& p : g.ports(*n).inputs)
            if (p.type == PortType::Path) out.emplace_back(name, p.name);
    }
    return out;
}

std::string currentValue(const Graph& g, const std::string& node, const std::string& port) {
    const Node* n = g.node(node);
    if (const Value* v = n->parameter(port)) return v->asString();
    return g.ports(*n).input(port)->defaultValue.asString();
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
    cmd->add_option("-j,--threads", a->threads, "Worker threads (default: all cores)")->check(CLI::NonNegativeNumber);
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
            o.cacheBytes = std::size_t(a->cacheMB * 1024 * 1024);
            // One evaluation needs no cache: results are dropped as soon as
            // nothing downstream needs them. Entries of --foreach share what
            // does not depend on the entry.
            o.retainIntermediate = !a->foreach.empty();
            ProgressBar bar("run", !global.quiet && stderrIsTerminal());
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
                    evaluate(a->path);
                } else {
                    const Node* reader = g.node(a->foreach);
                    if (!reader || !g.ports(*reader).input("database") || !g.ports(*reader).input("parameters")) {
                        reportError("--foreach " + a->foreach +
                                    ": expected the name of a CinemaReader node (with 'database' and 'parameters')");
                        return int(kBadInput);
                    }
                    std::filesystem::path dbPath = currentValue(g, a->foreach, "database");
                    if (dbPath.is_relative()) dbPath = std::filesystem::path(o.inputBase) / dbPath;
                    const CinemaDatabase db = CinemaDatabase::open(dbPath.string());
                    std::vector<std::size_t> rows;
                    if (a->where.empty())
                        for (std::size_t r = 0; r < db.rowCount(); ++r) rows.push_back(r);
                    else
                        rows = db.selectWhere(a->where);
                    if (rows.empty()) {
                        reportError(dbPath.string() + ": no entry matches '" + a->where + "'");
                        return int(kBadInput);
                    }
                    // Sinks that depend on the entry run once per entry; the others
                    // (e.g. a Movie of the database the entries are written to) once,
                    // after the last entry.
                    const std::set<std::string> perEntry = downstreamOf(g, a->foreach);
                    std::vector<std::string> entrySinks, finalSinks;
                    for (const auto& sink : g.sinks()) (perEntry.count(sink) ? entrySinks : finalSinks).push_back(sink);
                    if (entrySinks.empty()) std::swap(entrySinks, finalSinks);  // nothing reads the entry: as before
                    const auto outputs = outputPathPorts(g, entrySinks);
                    std::vector<std::string> originals;
                    for (const auto& [n, p] : outputs) originals.push_back(currentValue(g, n, p));
                    for (std::size_t i = 0; i < rows.size(); ++i) {
                        g.setParameter(a->foreach, "parameters", Value(db.formatParameters(rows[i])));
                        for (std::size_t k = 0; k < outputs.size(); ++k)
                            if (!originals[k].empty())
                                g.setParameter(outputs[k].first, outputs[k].second,
                                               Value(perEntryPath(originals[k], db.entryName(rows[i]))));
                        const std::string entry = db.entryName(rows[i]);
                        const double n = double(rows.size());
                        o.onProgress = [&bar, i, n, entry](double f, const std::string&) {
                            bar.update((double(i) + f) / n, entry);
                        };
                        ev.setOptions(o);
                        evaluate("entry " + entry + " (" + std::to_string(i + 1) + " of " +
                                 std::to_string(rows.size()) + ")",
                                 entrySinks);
                    }
                    if (!finalSinks.empty()) {
                        o.onProgress = [&bar](double f, const std::string& node) { bar.update(f, node); };
                        ev.setOptions(o);
                        evaluate("after the last entry", finalSinks);
                    }
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
