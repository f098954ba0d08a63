// Any OpenImageIO-readable file -> a planar Buffer (see image_io.h), and its
// header alone. Part of the OpenImageIO module (module.h).
#include "module.h"
#include "oiio_metadata.h"
#include "png_chunks.h"

#include "../src/io/oiio_message.h"

#include <darkroom/error.h>
#include <darkroom/input_file.h>
#include <darkroom/limits.h>
#include <darkroom/srgb.h>

#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <set>

namespace darkroom::oiio_module {

namespace {

namespace fs = std::filesystem;

[[noreturn]] void fail(const std::string& path, const std::string& why) {
    throw Error("cannot read image '" + path + "': " + why);
}

// What a file channel becomes in the buffer.
enum class Kind { Float, UInt, Normalised };

Kind kindOf(OIIO::TypeDesc t) {
    if (t.basetype == OIIO::TypeDesc::FLOAT || t.basetype == OIIO::TypeDesc::HALF ||
        t.basetype == OIIO::TypeDesc::DOUBLE)
        return Kind::Float;
    // 32-bit integers are ids or counts, never colour.
    if (t.basetype == OIIO::TypeDesc::UINT32 || t.basetype == OIIO::TypeDesc::INT32) return Kind::UInt;
    return Kind::Normalised;
}

std::string oiioError(OIIO::ImageInput* in) {
    std::string e = in ? in->geterror() : OIIO::geterror();
    if (in) OIIO::geterror();  // clear any global message too
    return io::oneLine(e);
}

bool taggedLinear(const OIIO::ImageSpec& spec) {
    std::string cs = spec.get_string_attribute("oiio:ColorSpace");
    std::transform(cs.begin(), cs.end(), cs.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    return cs == "linear" || cs == "scene_linear" || cs == "lin_srgb";
}

// Puts the channels in `order` when it names exactly the file's channels.
std::vector<int> channelPermutation(const std::vector<std::string>& names,
                                    const std::vector<std::string>& order) {
    std::vector<int> perm(names.size());
    for (std::size_t i = 0; i < names.size(); ++i) perm[i] = int(i);
    if (order.size() != names.size()) return perm;
    if (std::set<std::string>(order.begin(), order.end()) != std::set<std::string>(names.begin(), names.end()))
        return perm;
    for (std::size_t i = 0; i < order.size(); ++i)
        perm[i] = int(std::find(names.begin(), names.end(), order[i]) - names.begin());
    return perm;
}

}  // namespace

std::shared_ptr<WritableBuffer> readImage(const std::string& path) {
    std::error_code ec;
    if (!fs::exists(path, ec)) fail(path, "no such file");
    requireRegularFile(path, "image");  // a FIFO or a device would block OpenImageIO
    checkPngChunks(path);

    // Straight alpha, as the graph keeps it: no premultiplication on read.
    OIIO::ImageSpec config;
    config.attribute("oiio:UnassociatedAlpha", 1);
    auto in = OIIO::ImageInput::open(path, &config);
    if (!in) fail(path, oiioError(nullptr));
    const OIIO::ImageSpec spec = in->spec();
    const bool exr = std::string(in->format_name()) == "openexr";
    if (spec.deep) fail(path, "deep images are not supported");
    if (spec.depth > 1) fail(path, "volume images are not supported");
    if (spec.nchannels <= 0 || spec.width <= 0 || spec.height <= 0) fail(path, "the image is empty");

    const int nch = spec.nchannels;
    const int w = spec.width, h = spec.height;
    // Sizes come from the header: checked before a pixel is allocated (the
    // buffer, and the scratch a run of channels is read into).
    checkImagePixels(std::uint64_t(w), std::uint64_t(h), path);
    checkBytes(Limit::DecodedBytes, std::uint64_t(w) * std::uint64_t(h) * std::uint64_t(nch) * 4, path,
               std::to_string(nch) + " channels");
    std::vector<std::string> names(static_cast<std::size_t>(nch));
    std::vector<Kind> kinds(static_cast<std::size_t>(nch));
    for (int c = 0; c < nch; ++c) {
        names[c] = c < int(spec.channelnames.size()) && !spec.channelnames[c].empty()
                       ? spec.channelnames[c]
                       : "channel" + std::to_string(c);
        kinds[c] = kindOf(spec.channelformat(c));
    }
    if (std::set<std::string>(names.begin(), names.end()).size() != names.size())
        fail(path, "two channels have the same name");

    BufferMetadata meta;
    std::vector<std::string> order;
    try {
        order = io::getMetadata(spec, meta);
    } catch (const Error& e) {
        fail(path, e.what());
    }
    const std::vector<int> perm = channelPermutation(names, order);
    std::vector<ChannelDesc> desc;
    for (int i : perm)
        desc.push_back({names[i], kinds[i] == Kind::UInt ? ChannelType::UInt32 : ChannelType::Float32});
    auto buffer = makeCpuBuffer(w, h, desc);
    buffer->metadata() = std::move(meta);

    // Read runs of channels that share a buffer type in one call each (EXR
    // decompresses a block once per call), then scatter to planar storage.
    const std::size_t pixels = std::size_t(w) * std::size_t(h);
    std::vector<std::uint32_t> scratch;
    const bool decodeSrgb = !exr && !taggedLinear(spec);
    std::array<float, 256> lut8{};
    for (int i = 0; i < 256; ++i) lut8[std::size_t(i)] = srgbToLinear(float(i) / 255.0f);
    for (int begin = 0; begin < nch;) {
        const bool isUInt = kinds[begin] == Kind::UInt;
        int end = begin + 1;
        while (end < nch && (kinds[end] == Kind::UInt) == isUInt) ++end;
        const int n = end - begin;
        scratch.resize(pixels * std::size_t(n));
        const OIIO::TypeDesc type = isUInt ? OIIO::TypeDesc::UINT32 : OIIO::TypeDesc::FLOAT;
        if (!in->read_image(0, 0, begin, end, type, scratch.data()))
            fail(path, oiioError(in.get()));
        for (int c = begin; c < end; ++c) {
            const std::size_t k = std::size_t(c - begin);
            if (isUInt) {
                std::uint32_t* dst = buffer->writeUInt(names[c]);
                for (std::size_t p = 0; p < pixels; ++p) dst[p] = scratch[p * n + k];
                continue;
            }
            float* dst = buffer->writeFloat(names[c]);
            const float* src = reinterpret_cast<const float*>(scratch.data());
            const bool alpha = c == spec.alpha_channel || names[c] == "A" || names[c] == "a";
            const bool decode = decodeSrgb && kinds[c] == Kind::Normalised && !alpha;
            const bool is8 = spec.channelformat(c).basetype == OIIO::TypeDesc::UINT8;
            for (std::size_t p = 0; p < pixels; ++p) {
                const float v = src[p * n + k];
                if (!decode)
                    dst[p] = v;
                else if (is8)
                    dst[p] = lut8[std::size_t(std::clamp(int(std::lround(v * 255.0f)), 0, 255))];
                else
                    dst[p] = srgbToLinear(v);
            }
        }
        begin = end;
    }
    if (!in->close()) fail(path, oiioError(in.get()));
    return buffer;
}

io::ImageHeader readHeader(const std::string& path) {
    requireRegularFile(path, "image");
    checkPngChunks(path);
    auto in = OIIO::ImageInput::open(path);
    if (!in) fail(path, oiioError(nullptr));
    const OIIO::ImageSpec& spec = in->spec();
    io::ImageHeader h;
    h.width = spec.width;
    h.height = spec.height;
    std::vector<std::string> names;
    for (int c = 0; c < spec.nchannels; ++c)
        names.push_back(c < int(spec.channelnames.size()) && !spec.channelnames[c].empty()
                            ? spec.channelnames[c]
                            : "channel" + std::to_string(c));
    BufferMetadata meta;
    std::vector<std::string> order;
    try {
        order = io::getMetadata(spec, meta);
    } catch (const Error&) {
        // A malformed camera is readImage()'s to report; the header is still what it is.
    }
    for (int i : channelPermutation(names, order))
        h.channels.push_back(
            {names[std::size_t(i)], kindOf(spec.channelformat(i)) == Kind::UInt ? ChannelType::UInt32 : ChannelType::Float32});
    return h;
}

}  // namespace darkroom::oiio_module
