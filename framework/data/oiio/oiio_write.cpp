// A Buffer -> any format OpenImageIO writes: EXR (every channel, exact) or an
// 8-bit sRGB file. Part of the OpenImageIO module (module.h); the framework
// writes EXR and PNG itself.
#include "module.h"
#include "oiio_metadata.h"

#include "../src/io/eight_bit.h"
#include "../src/io/oiio_message.h"

#include <darkroom/atomic_file.h>
#include <darkroom/error.h>
#include <darkroom/srgb.h>
#include <darkroom/channel_text.h>

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>

#include <Imath/half.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>

namespace darkroom::oiio_module {

namespace {

namespace fs = std::filesystem;

[[noreturn]] void fail(const std::string& path, const std::string& why) {
    throw Error("cannot write image '" + path + "': " + why);
}

void checkCompression(const std::string& path, const std::string& compression) {
    static const char* const known[] = {"none", "rle", "zips", "zip", "piz", "pxr24", "b44", "b44a", "dwaa", "dwab"};
    const std::string base = compression.substr(0, compression.find(':'));
    for (const char* k : known)
        if (base == k) return;
    fail(path, "unknown EXR compression '" + compression +
                   "' (expected none, rle, zips, zip, piz, pxr24, b44, b44a, dwaa or dwab)");
}

// Formats whose OpenImageIO writer encodes correctly into memory (TIFF's,
// in OpenImageIO 2.4, writes a file without its image directory there).
bool encodesInMemory(OIIO::ImageOutput& out) {
    const std::string name = out.format_name();
    return out.supports("ioproxy") && (name == "openexr" || name == "png" || name == "jpeg");
}

// OpenImageIO's stdio writes can drop a failure: a temporary file it wrote
// must at least open again as an image before it replaces anything.
bool reopens(const std::string& file) {
    auto in = OIIO::ImageInput::open(file);
    if (!in) {
        (void)OIIO::geterror();
        return false;
    }
    in->close();
    return true;
}

// Writes `spec` and the native-layout pixels, then renames into place. A
// format encoded in memory is written by writeFileAtomic, every write, fsync
// and close checked; the others write a temporary file themselves, which
// must reopen before commitFile syncs and renames it.
void writeAtomically(const std::string& path, OIIO::ImageOutput& out, const OIIO::ImageSpec& spec,
                     OIIO::TypeDesc format, const void* pixels) {
    const bool inMemory = encodesInMemory(out);
    std::vector<unsigned char> bytes;
    OIIO::Filesystem::IOVecOutput memory(bytes);
    const std::string target = inMemory ? path : createTemporaryFile(path);
    auto oiioFail = [&]() {
        const std::string e = io::oneLine(out.geterror());
        std::error_code ec;
        if (!inMemory) fs::remove(target, ec);
        fail(path, e);
    };
    if (inMemory && !out.set_ioproxy(&memory)) oiioFail();
    if (!out.open(target, spec)) oiioFail();
    if (!out.write_image(format, pixels)) {
        out.close();
        oiioFail();
    }
    if (!out.close()) oiioFail();
    if (inMemory) {
        writeFileAtomic(path, std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size()));
        return;
    }
    std::error_code ec;
    if (fs::file_size(target, ec) == 0 || ec || !reopens(target)) {
        fs::remove(target, ec);
        fail(path, "the file OpenImageIO wrote is empty or unreadable (a failed write it did not report)");
    }
    commitFile(target, path);
}

void writeExr(const Buffer& image, const std::string& path, const ImageWriteOptions& options,
              OIIO::ImageOutput& out) {
    checkCompression(path, options.compression);
    std::vector<ChannelDesc> channels;
    if (options.channels.empty()) {
        channels = image.channels();
    } else {
        for (const auto& name : options.channels) {
            const auto type = image.channelType(name);
            if (!type) fail(path, "the image has no channel '" + name + "'; it has " + channelListText(image, true));
            channels.push_back({name, *type});
        }
    }
    if (channels.empty()) fail(path, "the image has no channels");
    const int n = int(channels.size());

    OIIO::ImageSpec spec(image.width(), image.height(), n, OIIO::TypeDesc::FLOAT);
    spec.channelnames.clear();
    std::vector<std::size_t> offset(channels.size());
    std::size_t pixelBytes = 0;
    for (int c = 0; c < n; ++c) {
        const ChannelDesc& ch = channels[std::size_t(c)];
        spec.channelnames.push_back(ch.name);
        const bool half = options.halfFloat && ch.type == ChannelType::Float32 && ch.name != "Z";
        const OIIO::TypeDesc t = ch.type == ChannelType::UInt32 ? OIIO::TypeDesc::UINT32
                                 : half                         ? OIIO::TypeDesc::HALF
                                                                : OIIO::TypeDesc::FLOAT;
        spec.channelformats.push_back(t);
        offset[std::size_t(c)] = pixelBytes;
        pixelBytes += t.size();
        if (ch.name == "A") spec.alpha_channel = c;
        if (ch.name == "Z") spec.z_channel = c;
    }
    spec.attribute("compression", options.compression);
    // OpenImageIO stamps EXR files with the current time (capDate) unless a
    // DateTime is given. An empty one keeps products reproducible: the same
    // buffer always gives the same bytes, which a resumed Cinema capture
    // relies on to end identical to an uninterrupted one.
    spec.attribute("DateTime", "");
    std::vector<std::string> order;
    for (const auto& c : channels) order.push_back(c.name);
    io::putMetadata(image.metadata(), order, spec);

    // Native layout: pixel-interleaved, each channel in its file type.
    const std::size_t pixels = image.pixelCount();
    std::vector<unsigned char> data(pixels * pixelBytes);
    for (int c = 0; c < n; ++c) {
        const ChannelDesc& ch = channels[std::size_t(c)];
        unsigned char* dst = data.data() + offset[std::size_t(c)];
        if (spec.channelformats[std::size_t(c)] == OIIO::TypeDesc::HALF) {
            const float* src = image.hostFloat(ch.name);
            for (std::size_t p = 0; p < pixels; ++p) {
                const Imath::half h(src[p]);
                std::memcpy(dst + p * pixelBytes, &h, sizeof h);
            }
        } else {
            const void* src = ch.type == ChannelType::UInt32 ? static_cast<const void*>(image.hostUInt(ch.name))
                                                             : static_cast<const void*>(image.hostFloat(ch.name));
            const unsigned char* s = static_cast<const unsigned char*>(src);
            for (std::size_t p = 0; p < pixels; ++p) std::memcpy(dst + p * pixelBytes, s + p * 4, 4);
        }
    }
    writeAtomically(path, out, spec, OIIO::TypeUnknown, data.data());
}

void writeEightBit(const Buffer& image, const std::string& path, const ImageWriteOptions& options,
                   OIIO::ImageOutput& out) {
    const io::EightBitPixels pixels = io::encodeEightBit(image, path, options, out.supports("alpha"));
    const int n = pixels.channels;
    OIIO::ImageSpec spec(image.width(), image.height(), n, OIIO::TypeDesc::UINT8);
    spec.channelnames.clear();
    static const char* const grey[] = {"Y", "A"};
    static const char* const rgba[] = {"R", "G", "B", "A"};
    for (int c = 0; c < n; ++c) spec.channelnames.emplace_back(n <= 2 ? grey[c] : rgba[c]);
    spec.alpha_channel = pixels.alpha ? n - 1 : -1;
    spec.attribute("oiio:ColorSpace", "sRGB");
    // The data is straight alpha: OIIO must not divide it by alpha again.
    spec.attribute("oiio:UnassociatedAlpha", 1);
    writeAtomically(path, out, spec, OIIO::TypeDesc::UINT8, pixels.data.data());
}

}  // namespace

void writeImage(const Buffer& image, const std::string& path, const ImageWriteOptions& options) {
    if (image.width() <= 0 || image.height() <= 0) fail(path, "the image is empty");
    const fs::path parent = fs::path(path).parent_path();
    std::error_code ec;
    if (!parent.empty() && !fs::is_directory(parent, ec))
        fail(path, "the folder '" + parent.string() + "' does not exist");
    auto out = OIIO::ImageOutput::create(path);
    if (!out) {
        fail(path, "no image format for this file name (" + io::oneLine(OIIO::geterror()) + ")");
    }
    if (std::string(out->format_name()) == "openexr")
        writeExr(image, path, options, *out);
    else
        writeEightBit(image, path, options, *out);
}

}  // namespace darkroom::oiio_module
