#include "commands.h"
#include "processes.h"
#include "profile_report.h"
#include "progress_bar.h"
#include "warning_log.h"

#include <darkroom/error.h>
#include <darkroom/core/assignment.h>
#include <darkroom/core/evaluator.h>
#include <darkroom/core/pipeline.h>
#include <darkroom/workflows/batch.h>
#include <darkroom/workflows/pipeline_record.h>

#include <CLI/CLI.hpp>
#include <fmt/core.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <mutex>
#include <optional>
#include <set>

namespace darkroom::cli {

namespace {

struct RunArgs {
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
    int inFlight = 0;
};

// Reports the batch's failures the way the runner reports them: a graph's
// diagnostics, or one line; returns the exit code.
int reportBatch(const workflows::BatchSummary& summary, bool quiet) {
    ProcessGroup& group = processGroup();
    if (group.lead() && summary.shadedPerProcess.size() > 1 && !quiet) {
        // How the dynamic scheduling shared the entries out.
        std::string counts;
        std::size_t shaded = 0;
        for (const std::size_t n : summary.shadedPerProcess) {
            counts += (counts.empty() ? "" : ", ") + std::to_string(n);
            shaded += n;
        }
        std::fprintf(stderr, "darkroom: shaded %zu entries over %zu ranks (per rank: %s)%s\n", shaded,
                     summary.shadedPerProcess.size(), counts.c_str(),
                     summary.kept ? (", " + std::to_string(summary.kept) + " kept by --resume").c_str() : "");
    }
    if (!summary.failure) return summary.failedElsewhere ? int(kRuntimeFailure) : int(kOk);
    try {
        std::rethrow_exception(summary.failure);
    } catch (const GraphError& e) {
        report(e.diagnostics());
        return kBadInput;
    } catch (const Error& e) {
        reportError(e.what());
    }
    return kRuntimeFailure;
}

// The pipeline once, or once per entry of --foreach's database.
int evaluatePipeline(Graph& g, const RunArgs& a, const GlobalOptions& global, EvaluatorOptions o) {
    // Under mpirun, rank 0 alone draws the bar.
    ProgressBar bar("run", showProgress(global));
    // With entries in flight, progress, warnings and profiles come from
    // several threads: one at a time on the terminal.
    std::mutex terminal;
    o.onProgress = [&bar, &terminal](double f, const std::string& node) {
        std::lock_guard<std::mutex> lock(terminal);
        bar.update(f, node);
    };
    WarningLog warnings;
    o.onWarning = [&bar, &warnings, &terminal](const Diagnostic& w) {
        std::lock_guard<std::mutex> lock(terminal);
        if (!warnings.firstTime(w)) return;
        bar.finish();
        report({w});
    };
    Evaluator ev(o);
    auto evaluate = [&](Evaluator& e, const Graph& graph, const std::string& title, std::vector<std::string> sinks) {
        const auto t0 = std::chrono::steady_clock::now();
        e.run(graph, std::move(sinks));
        if (a.profile) {
            std::lock_guard<std::mutex> lock(terminal);
            bar.finish();
            printProfile(title, e.lastProfile(), std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
        }
    };
    ProcessGroup& group = processGroup();
    if (a.foreach.empty()) {
        // One evaluation is not shared out: rank 0 runs it.
        if (group.size() > 1) {
            if (!group.lead()) return kOk;
            if (!global.quiet)
                fmt::print(stderr, "darkroom: note: without --foreach there is one evaluation; rank 0 runs it and "
                                   "the other {} ranks have nothing to do\n", group.size() - 1);
        }
        evaluate(ev, g, a.path, {});
        bar.finish();
        warnings.reportRepeats();
        return kOk;
    }
    workflows::BatchCallbacks cb;
    cb.evaluate = [&](Evaluator& e, const Graph& graph, const std::string& title,
                      const std::vector<std::string>& sinks) { evaluate(e, graph, title, sinks); };
    cb.progress = [&bar, &terminal](double f, const std::string& entry) {
        std::lock_guard<std::mutex> lock(terminal);
        bar.update(f, entry);
    };
    workflows::BatchSummary summary;
    try {
        summary = workflows::shadeEntries(g, ev, o, {a.foreach, a.where, a.index, a.resume, a.inFlight}, group, cb);
    } catch (const InputError& e) {
        bar.finish();
        warnings.reportRepeats();
        // The same on every process: one says so.
        if (group.lead()) reportError(e.what());
        return kBadInput;
    }
    bar.finish();
    warnings.reportRepeats();
    return reportBatch(summary, global.quiet);
}

int runPipeline(const GlobalOptions& global, const RunArgs& a) {
    // Only the plugins the pipeline's nodes come from, and the capture
    // backends when a Capture node will create one.
    std::optional<std::set<std::string>> types = pipelineNodeTypes(a.path);
    if (types && types->count("Capture")) types->insert(Registry::kEveryCaptureBackend);
    const Registry& r = loadRegistry(global, types ? &*types : nullptr);
    Diagnostics d;
    Graph g = loadPipeline(a.path, r, d);
    // Every rank meets the same problems in the same files: one says so.
    const bool lead = processGroup().lead();
    if (lead) report(d);
    if (hasErrors(d)) return kBadInput;
    for (const auto& s : a.sets) {
        try {
            assignParameter(g, s);
        } catch (const Error& e) {
            if (lead) reportError("--set '" + s + "': " + e.what());
            return kBadInput;
        }
    }
    Diagnostics problems = g.validate();
    if (hasErrors(problems)) {
        for (auto& x : problems) x.where = a.path + ": " + x.where;
        if (lead) report(problems);
        return kBadInput;
    }
    // What each CinemaWriter records of the pipeline, for a resume to compare.
    workflows::describeUpstreamPipelines(g);
    if (!a.output.empty()) std::filesystem::create_directories(a.output);
    EvaluatorOptions o;
    o.threads = a.threads ? a.threads : defaultThreads();
    o.inputBase = std::filesystem::path(a.path).parent_path().string();
    o.outputDir = a.output;
    o.cacheBytes = std::size_t(a.cacheMB * 1024 * 1024);
    // One evaluation needs no cache: results are dropped as soon as nothing
    // downstream needs them. Entries of --foreach share what does not
    // depend on the entry.
    o.retainIntermediate = !a.foreach.empty();
    try {
        return evaluatePipeline(g, a, global, o);
    } catch (const GraphError& e) {
        report(e.diagnostics());
        return kBadInput;
    }
}

}  // namespace

void addRunCommand(CLI::App& app, GlobalOptions& global, Runner& run) {
    auto* cmd = app.add_subcommand("run", "Run a pipeline: evaluate every output node (e.g. ImageWriter)");
    auto a = std::make_shared<RunArgs>();
    cmd->add_option("PIPELINE", a->path, "Pipeline YAML file")->required();
    cmd->add_option("--set", a->sets, "Override a parameter: node.port=value (repeatable)")->type_name("NODE.PORT=VALUE");
    cmd->add_option("-o,--output", a->output, "Directory for relative output paths (default: the pipeline's folder)")
        ->type_name("DIR");
    auto* fe = cmd->add_option("--foreach", a->foreach,
                               "Run once per entry of the Cinema database read by NODE (a CinemaReader); "
                               "output paths get the entry's parameters, or replace {entry} and {column} (e.g. "
                               "frames/{time}.png; sinks fed the "
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
    cmd->add_option("--in-flight", a->inFlight,
                    "With --foreach: entries shaded at once in this process, each reading, shading or writing "
                    "while the others do (0: automatic, 3; 1: one after another; under mpirun each rank takes "
                    "one at a time). Outputs are the same whatever the number; memory grows with it")
        ->needs(fe)
        ->check(CLI::NonNegativeNumber)
        ->type_name("N");
    cmd->add_option("--cache-memory", a->cacheMB,
                    "With --foreach: memory for results kept between entries, in MiB (least recently used "
                    "dropped first; default 2048)")
        ->check(CLI::NonNegativeNumber)
        ->type_name("MB");
    cmd->callback([&global, &run, a] { run = [&global, a] { return runPipeline(global, *a); }; });
}

}  // namespace darkroom::cli
