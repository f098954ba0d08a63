// Sweep "storage" (issue 6): what each stored G-buffer channel costs on disk
// under each OpenEXR compression, float32 against half, and what reconstructing
// normals from the stored depth costs in accuracy instead, so the database's
// default channel set and compression can be chosen from numbers
// (docs/accuracy-storage.md; bench/accuracy/storage_table.py renders the CSV).
//
// Every file is written through darkroom::writeImage, i.e. exactly the bytes a
// Cinema database entry holds (same metadata, same header attributes).
#include "harness.h"

#include <darkroom/error.h>
#include <darkroom/data/image_io.h>
#include <darkroom/accuracy/metrics.h>
#include <darkroom/scene/generators.h>
#include <darkroom/scene/scene_file.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <limits>
#include <string>
#include <time.h>
#include <unistd.h>
#include <vector>

namespace darkroom::accuracy {

namespace {

namespace fs = std::filesystem;

// One way of storing: an EXR compression and whether float channels (except Z)
// are written as half.
struct Variant {
    std::string compression;
    bool half = false;
    std::string name() const { return compression + (half ? " half" : ""); }
};

const std::vector<Variant>& variants() {
    static const std::vector<Variant> v = {{"none", false}, {"zip", false}, {"piz", false},
                                           {"zip", true},   {"piz", true}};
    return v;
}

// A stored channel group: the name in the CSV and the buffer channels.
struct Group {
    std::string name;
    std::vector<std::string> channels;
};

// The temporary folder files are written to; removed with everything in it.
class TempDir {
public:
    TempDir() {
        path_ = fs::temp_directory_path() / ("darkroom-storage-" + std::to_string(::getpid()));
        fs::create_directories(path_);
    }
    ~TempDir() {
        std::error_code ec;
        fs::remove_all(path_, ec);
    }
    std::string file(const std::string& name) const { return (path_ / name).string(); }

private:
    fs::path path_;
};

double nowMs() {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

// CPU time of the whole process (all threads): on a shared, loaded machine it
// depends far less on the other jobs than wall time does.
double cpuMs() {
    timespec t{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return double(t.tv_sec) * 1e3 + double(t.tv_nsec) * 1e-6;
}

// The demo generator scene (isosurface, streamlines, particles, maxima) seen as
// the demo's surface captures see it (docs/examples/demo/surface.yaml: fov 30,
// distance 4.6, up +Z), at phi 45, theta 15.
stress::StressScene demoScene(int width, int height) {
    stress::StressScene s;
    s.family = "demo";
    s.name = "demo";
    s.description = "the built-in demo generator: isosurface, streamlines, particles and maxima";
    auto scene = std::make_shared<Scene>();
    scene->objects = generate("demo", {});
    s.scene = scene;
    Camera proto;
    proto.projection = Camera::Projection::Perspective;
    proto.fovYDegrees = 30.0;
    proto.width = width;
    proto.height = height;
    s.camera = orbitCamera(proto, Vec3{0, 0, 0}, 4.6, 45.0, 15.0, Vec3{0, 0, 1});
    s.colorField = "height";
    s.fieldMin = -1.0;
    s.fieldMax = 1.0;
    return s;
}

std::vector<stress::StressScene> scenes(const Options& o) {
    const int w = o.quick ? o.size : 1024;
    const int h = o.quick ? o.size : 768;
    stress::Options so;
    so.width = w;
    so.height = h;
    std::vector<stress::StressScene> list;
    list.push_back(stress::make("terrain", stress::knobValues("terrain").front(), so));
    list.push_back(stress::make("gyroid", stress::knobValues("gyroid").front(), so));
    list.push_back(stress::make("particles", 2.0, so));
    list.push_back(stress::make("streamlines", 1.0, so));
    list.push_back(demoScene(w, h));
    return list;
}

// A copy of `src` holding only `channels`, renamed by `rename` (same order),
// with src's metadata.
std::shared_ptr<WritableBuffer> subset(const Buffer& src, const std::vector<std::string>& channels,
                                       const std::vector<std::string>& rename) {
    std::vector<ChannelDesc> desc;
    for (std::size_t i = 0; i < channels.size(); ++i) {
        const auto t = src.channelType(channels[i]);
        if (!t) throw Error("storage sweep: the capture has no channel '" + channels[i] + "'");
        desc.push_back({rename[i], *t});
    }
    auto out = makeCpuBuffer(src.width(), src.height(), desc);
    out->metadata() = src.metadata();
    const std::size_t n = src.pixelCount();
    for (std::size_t i = 0; i < channels.size(); ++i) {
        if (desc[i].type == ChannelType::UInt32)
            std::memcpy(out->writeUInt(rename[i]), src.hostUInt(channels[i]), n * 4);
        else
            std::memcpy(out->writeFloat(rename[i]), src.hostFloat(channels[i]), n * 4);
    }
    return out;
}

bool sameBits(const Buffer& a, const Buffer& b, const std::string& channel) {
    const float* pa = a.hostFloat(channel);
    const float* pb = b.hostFloat(channel);
    return pa && pb && a.pixelCount() == b.pixelCount() && std::memcmp(pa, pb, a.pixelCount() * 4) == 0;
}

class StorageSweep {
public:
    StorageSweep(Harness& h, Csv& csv, const stress::StressScene& s) : h_(h), csv_(csv), s_(s) {}

    void run() {
        CaptureRequest request;
        request.scalars = {s_.colorField};
        request.normals = true;
        request.objectId = true;
        auto backend = h_.backend(s_);
        gbuffer_ = backend->render(s_.camera, request, h_.context());
        masks_ = metrics::edgeMasks(*gbuffer_);

        measureBytes();
        measureScalarHalf();
        measureNormals();
    }

private:
    Row row(const std::string& method, const std::string& setting, const std::string& metric, double value,
            const std::string& region = "all") const {
        Row r;
        r.sweep = "storage";
        r.scene = s_.name;
        r.family = s_.family;
        r.knob = s_.knob;
        r.knobValue = s_.knobValue;
        r.method = method;
        r.setting = setting;
        r.region = region;
        r.metric = metric;
        r.value = value;
        return r;
    }

    // Writes `image` (only `channels`, all when empty) best-of-N times and
    // reads it back best-of-N times; rows bytes, bytes_per_pixel and wall
    // and CPU times. Returns the file read back.
    BufferPtr store(const Buffer& image, const std::vector<std::string>& channels, const Variant& v,
                    const std::string& setting, const std::string& methodOverride = "") {
        const std::string path = tmp_.file("entry.exr");
        ImageWriteOptions o;
        o.channels = channels;
        o.compression = v.compression;
        o.halfFloat = v.half;
        const int repeats = std::max(1, h_.options().repeats);
        const double inf = std::numeric_limits<double>::infinity();
        double writeMs = inf, readMs = inf, writeCpu = inf, readCpu = inf;
        BufferPtr back;
        for (int i = 0; i < repeats; ++i) {
            const double t0 = nowMs(), c0 = cpuMs();
            writeImage(image, path, o);
            writeMs = std::min(writeMs, nowMs() - t0);
            writeCpu = std::min(writeCpu, cpuMs() - c0);
        }
        const double bytes = double(fs::file_size(path));
        for (int i = 0; i < repeats; ++i) {
            const double t0 = nowMs(), c0 = cpuMs();
            back = readImage(path);
            readMs = std::min(readMs, nowMs() - t0);
            readCpu = std::min(readCpu, cpuMs() - c0);
        }
        const std::string method = methodOverride.empty() ? v.name() : methodOverride;
        const double mpix = double(image.pixelCount()) * 1e-6;
        for (const auto& [metric, value] : {std::pair<std::string, double>{"bytes", bytes},
                                            {"bytes_per_pixel", bytes / double(image.pixelCount())},
                                            {"write_ms", writeMs},
                                            {"read_ms", readMs},
                                            {"write_cpu_ms", writeCpu},
                                            {"read_cpu_ms", readCpu}}) {
            Row r = row(method, setting, metric, value);
            r.msPerMpix = writeMs / mpix;
            csv_.add(r);
        }
        return back;
    }

    void measureBytes() {
        const std::vector<Group> groups = {{"Z", {"Z"}},
                                           {"scalar", {s_.colorField}},
                                           {"N", {"N.x", "N.y", "N.z"}},
                                           {"objectId", {"objectId"}},
                                           {"entry", {}}};
        // The fixed part of a file: header (camera, attributes, channel list)
        // and offset table of a 1x1 image with one float channel. A w x h file
        // also has one offset per chunk (8 bytes per 1/16/32 scanlines for
        // none/zip/piz), counted in its channel's bytes here.
        auto one = makeCpuBuffer(1, 1, {{"Z", ChannelType::Float32}});
        one->metadata() = gbuffer_->metadata();
        for (const Variant& v : variants()) {
            if (!v.half) store(*one, {}, v, "header");
            for (const Group& g : groups) {
                const BufferPtr back = store(*gbuffer_, g.channels, v, g.name);
                if (g.name == "Z") zBack_.push_back({v.name(), back});
                if (g.name == "N" && v.half && v.compression == "zip") nHalf_ = back;
                if (g.name == "N" && !v.half && v.compression == "zip") nFloat_ = back;
                if (g.name == "scalar" && v.half && v.compression == "zip") scalarHalf_ = back;
            }
        }
        // Depth as half, which writeImage never writes (it keeps "Z" float32):
        // the same values under another name, to show what half would cost
        // the reconstruction.
        const auto renamed = subset(*gbuffer_, {"Z"}, {"depth"});
        for (const Variant& v : variants()) {
            if (!v.half) continue;
            const BufferPtr back = store(*renamed, {}, v, "Z", v.name() + " (Z as half)");
            if (v.compression == "zip") zHalf_ = subset(*back, {"depth"}, {"Z"});
        }
    }

    // Half scalars against float: the largest error as a share of the field's
    // range (a colour map step at 8 bits is 1/255 of it) and whether NaN (no
    // data) stays NaN. Half keeps 11 significant bits relative to the value,
    // not the range, so the field is also stored shifted by k ranges (a
    // temperature in kelvin, a height above sea level) to show where half
    // stops being safe.
    void measureScalarHalf() {
        const double range = s_.fieldMax - s_.fieldMin;
        const Variant zipHalf{"zip", true};
        for (const double k : {0.0, 1.0, 4.0, 16.0, 64.0}) {
            const auto shifted = subset(*gbuffer_, {s_.colorField}, {"field"});
            float* f = shifted->writeFloat("field");
            for (std::size_t p = 0; p < shifted->pixelCount(); ++p) f[p] = float(double(f[p]) + k * range);
            const std::string setting = k == 0 ? "scalar" : "scalar + " + std::to_string(int(k)) + " ranges";
            const BufferPtr back = k == 0 ? scalarHalf_ : store(*shifted, {}, zipHalf, setting);
            const float* b = back->requireFloat(k == 0 ? s_.colorField : "field");
            double maxErr = 0, sumSq = 0;
            std::size_t n = 0, nanMismatch = 0;
            for (std::size_t p = 0; p < gbuffer_->pixelCount(); ++p) {
                if (std::isnan(f[p]) != std::isnan(b[p])) ++nanMismatch;
                if (!std::isfinite(f[p]) || !std::isfinite(b[p])) continue;
                const double e = std::abs(double(f[p]) - double(b[p])) / range;
                maxErr = std::max(maxErr, e);
                sumSq += e * e;
                ++n;
            }
            Row r = row("zip half", setting, "max_error_of_range", maxErr);
            r.quality = k;
            csv_.add(r);
            r.metric = "rmse_of_range";
            r.value = n ? std::sqrt(sumSq / double(n)) : 0.0;
            csv_.add(r);
            r.metric = "nan_mismatch";
            r.value = double(nanMismatch);
            csv_.add(r);
        }
    }

    void angularRows(const std::string& method, const std::string& setting, const Buffer& normals,
                     double msPerMpix) {
        const auto stats = metrics::split(masks_, [&](const std::uint8_t* m) {
            return metrics::angularError(normals, *gbuffer_, {"N.x", "N.y", "N.z"}, m);
        });
        const std::pair<const char*, const metrics::AngularStats*> regions[] = {
            {"all", &stats.all}, {"edge", &stats.edge}, {"interior", &stats.interior}};
        for (const auto& [region, st] : regions) {
            for (const auto& [metric, value] : {std::pair<std::string, double>{"angle_mean", st->mean},
                                                {"angle_median", st->median},
                                                {"angle_p95", st->p95},
                                                {"share_above_5", st->shareAbove5},
                                                {"pixels", double(st->count)}}) {
                Row r = row(method, setting, metric, value, region);
                r.msPerMpix = msPerMpix;
                csv_.add(r);
            }
        }
    }

    // Reconstructs normals from Z with the Normals pass; rows with its time.
    void reconstruct(const BufferPtr& z, const std::string& source) {
        for (const std::string method : {"central", "extrapolated"}) {
            const std::map<std::string, Value> params = {{"method", Value(method)}};
            BufferPtr normals;
            const double ms = h_.msPerMpix([&] { normals = h_.runPass("Normals", z, params); }, z->pixelCount());
            angularRows(method, source, *normals, ms);
            if (source == "captured") perObject(method, *normals);
        }
    }

    // In a scene of several objects (the demo), the error on each object's
    // pixels alone: surfaces and thin features fail differently.
    void perObject(const std::string& method, const Buffer& normals) {
        const auto& objects = s_.scene->objects;
        if (objects.size() < 2) return;
        const std::uint32_t* ids = gbuffer_->requireUInt("objectId");
        std::vector<std::uint8_t> mask(gbuffer_->pixelCount());
        for (std::size_t o = 0; o < objects.size(); ++o) {
            for (std::size_t p = 0; p < mask.size(); ++p) mask[p] = ids[p] == o;
            const auto st = metrics::angularError(normals, *gbuffer_, {"N.x", "N.y", "N.z"}, mask.data());
            const std::string setting = "captured, " + objects[o].name + " only";
            for (const auto& [metric, value] : {std::pair<std::string, double>{"angle_median", st.median},
                                                {"angle_p95", st.p95},
                                                {"share_above_5", st.shareAbove5},
                                                {"pixels", double(st.count)}})
                csv_.add(row(method, setting, metric, value));
        }
    }

    void measureNormals() {
        // Stored normals read back: float32 must be exact, half shows its cost.
        angularRows("N float32", "zip", *nFloat_, 0.0);
        angularRows("N half", "zip half", *nHalf_, 0.0);

        const BufferPtr captured = subset(*gbuffer_, {"Z"}, {"Z"});
        reconstruct(captured, "captured");
        // Z stays float32 under every variant and the compressions used are
        // lossless, so a stored Z reconstructs exactly like the captured one;
        // checked bit for bit here (1 = identical), reconstructed again only
        // if not.
        for (const auto& [name, back] : zBack_) {
            const bool same = sameBits(*captured, *back, "Z");
            csv_.add(row("Z read back", name, "z_bitwise_equal", same ? 1.0 : 0.0));
            if (!same) reconstruct(subset(*back, {"Z"}, {"Z"}), name);
        }
        reconstruct(zHalf_, "zip half (Z as half)");
    }

    Harness& h_;
    Csv& csv_;
    const stress::StressScene& s_;
    TempDir tmp_;
    BufferPtr gbuffer_;
    metrics::EdgeMasks masks_;
    std::vector<std::pair<std::string, BufferPtr>> zBack_;
    BufferPtr nFloat_, nHalf_, scalarHalf_, zHalf_;
};

void sweepStorage(Harness& h, Csv& csv) {
    for (const stress::StressScene& s : scenes(h.options())) StorageSweep(h, csv, s).run();
}

}  // namespace

DARKROOM_ACCURACY_SWEEP("storage",
                        "bytes per entry of each G-buffer channel under each EXR compression and half floats, "
                        "against the accuracy of normals reconstructed from depth",
                        sweepStorage);

}  // namespace darkroom::accuracy
