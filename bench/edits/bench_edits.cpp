// bench_edits: what an analyst's edit costs. The demo pipeline
// (docs/examples/demo.yaml) on the demo scene captured at SIZE x SIZE (default
// 1024; the captures are made here, one view each), evaluated once cold, then
// edited one parameter at a time with a warm cache: one input's colour map,
// the SSAO radius, the IBS strength, the FXAA preset. For each: the time to
// the final image (the antialias node, what the editor shows) and to the
// written PNG, the nodes that ran, and the time as a share of a full run.
// Peak memory: `darkroom run` of the same pipeline in a child process.
//
//   bench_edits [SIZE] [REPETITIONS]      (markdown on stdout)
#include <darkroom/error.h>
#include <darkroom/core/evaluator.h>
#include <darkroom/core/pipeline.h>
#include <darkroom/core/registry.h>

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

namespace fs = std::filesystem;
using namespace darkroom;

namespace {

using Clock = std::chrono::steady_clock;

std::string readText(const fs::path& p) {
    std::ifstream in(p);
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

void writeText(const fs::path& p, const std::string& s) { std::ofstream(p) << s; }

int runCommand(const std::vector<std::string>& args, long* maxRssKb = nullptr) {
    const pid_t pid = ::fork();
    if (pid == 0) {
        std::vector<char*> argv;
        for (const auto& a : args) argv.push_back(const_cast<char*>(a.c_str()));
        argv.push_back(nullptr);
        ::execv(argv[0], argv.data());
        ::_exit(127);
    }
    int status = 0;
    rusage usage{};
    ::wait4(pid, &status, 0, &usage);
    if (maxRssKb) *maxRssKb = usage.ru_maxrss;
    return WIFEXITED(status) ? WEXITSTATUS(status) : 128;
}

// The demo scene's three parts, captured at size x size for the one view the
// pipeline reads (phi 45, theta 40), laid out as the pipeline expects.
fs::path prepare(int size) {
    const fs::path root = fs::temp_directory_path() / ("darkroom-bench-edits-" + std::to_string(::getpid()));
    fs::create_directories(root / "docs/examples/demo");
    fs::create_directories(root / "out/demo");
    for (const char* part : {"surface", "flow", "particles"}) {
        std::string scene = readText(fs::path(DARKROOM_SOURCE_DIR) / "docs/examples/demo" / (std::string(part) + ".yaml"));
        const std::string res = "resolution: [" + std::to_string(size) + ", " + std::to_string(size) + "]";
        scene = std::regex_replace(scene, std::regex(R"(resolution: \[\d+, \d+\])"), res);
        scene = std::regex_replace(scene, std::regex(R"(phi: \[[^\]]*\])"), "phi: [45]");
        scene = std::regex_replace(scene, std::regex(R"(theta: \[[^\]]*\])"), "theta: [40]");
        const fs::path file = root / "docs/examples/demo" / (std::string(part) + ".yaml");
        writeText(file, scene);
        if (runCommand({DARKROOM_RUNNER, "-q", "capture", file.string(), "--output",
                        (root / "out/demo" / (std::string(part) + ".cdb")).string()}) != 0)
            throw Error(std::string("capture of the demo's ") + part + " failed");
    }
    fs::copy_file(fs::path(DARKROOM_SOURCE_DIR) / "docs/examples/demo.yaml", root / "docs/examples/demo.yaml");
    return root;
}

struct Timing {
    double toImage = 0, toFile = 0;  // seconds
    std::vector<std::string> ran;
};

Timing evaluate(Evaluator& ev, const Graph& g) {
    Timing t;
    const auto t0 = Clock::now();
    ev.evaluate(g, "antialias", "image");
    t.toImage = std::chrono::duration<double>(Clock::now() - t0).count();
    for (const auto& p : ev.lastProfile())
        if (p.status == NodeProfile::Status::Ran) t.ran.push_back(p.node + " " + std::to_string(int(p.seconds * 1e3 + 0.5)));
    ev.run(g, {"write"});
    t.toFile = std::chrono::duration<double>(Clock::now() - t0).count();
    for (const auto& p : ev.lastProfile())
        if (p.status == NodeProfile::Status::Ran && p.node == "write")
            t.ran.push_back(p.node + " " + std::to_string(int(p.seconds * 1e3 + 0.5)));
    return t;
}

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v.empty() ? 0 : v[v.size() / 2];
}

std::string joined(const std::vector<std::string>& v) {
    std::string s;
    for (const auto& x : v) s += (s.empty() ? "" : ", ") + x;
    return s.empty() ? "none" : s;
}

}  // namespace

int main(int argc, char** argv) {
    const int size = argc > 1 ? std::atoi(argv[1]) : 1024;
    const int reps = argc > 2 ? std::atoi(argv[2]) : 5;
    try {
        const fs::path root = prepare(size);
        const fs::path pipeline = root / "docs/examples/demo.yaml";

        // Peak memory of a whole run in its own process, and of the process
        // with nothing to run (the libraries: OpenImageIO's dependencies alone
        // are ~130 MB resident on Debian 12).
        long peakRun = 0, peakIdle = 0;
        // The whole command as a user runs it (process start, plugin loading,
        // reading the databases, every node, writing the PNG): best of three.
        double processSeconds = 1e9;
        for (int i = 0; i < 3; ++i) {
            long peak = 0;
            const auto t0 = Clock::now();
            runCommand({DARKROOM_RUNNER, "-q", "run", pipeline.string(), "--output", (root / "o").string()}, &peak);
            processSeconds = std::min(processSeconds, std::chrono::duration<double>(Clock::now() - t0).count());
            peakRun = std::max(peakRun, peak);
        }
        runCommand({DARKROOM_RUNNER, "-q", "validate", pipeline.string()}, &peakIdle);

        Registry registry;
        registry.loadPlugins({DARKROOM_BENCH_PLUGIN_DIR});
        Diagnostics d;
        Graph g = loadPipeline(pipeline.string(), registry, d);
        if (hasErrors(d)) throw Error("cannot load " + pipeline.string());
        EvaluatorOptions o;
        o.inputBase = pipeline.parent_path().string();
        o.outputDir = (root / "o").string();

        // Full runs, each with an empty cache (a fresh evaluator).
        std::vector<double> fullImage, fullFile;
        Timing full;
        for (int i = 0; i < reps; ++i) {
            Evaluator cold(o);
            full = evaluate(cold, g);
            fullImage.push_back(full.toImage);
            fullFile.push_back(full.toFile);
        }

        struct Edit {
            std::string what, node, port;
            Value a, b;
        };
        const std::vector<Edit> edits = {
            {"colour map of one input (surface: cool-to-warm / plasma)", "surfaceColour", "colormap",
             Value("plasma"), Value("cool-to-warm")},
            {"SSAO radius (0.08 / 0.1)", "ao", "radius", Value(0.1), Value(0.08)},
            {"IBS strength (0.8 / 0.6)", "outline", "strength", Value(0.6), Value(0.8)},
            {"FXAA preset (12 / 39)", "antialias", "preset", Value("39"), Value("12")},
        };
        Evaluator ev(o);
        evaluate(ev, g);  // warm

        const double fullMs = median(fullImage) * 1e3, fullFileMs = median(fullFile) * 1e3;
        char line[512];
        std::printf("Demo pipeline at %dx%d, median of %d; machine load (1 min) at start: ", size, size, reps);
        double load[1] = {0};
        if (::getloadavg(load, 1) == 1) std::printf("%.2f\n\n", load[0]);
        std::printf("| evaluation | to the image (ms) | to the PNG (ms) | share of a full run | nodes that ran (ms, last repetition) |\n");
        std::printf("|---|---:|---:|---:|---|\n");
        std::snprintf(line, sizeof line, "| full run, empty cache | %.1f | %.1f | 100 %% | all %zu |\n", fullMs,
                      fullFileMs, full.ran.size());
        std::fputs(line, stdout);
        for (const auto& e : edits) {
            std::vector<double> toImage, toFile;
            Timing t;
            for (int i = 0; i < reps; ++i) {
                g.setParameter(e.node, e.port, i % 2 == 0 ? e.a : e.b);
                t = evaluate(ev, g);
                toImage.push_back(t.toImage);
                toFile.push_back(t.toFile);
            }
            const double ms = median(toImage) * 1e3;
            std::snprintf(line, sizeof line, "| %s | %.1f | %.1f | %.1f %% | %s |\n", e.what.c_str(), ms,
                          median(toFile) * 1e3, 100.0 * ms / fullMs, joined(t.ran).c_str());
            std::fputs(line, stdout);
        }
        std::printf("\nPeak resident memory of `darkroom run` (one process, whole pipeline): %.0f MB; of the same "
                    "process validating only (libraries and plugins loaded): %.0f MB; the pipeline's own: %.0f MB.\n",
                    peakRun / 1024.0, peakIdle / 1024.0, (peakRun - peakIdle) / 1024.0);
        std::printf("Cache held after the edits: %.0f MB.\n", double(ev.cachedBytes()) / (1 << 20));
        std::printf("`darkroom run` of the pipeline as a command (process start to exit, PNG written), best of 3: "
                    "%.0f ms.\n",
                    processSeconds * 1e3);
        fs::remove_all(root);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "bench_edits: %s\n", e.what());
        return 1;
    }
    return 0;
}
