#include "layers_storage.h"

#include <darkroom/data/image_io.h>
#include <darkroom/error.h>
#include <darkroom/layers.h>

#include <OpenImageIO/deepdata.h>
#include <OpenImageIO/imageio.h>

#include <chrono>
#include <cmath>
#include <cstring>
#include <ctime>
#include <filesystem>
#include <map>

namespace darkroom::bench {

namespace {

namespace oiio = OIIO;

double now() {
    return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

// The channels of one layer (layer 0's names) and their types.
std::vector<ChannelDesc> perLayer(const Buffer& g) {
    std::vector<ChannelDesc> out;
    for (const auto& ch : g.channels())
        if (layers::parse(ch.name).first == 0) out.push_back(ch);
    return out;
}

// A deep image holds one sample per crossing; a pixel's samples are its
// layers whose depth is finite (layers are front to back, so they come first).
void writeDeep(const Buffer& g, const std::string& path, const std::string& compression) {
    const std::vector<ChannelDesc> chans = perLayer(g);
    const int k = layers::count(g);
    oiio::ImageSpec spec(g.width(), g.height(), int(chans.size()), oiio::TypeDesc::FLOAT);
    spec.deep = true;
    spec.channelnames.clear();
    spec.channelformats.clear();
    for (std::size_t c = 0; c < chans.size(); ++c) {
        spec.channelnames.push_back(chans[c].name);
        spec.channelformats.push_back(chans[c].type == ChannelType::UInt32 ? oiio::TypeDesc::UINT32 : oiio::TypeDesc::FLOAT);
        if (chans[c].name == "Z") spec.z_channel = int(c);
    }
    spec.attribute("compression", compression);
    oiio::DeepData deep(spec);
    const std::size_t n = g.pixelCount();
    std::vector<const float*> z(std::size_t(k), nullptr);
    for (int l = 0; l < k; ++l) z[std::size_t(l)] = g.hostFloat(layers::channel("Z", l));
    std::vector<unsigned> samples(n);
    for (std::size_t i = 0; i < n; ++i) {
        int s = 0;
        while (s < k && std::isfinite(z[std::size_t(s)][i])) ++s;
        samples[i] = unsigned(s);
    }
    deep.set_all_samples(samples);
    for (std::size_t c = 0; c < chans.size(); ++c)
        for (int l = 0; l < k; ++l) {
            const std::string name = layers::channel(chans[c].name, l);
            const void* plane = chans[c].type == ChannelType::UInt32 ? static_cast<const void*>(g.hostUInt(name))
                                                                       : static_cast<const void*>(g.hostFloat(name));
            for (std::size_t i = 0; i < n; ++i)
                if (unsigned(l) < samples[i]) std::memcpy(deep.data_ptr(int64_t(i), int(c), l), static_cast<const char*>(plane) + 4 * i, 4);
        }
    auto out = oiio::ImageOutput::create(path);
    if (!out || !out->open(path, spec) || !out->write_deep_image(deep) || !out->close())
        throw Error("bench_layers: cannot write the deep EXR " + path + ": " + (out ? out->geterror() : oiio::geterror()));
}

// Reads a deep file back into the flat layout: K sets of planes, missing
// layers filled as a capture fills them (Z = +inf, NaN, 0xffffffff).
// planes[c * k + l] is channel c (in the file's order; Z is first) of layer l.
std::vector<std::vector<std::uint32_t>> readDeep(const std::string& path, int k) {
    auto in = oiio::ImageInput::open(path);
    oiio::DeepData deep;
    if (!in || !in->read_native_deep_image(0, 0, deep))
        throw Error("bench_layers: cannot read the deep EXR " + path + ": " + (in ? in->geterror() : oiio::geterror()));
    const oiio::ImageSpec& spec = in->spec();
    const std::size_t n = std::size_t(spec.width) * std::size_t(spec.height);
    std::vector<std::vector<std::uint32_t>> planes(std::size_t(spec.nchannels) * std::size_t(k));
    for (int c = 0; c < spec.nchannels; ++c) {
        const bool ids = spec.channelformat(c) == oiio::TypeDesc::UINT32;
        const float inf = std::numeric_limits<float>::infinity(), nan = std::numeric_limits<float>::quiet_NaN();
        std::uint32_t missing;
        std::memcpy(&missing, spec.channelnames[std::size_t(c)] == "Z" ? &inf : &nan, 4);
        if (ids) missing = 0xFFFFFFFFu;
        for (int l = 0; l < k; ++l) {
            auto& plane = planes[std::size_t(c) * std::size_t(k) + std::size_t(l)];
            plane.assign(n, missing);
            for (std::size_t i = 0; i < n; ++i)
                if (l < deep.samples(int64_t(i))) std::memcpy(&plane[i], deep.data_ptr(int64_t(i), c, l), 4);
        }
    }
    return planes;
}

double cpuNow() {
    timespec ts;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
    return double(ts.tv_sec) + 1e-9 * double(ts.tv_nsec);
}

std::size_t fileBytes(const std::string& path) { return std::size_t(std::filesystem::file_size(path)); }

}  // namespace

double meanCrossings(const Buffer& g) {
    double finite = 0;
    for (int l = 0; l < layers::count(g); ++l) {
        const float* z = g.hostFloat(layers::channel("Z", l));
        for (std::size_t i = 0; i < g.pixelCount(); ++i) finite += std::isfinite(z[i]);
    }
    return finite / double(g.pixelCount());
}

std::vector<StorageFigure> measureStorage(const Buffer& g, const std::string& dir, int reps) {
    const int k = layers::count(g);
    std::vector<StorageFigure> out;
    auto best = [](double& wall, double& cpu, double wall0, double cpu0) {
        wall = std::min(wall, now() - wall0);
        cpu = std::min(cpu, cpuNow() - cpu0);
    };
    for (const std::string compression : {"zip", "zips"}) {
        StorageFigure flat{"flat " + compression, 0, 1e30, 1e30, 1e30, 1e30};
        const std::string path = dir + "/flat-" + compression + ".exr";
        ImageWriteOptions options;
        options.compression = compression;
        for (int r = 0; r < reps; ++r) {
            double w0 = now(), c0 = cpuNow();
            writeImage(g, path, options);
            best(flat.writeSeconds, flat.writeCpu, w0, c0);
            w0 = now(), c0 = cpuNow();
            const auto back = readImage(path);
            best(flat.readSeconds, flat.readCpu, w0, c0);
            if (std::memcmp(back->hostFloat("layer1.Z"), g.hostFloat("layer1.Z"), 4 * g.pixelCount()) != 0)
                throw Error("bench_layers: the flat EXR did not keep layer1.Z");
        }
        flat.bytes = fileBytes(path);
        out.push_back(flat);
    }
    // OpenEXR compresses deep scanlines with none, rle or zips only
    // (OpenImageIO writes zips when asked for zip).
    StorageFigure deep{"deep zips", 0, 1e30, 1e30, 1e30, 1e30};
    const std::string path = dir + "/deep-zips.exr";
    for (int r = 0; r < reps; ++r) {
        double w0 = now(), c0 = cpuNow();
        writeDeep(g, path, "zips");
        best(deep.writeSeconds, deep.writeCpu, w0, c0);
        w0 = now(), c0 = cpuNow();
        const auto planes = readDeep(path, k);
        best(deep.readSeconds, deep.readCpu, w0, c0);
        if (std::memcmp(planes[1].data(), g.hostFloat("layer1.Z"), 4 * g.pixelCount()) != 0)
            throw Error("bench_layers: the deep EXR did not keep layer1.Z");
    }
    deep.bytes = fileBytes(path);
    out.push_back(deep);
    return out;
}

}  // namespace darkroom::bench
