// `darkroom capture SCENE -o DB`, alone or under `mpirun -np N`: the command
// line of the capture workflow (darkroom/workflows/capture.h), which the in
// situ API shares.
#include "commands.h"
#include "processes.h"
#include "progress_bar.h"

#include <darkroom/error.h>
#include <darkroom/workflows/capture.h>

#include <CLI/CLI.hpp>
#include <fmt/core.h>

#include <chrono>
#include <cstdio>

#include <sys/resource.h>

namespace darkroom::cli {

namespace {

void printSummary(const std::string& output, const workflows::CaptureSummary& s, int processes, double seconds) {
    const std::string kept = s.kept ? fmt::format(", {} kept from the interrupted capture", s.kept) : "";
    if (processes == 1)
        fmt::print(stderr, "darkroom: wrote {} ({} entries rendered{}, {:.1f} s)\n", output, s.rendered, kept, seconds);
    else
        fmt::print(stderr,
                   "darkroom: wrote {} ({} entries rendered over {} ranks{}, {:.1f} s: ray tracing {:.2f} s, "
                   "compositing {:.2f} s (slowest rank), writing {:.2f} s)\n",
                   output, s.rendered, processes, kept, seconds, s.renderSeconds, s.compositeSeconds,
                   s.writeSeconds);
    // A time series whose steps the ranks shared: which rank captured which steps whole.
    for (std::size_t k = 0; k < s.stepsPerRank.size(); ++k)
        fmt::print(stderr, "darkroom: rank {} captured {}\n", k,
                   s.stepsPerRank[k].empty() ? std::string("no step") : "the steps " + s.stepsPerRank[k]);
}

// `--profile`: where the time before the first ray went, and the peak
// memory, so that ingest of big meshes can be measured from the command line
// (bench/capture/run_ingest_bench.sh reads this line).
void printProfile(const workflows::CaptureSummary& s, double seconds) {
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    fmt::print(stderr,
               "darkroom: profile: scene read {:.2f} s, backend setup {:.2f} s, first ray at {:.2f} s, "
               "ray tracing {:.2f} s, writing {:.2f} s, total {:.2f} s, peak RSS {} MiB\n",
               s.sceneSeconds, s.setupSeconds, s.firstRaySeconds, s.renderSeconds, s.writeSeconds, seconds,
               usage.ru_maxrss / 1024);
}

int capture(const GlobalOptions& global, workflows::SceneCapture request, bool profile) {
    ProcessGroup& group = processGroup();
    const Registry& registry = loadRegistry(global);
    ProgressBar bar("capture", showProgress(global));
    request.progress = [&bar](double f, const std::string& label) { bar.update(f, label); };
    // Warnings about parts differ between processes: each says its own.
    request.warn = [&group](const std::string& w) {
        if (group.size() == 1) std::fprintf(stderr, "darkroom: warning: %s\n", w.c_str());
        else std::fprintf(stderr, "darkroom: rank %d: warning: %s\n", group.rank(), w.c_str());
    };
    const auto start = std::chrono::steady_clock::now();
    workflows::CaptureSummary summary;
    try {
        summary = workflows::captureSceneFile(request, registry, group);
    } catch (const InputError& e) {
        bar.finish();
        if (group.lead()) reportError(e.what());  // the same on every process: one says so
        return kBadInput;
    } catch (const Cancelled&) {
        throw;
    } catch (const Error& e) {
        bar.finish();
        if (group.lead()) reportError(e.what());
        return kRuntimeFailure;
    }
    bar.finish();
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (group.lead() && !global.quiet) printSummary(request.output, summary, group.size(), seconds);
    if (profile) printProfile(summary, seconds);
    return kOk;
}

}  // namespace

void addCaptureCommand(CLI::App& app, GlobalOptions& global, Runner& run) {
    auto* cmd = app.add_subcommand("capture", "Ray trace a scene file's cameras into a Cinema database of G-buffers");
    auto a = std::make_shared<workflows::SceneCapture>();
    cmd->add_option("SCENE", a->scene, "Scene file (YAML): objects, cameras, channels")->required();
    cmd->add_option("-o,--output", a->output, "Database folder to write, e.g. out/demo.cdb")->required()->type_name("DB.cdb");
    auto* ow = cmd->add_flag("--overwrite", a->overwrite, "Replace an existing database");
    cmd->add_flag("--resume", a->resume, "Complete an interrupted capture, keeping the entries already written")
        ->excludes(ow);
    cmd->add_option("--compression", a->compression, "OpenEXR compression of the products")
        ->check(CLI::IsMember({"none", "zip", "zips", "piz", "rle", "pxr24", "b44", "dwaa", "dwab"}));
    cmd->add_flag("--half", a->half, "Store scalar channels as half floats (depth and ids stay exact)");
    cmd->add_option("-j,--threads", a->threads, "Worker threads (default: all cores)")->check(CLI::NonNegativeNumber);
    auto profile = std::make_shared<bool>(false);
    cmd->add_flag("--profile", *profile,
                  "Print where the time went (scene read, backend setup, first ray, ray tracing, writing) and "
                  "the peak memory");
    cmd->callback([&global, &run, a, profile] {
        run = [&global, a, profile] { return capture(global, *a, *profile); };
    });
}

}  // namespace darkroom::cli
