// EXR through the OpenEXR library (see exr_file.h for why not OpenImageIO).
#include "exr_file.h"
#include "exr_attributes.h"
#include "exr_direct.h"

#include "exr_memory_stream.h"
#include "exr_metadata.h"
#include "oiio_message.h"

#include <darkroom/atomic_file.h>
#include <darkroom/error.h>
#include <darkroom/input_file.h>
#include <darkroom/limits.h>
#include <darkroom/channel_text.h>

#include <IlmThreadPool.h>
#include <ImfChannelList.h>
#include <ImfCompression.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfInputFile.h>
#include <ImfOutputFile.h>
#include <ImfPartType.h>
#include <ImfTestFile.h>
#include <ImfThreading.h>

#include <Imath/half.h>

#include <algorithm>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <mutex>
#include <thread>

namespace darkroom::io {

namespace {

namespace fs = std::filesystem;

[[noreturn]] void failRead(const std::string& path, const std::string& why) {
    throw Error("cannot read image '" + path + "': " + why);
}
[[noreturn]] void failWrite(const std::string& path, const std::string& why) {
    throw Error("cannot write image '" + path + "': " + why);
}

// OpenEXR (de)compresses blocks of lines on its own thread pool. Sized once
// to the machine, as OpenImageIO sizes it.
void useAllCores() {
    static std::once_flag once;
    std::call_once(once, [] { Imf::setGlobalThreadCount(int(std::max(1u, std::thread::hardware_concurrency()))); });
}

// OpenImageIO orders an EXR's channels by layer (the part of the name before
// the last '.'), channels without a layer first, and within a layer puts
// R, G, B, A (and their lower-case and long forms) first, keeping the file's
// (alphabetical) order otherwise; so do we, so that a file reads the same
// whichever library reads it.
int colourRank(const std::string& n) {
    static const char* const order[][3] = {{"R", "r", "red"}, {"G", "g", "green"}, {"B", "b", "blue"},
                                           {"A", "a", "alpha"}};
    for (int k = 0; k < 4; ++k)
        for (const char* alias : order[k])
            if (n == alias) return k;
    return 4;
}

struct ChannelKey {
    std::string layer;
    int rank;
    explicit ChannelKey(const std::string& name) {
        const auto dot = name.rfind('.');
        layer = dot == std::string::npos ? std::string() : name.substr(0, dot);
        rank = colourRank(dot == std::string::npos ? name : name.substr(dot + 1));
    }
    bool operator<(const ChannelKey& o) const {
        if (layer.empty() != o.layer.empty()) return layer.empty();
        if (layer != o.layer) return layer < o.layer;
        return rank < o.rank;
    }
};

struct FileChannel {
    std::string name;
    Imf::PixelType type;
};

std::vector<FileChannel> channelsOf(const Imf::Header& header, const std::string& path) {
    std::vector<FileChannel> out;
    for (auto it = header.channels().begin(); it != header.channels().end(); ++it) {
        if (it.channel().xSampling != 1 || it.channel().ySampling != 1)
            failRead(path, std::string("channel '") + it.name() + "' is subsampled, which is not supported");
        out.push_back({it.name(), it.channel().type});
    }
    std::stable_sort(out.begin(), out.end(),
                     [](const FileChannel& a, const FileChannel& b) { return ChannelKey(a.name) < ChannelKey(b.name); });
    return out;
}

ChannelType bufferType(Imf::PixelType t) { return t == Imf::UINT ? ChannelType::UInt32 : ChannelType::Float32; }

// Puts the channels in `order` when it names exactly the file's channels.
std::vector<FileChannel> inStoredOrder(std::vector<FileChannel> channels, const std::vector<std::string>& order) {
    if (order.size() != channels.size()) return channels;
    std::vector<FileChannel> sorted;
    for (const auto& name : order) {
        auto it = std::find_if(channels.begin(), channels.end(), [&](const FileChannel& c) { return c.name == name; });
        if (it == channels.end()) return channels;
        sorted.push_back(*it);
    }
    return sorted;
}

void checkReadable(const std::string& path) {
    std::error_code ec;
    if (!fs::exists(path, ec)) failRead(path, "no such file");
    requireRegularFile(path, "image");  // a FIFO or a device would block OpenEXR
    bool tiled = false, deep = false, multiPart = false;
    if (!Imf::isOpenExrFile(path.c_str(), tiled, deep, multiPart)) failRead(path, "not an OpenEXR file");
    if (deep) failRead(path, "deep images are not supported");
    checkExrAttributeSizes(path);
}

struct Size {
    int width, height;
};

Size sizeOf(const Imf::Header& header, const std::string& path) {
    const Imath::Box2i dw = header.dataWindow();
    const long long w = (long long)dw.max.x - dw.min.x + 1, h = (long long)dw.max.y - dw.min.y + 1;
    if (w <= 0 || h <= 0) failRead(path, "the image is empty");
    if (w > (1 << 30) || h > (1 << 30)) failRead(path, "the data window is too large");
    return {int(w), int(h)};
}

Imf::Compression compressionFor(const std::string& path, const std::string& text, Imf::Header& header) {
    static const std::pair<const char*, Imf::Compression> known[] = {
        {"none", Imf::NO_COMPRESSION}, {"rle", Imf::RLE_COMPRESSION},     {"zips", Imf::ZIPS_COMPRESSION},
        {"zip", Imf::ZIP_COMPRESSION},  {"piz", Imf::PIZ_COMPRESSION},     {"pxr24", Imf::PXR24_COMPRESSION},
        {"b44", Imf::B44_COMPRESSION},  {"b44a", Imf::B44A_COMPRESSION},   {"dwaa", Imf::DWAA_COMPRESSION},
        {"dwab", Imf::DWAB_COMPRESSION}};
    const auto colon = text.find(':');
    const std::string base = text.substr(0, colon);
    for (const auto& [name, c] : known) {
        if (base != name) continue;
        if (colon != std::string::npos) {
            const std::string level = text.substr(colon + 1);
            char* end = nullptr;
            const double v = std::strtod(level.c_str(), &end);
            if (level.empty() || *end != '\0' || !(v >= 0 && v <= 1e6))
                failWrite(path, "compression level '" + level + "' must be a non-negative number");
            if (c == Imf::ZIP_COMPRESSION || c == Imf::ZIPS_COMPRESSION)
                header.zipCompressionLevel() = std::clamp(int(v), 0, 9);
            else if (c == Imf::DWAA_COMPRESSION || c == Imf::DWAB_COMPRESSION)
                header.dwaCompressionLevel() = float(v);
        }
        return c;
    }
    failWrite(path, "unknown EXR compression '" + text +
                        "' (expected none, rle, zips, zip, piz, pxr24, b44, b44a, dwaa or dwab)");
}

}  // namespace

bool isExrFile(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    unsigned char magic[4] = {};
    if (!in.read(reinterpret_cast<char*>(magic), 4)) return false;
    return magic[0] == 0x76 && magic[1] == 0x2f && magic[2] == 0x31 && magic[3] == 0x01;
}

ImageHeader readExrHeader(const std::string& path) {
    checkReadable(path);
    try {
        Imf::InputFile file(path.c_str(), 1);
        const Size size = sizeOf(file.header(), path);
        BufferMetadata meta;
        const auto order = exr::getMetadata(file.header(), meta);
        ImageHeader h;
        h.width = size.width;
        h.height = size.height;
        for (const auto& c : inStoredOrder(channelsOf(file.header(), path), order))
            h.channels.push_back({c.name, bufferType(c.type)});
        return h;
    } catch (const Error&) {
        throw;
    } catch (const std::exception& e) {
        failRead(path, oneLine(e.what(), "unknown OpenEXR error"));
    }
}

std::shared_ptr<WritableBuffer> readExr(const std::string& path, ExrPixelPath pixels) {
    checkReadable(path);
    useAllCores();
    try {
        Imf::InputFile file(path.c_str(), Imf::globalThreadCount());
        const Imf::Header& header = file.header();
        const Size size = sizeOf(header, path);
        BufferMetadata meta;
        std::vector<std::string> order;
        try {
            order = exr::getMetadata(header, meta);
        } catch (const Error& e) {
            failRead(path, e.what());
        }
        const std::vector<FileChannel> channels = inStoredOrder(channelsOf(header, path), order);
        if (channels.empty()) failRead(path, "the image has no channels");
        // From the header, before a pixel is allocated.
        checkImagePixels(std::uint64_t(size.width), std::uint64_t(size.height), path);
        checkBytes(Limit::DecodedBytes, std::uint64_t(size.width) * std::uint64_t(size.height) * channels.size() * 4,
                   path, std::to_string(channels.size()) + " channels");
        std::vector<ChannelDesc> desc;
        for (const auto& c : channels) desc.push_back({c.name, bufferType(c.type)});
        // Planes not zeroed: either path below writes every pixel (the
        // buffer is the data window), and a --foreach batch reads one file
        // per entry into planes recycled from the last (newHostPlane).
        auto buffer = makeHostBuffer(size.width, size.height);
        for (const auto& d : desc) buffer->setPlane(d, newHostPlane(buffer->pixelCount(), false));
        buffer->metadata() = std::move(meta);
        // The files Darkroom writes (ZIP, FLOAT) decode several times faster
        // without the C++ library's sample-by-sample copy (exr_direct.h);
        // the rest, and whatever the direct decoder doubts, read on below.
        if (pixels == ExrPixelPath::DirectWhenPossible && readExrDirect(path, header, *buffer)) return buffer;

        // Slices point straight into the planes: OpenEXR decodes (and widens
        // half to float) into them, no interleaved copy in between. The base
        // pointer is that of pixel (0, 0) of the data window's coordinates.
        const Imath::Box2i dw = header.dataWindow();
        const std::ptrdiff_t origin = std::ptrdiff_t(dw.min.x) + std::ptrdiff_t(dw.min.y) * size.width;
        const std::size_t yStride = std::size_t(size.width) * 4;
        Imf::FrameBuffer fb;
        for (const auto& c : channels) {
            char* base = c.type == Imf::UINT ? reinterpret_cast<char*>(buffer->writeUInt(c.name))
                                             : reinterpret_cast<char*>(buffer->writeFloat(c.name));
            fb.insert(c.name, Imf::Slice(c.type == Imf::UINT ? Imf::UINT : Imf::FLOAT, base - origin * 4, 4, yStride));
        }
        file.setFrameBuffer(fb);
        file.readPixels(dw.min.y, dw.max.y);
        return buffer;
    } catch (const Error&) {
        throw;
    } catch (const std::bad_alloc&) {
        failRead(path, "not enough memory for its pixels");
    } catch (const std::exception& e) {
        failRead(path, oneLine(e.what(), "unknown OpenEXR error"));
    }
}

void writeExr(const Buffer& image, const std::string& path, const ImageWriteOptions& options) {
    std::vector<ChannelDesc> channels;
    if (options.channels.empty()) {
        channels = image.channels();
    } else {
        for (const auto& name : options.channels) {
            const auto type = image.channelType(name);
            if (!type) failWrite(path, "the image has no channel '" + name + "'; it has " + channelListText(image, true));
            channels.push_back({name, *type});
        }
    }
    if (channels.empty()) failWrite(path, "the image has no channels");

    const int w = image.width(), h = image.height();
    Imf::Header header(w, h);
    header.compression() = compressionFor(path, options.compression, header);
    std::vector<std::string> order;
    for (const auto& c : channels) order.push_back(c.name);
    exr::putMetadata(image.metadata(), order, header);

    useAllCores();
    const std::size_t pixels = image.pixelCount();
    std::vector<std::vector<Imath::half>> halves;  // channels stored as half
    halves.reserve(channels.size());
    Imf::FrameBuffer fb;
    for (const auto& ch : channels) {
        const bool half = options.halfFloat && ch.type == ChannelType::Float32 && ch.name != "Z";
        if (ch.type == ChannelType::UInt32) {
            header.channels().insert(ch.name, Imf::Channel(Imf::UINT));
            const char* src = reinterpret_cast<const char*>(image.hostUInt(ch.name));
            fb.insert(ch.name, Imf::Slice(Imf::UINT, const_cast<char*>(src), 4, std::size_t(w) * 4));
        } else if (half) {
            header.channels().insert(ch.name, Imf::Channel(Imf::HALF));
            const float* src = image.hostFloat(ch.name);
            auto& dst = halves.emplace_back(pixels);
            for (std::size_t p = 0; p < pixels; ++p) dst[p] = Imath::half(src[p]);
            fb.insert(ch.name, Imf::Slice(Imf::HALF, reinterpret_cast<char*>(dst.data()), 2, std::size_t(w) * 2));
        } else {
            header.channels().insert(ch.name, Imf::Channel(Imf::FLOAT));
            const char* src = reinterpret_cast<const char*>(image.hostFloat(ch.name));
            fb.insert(ch.name, Imf::Slice(Imf::FLOAT, const_cast<char*>(src), 4, std::size_t(w) * 4));
        }
    }

    // Encoded in memory, then written atomically with every write checked.
    ExrMemoryStream encoded(path);
    try {
        {
            Imf::OutputFile file(encoded, header, Imf::globalThreadCount());
            file.setFrameBuffer(fb);
            file.writePixels(h);
        }  // the offset table is written here
    } catch (const std::bad_alloc&) {
        failWrite(path, "not enough memory to encode it");
    } catch (const std::exception& e) {
        failWrite(path, oneLine(e.what(), "unknown OpenEXR error"));
    }
    writeFileAtomic(path, encoded.bytes());
}

}  // namespace darkroom::io
