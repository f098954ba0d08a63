#include "harness.h"

#include <darkroom/error.h>
#include <darkroom/data/image_io.h>
#include <darkroom/core/registry.h>
#include <darkroom/core/run_filter.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <iomanip>
#include <limits>
#include <sstream>

namespace darkroom::accuracy {

namespace {

std::string csvField(const std::string& s) {
    if (s.find_first_of(",\"\n") == std::string::npos) return s;
    std::string q = "\"";
    for (char c : s) q += (c == '"') ? std::string("\"\"") : std::string(1, c);
    return q + "\"";
}

std::string number(double v) {
    if (std::isnan(v)) return "nan";
    if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
    std::ostringstream o;
    o << std::setprecision(7) << v;
    return o.str();
}

std::vector<SweepInfo>& sweepList() {
    static std::vector<SweepInfo> list;
    return list;
}

}  // namespace

Csv::Csv(const std::string& path) : path_(path), out_(path) {
    if (!out_) throw Error("cannot write '" + path + "'");
    out_ << "sweep,scene,family,knob,knob_value,method,setting,quality,ms_per_mpix,region,metric,value\n";
}

void Csv::add(const Row& r) {
    out_ << csvField(r.sweep) << ',' << csvField(r.scene) << ',' << csvField(r.family) << ',' << csvField(r.knob)
         << ',' << number(r.knobValue) << ',' << csvField(r.method) << ',' << csvField(r.setting) << ','
         << number(r.quality) << ',' << number(r.msPerMpix) << ',' << csvField(r.region) << ','
         << csvField(r.metric) << ',' << number(r.value) << '\n';
    out_.flush();
}

Harness::Harness(Options options) : options_(std::move(options)), registry_(std::make_unique<Registry>()) {
    registry_->loadPlugins({DARKROOM_BENCH_PLUGIN_DIR});
    FilterRunOptions o;
    o.threads = options_.threads;
    o.registry = registry_.get();
    context_ = makeStandaloneContext(o, "accuracy");
}

Harness::~Harness() = default;

const Registry& Harness::registry() const { return *registry_; }

Context& Harness::context() { return *context_; }

std::unique_ptr<CaptureBackend> Harness::backend(const stress::StressScene& scene) const {
    auto b = registry_->createBackend("embree");
    if (!b) throw Error("the 'embree' capture backend is not built (plugin capture-embree)");
    b->setScene(scene.scene);
    return b;
}

BufferPtr Harness::runPass(const std::string& type, const BufferPtr& input,
                           const std::map<std::string, Value>& parameters) const {
    auto filter = registry_->createFilter(type);
    if (!filter) throw Error("pass '" + type + "' is not built");
    std::map<std::string, std::vector<Value>> inputs;
    inputs["image"] = {Value(input)};
    for (const auto& [k, v] : parameters) inputs[k] = {v};
    FilterRunOptions o;
    o.threads = options_.threads;
    o.registry = registry_.get();
    o.poison = false;  // timed
    FilterRunResult r = runFilter(*filter, inputs, o);
    return r.outputs.at("image").asImage();
}

double Harness::msPerMpix(const std::function<void()>& work, std::size_t pixels) const {
    double best = std::numeric_limits<double>::infinity();
    for (int i = 0; i < std::max(1, options_.repeats); ++i) {
        const auto t0 = std::chrono::steady_clock::now();
        work();
        best = std::min(best, std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count());
    }
    return best / (double(pixels) * 1e-6);
}

BufferPtr Harness::colorize(const stress::StressScene& scene, const BufferPtr& gbuffer) const {
    const BufferPtr mapped = runPass("ColorMapping", gbuffer,
                                     {{"channel", Value(scene.colorField)},
                                      {"colormap", Value(std::string("viridis"))},
                                      {"range", Value(std::string("manual"))},
                                      {"minimum", Value(scene.fieldMin)},
                                      {"maximum", Value(scene.fieldMax)}});
    return runPass("Background", mapped,
                   {{"mode", Value(std::string("color"))},
                    {"color", Value(Color{kBackground[0], kBackground[1], kBackground[2], 1.0f})}});
}

std::string Harness::writePicture(const Buffer& image, const std::vector<std::string>& channels,
                                  const std::string& name) const {
    if (options_.imageDir.empty()) return "";
    std::filesystem::create_directories(options_.imageDir);
    const std::string path = (std::filesystem::path(options_.imageDir) / (name + ".png")).string();
    ImageWriteOptions o;
    o.channels = channels;
    writeImage(image, path, o);
    return path;
}

bool registerSweep(const std::string& name, const std::string& description, SweepFn fn) {
    sweepList().push_back({name, description, std::move(fn)});
    return true;
}

const std::vector<SweepInfo>& sweeps() { return sweepList(); }

}  // namespace darkroom::accuracy
