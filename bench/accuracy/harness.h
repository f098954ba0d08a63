#pragma once
// Shared parts of the accuracy harness: the build's plugins, a backend per
// stress scene, running a pass, best-of-N timing, and the CSV every sweep
// writes (long format, one measured number per row, so plot.py needs no
// per-pass schema).
#include <darkroom/buffer.h>
#include <darkroom/capture_backend.h>
#include <darkroom/context.h>
#include <darkroom/accuracy/stress_scenes.h>
#include <darkroom/value.h>

#include <fstream>
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace darkroom {
class Registry;
}

namespace darkroom::accuracy {

struct Options {
    int size = 256;              // stress scenes are size x size
    bool quick = false;          // fewer settings and scenes (a smoke run)
    std::string outDir = ".";    // CSV files go here (<sweep>.csv)
    std::string imageDir = "";   // failure pictures go here (PNG); empty = none
    int threads = 0;             // 0 = all hardware threads
    int repeats = 3;             // timing: best of this many runs
    std::vector<std::string> families;  // the ao sweep's stress families (empty: all it measures); for development
};

// One measured number. Columns of the CSV, in this order:
//   sweep, scene, family, knob, knob_value, method, setting, quality,
//   ms_per_mpix, region, metric, value
// `method` names a curve on a chart (e.g. "horizon", "ray traced (cosine)"),
// `setting` the point on it in words (e.g. "slices=4 steps=8"), `quality` the
// same as a number that grows with cost (samples, taps...), for ordering.
// `region` is "all", "edge" or "interior" (metrics::edgeMasks).
struct Row {
    std::string sweep, scene, family, knob;
    double knobValue = 0;
    std::string method, setting;
    double quality = 0;
    double msPerMpix = 0;
    std::string region = "all", metric;
    double value = 0;
};

class Csv {
public:
    explicit Csv(const std::string& path);  // writes the header; throws on failure
    void add(const Row& row);
    const std::string& path() const { return path_; }

private:
    std::string path_;
    std::ofstream out_;
};

class Harness {
public:
    explicit Harness(Options options);
    ~Harness();
    const Options& options() const { return options_; }
    const Registry& registry() const;

    // A fresh context for running a backend or reference by hand.
    Context& context();

    // The "embree" backend with `scene` set (built once per call).
    std::unique_ptr<CaptureBackend> backend(const stress::StressScene& scene) const;

    // Runs filter `type` on image port "image" = `input` with `parameters`;
    // returns output port "image".
    BufferPtr runPass(const std::string& type, const BufferPtr& input,
                      const std::map<std::string, Value>& parameters = {}) const;

    // Best wall time of options().repeats calls, in milliseconds per
    // megapixel of `pixels`.
    double msPerMpix(const std::function<void()>& work, std::size_t pixels) const;

    // The stress scene's field colour-mapped (viridis over its range) and
    // composited over `background`, exactly as reference::colorMapShader does
    // per sample: ColorMapping then Background, on a G-buffer that holds Z
    // and the field.
    BufferPtr colorize(const stress::StressScene& scene, const BufferPtr& gbuffer) const;
    static constexpr float kBackground[3] = {0.25f, 0.25f, 0.25f};

    // Writes channels (one = grey, three = RGB; linear, sRGB-encoded on
    // write) as a PNG into options().imageDir, if set. Returns the path or "".
    std::string writePicture(const Buffer& image, const std::vector<std::string>& channels,
                             const std::string& name) const;

private:
    Options options_;
    std::unique_ptr<Registry> registry_;
    std::unique_ptr<Context> context_;
};

// A sweep writes <outDir>/<name>.csv. Registered from each sweep_*.cpp with
// DARKROOM_ACCURACY_SWEEP; run by name from the command line.
using SweepFn = std::function<void(Harness&, Csv&)>;
bool registerSweep(const std::string& name, const std::string& description, SweepFn fn);

#define DARKROOM_ACCURACY_SWEEP(NAME, DESCRIPTION, FN) \
    static const bool darkroom_sweep_registered_##FN = ::darkroom::accuracy::registerSweep(NAME, DESCRIPTION, FN)

struct SweepInfo {
    std::string name, description;
    SweepFn fn;
};
const std::vector<SweepInfo>& sweeps();

}  // namespace darkroom::accuracy
