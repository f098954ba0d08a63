// The PNG container around libdeflate's zlib stream: chunks of length, type,
// data and CRC-32 (PNG spec, section 5), written here because libpng deflates
// with zlib only.
#include "png_encoder.h"

#include "run_deflate.h"

#include <darkroom/error.h>

#include <libdeflate.h>

#include <algorithm>
#include <cstdint>
#include <memory>
#include <new>

namespace darkroom::io {

namespace {

void putU32(std::string& out, std::uint32_t v) {
    const char bytes[4] = {char(v >> 24), char(v >> 16), char(v >> 8), char(v)};
    out.append(bytes, 4);
}

void putChunk(std::string& out, const char type[4], const char* data, std::size_t size) {
    putU32(out, std::uint32_t(size));
    const std::size_t start = out.size();
    out.append(type, 4);
    out.append(data, size);
    putU32(out, std::uint32_t(libdeflate_crc32(0, out.data() + start, size + 4)));
}

std::string bigEndian(std::initializer_list<std::uint32_t> values) {
    std::string s;
    for (auto v : values) putU32(s, v);
    return s;
}

// IHDR, then the colour space chunks libpng wrote for
// png_set_sRGB_gAMA_and_cHRM(PNG_sRGB_INTENT_PERCEPTUAL), byte for byte:
// gAMA 1/2.2 (45455), sRGB perceptual, cHRM of the sRGB primaries.
void putHeader(std::string& out, const PngPixels& px) {
    static const unsigned char colourTypes[] = {0, 4, 2, 6};  // grey, grey+alpha, RGB, RGBA
    out.append("\x89PNG\r\n\x1a\n", 8);
    std::string ihdr = bigEndian({std::uint32_t(px.width), std::uint32_t(px.height)});
    // 8 bits, colour type; compression 0 (deflate), filter method 0, no interlace.
    ihdr += {char(8), char(colourTypes[px.channels - 1]), char(0), char(0), char(0)};
    putChunk(out, "IHDR", ihdr.data(), ihdr.size());
    const std::string gama = bigEndian({45455});
    putChunk(out, "gAMA", gama.data(), gama.size());
    putChunk(out, "sRGB", "\0", 1);
    const std::string chrm = bigEndian({31270, 32900, 64000, 33000, 30000, 60000, 15000, 6000});
    putChunk(out, "cHRM", chrm.data(), chrm.size());
}

struct CompressorDeleter {
    void operator()(libdeflate_compressor* c) const { libdeflate_free_compressor(c); }
};

// Bytes left uninitialised (new[], not std::vector): at 2048² RGBA the
// filtered rows and the deflate bound are 16 MiB each, and zeroing them
// showed in the encode (123 -> 96 ms at 2048², one run on a loaded machine).
struct Bytes {
    std::unique_ptr<unsigned char[]> data;
    std::size_t size = 0;
    explicit Bytes(std::size_t n) : data(new unsigned char[n]), size(n) {}
};

// The zlib stream of rows already filtered.
Bytes deflate(const unsigned char* filtered, std::size_t size, int channels, const PngEncoding& encoding) {
    if (encoding.deflater == Deflater::Runs) {
        const std::vector<unsigned char> runs = runDeflateZlib(filtered, size, channels);
        Bytes z(runs.size());
        std::copy(runs.begin(), runs.end(), z.data.get());
        return z;
    }
    std::unique_ptr<libdeflate_compressor, CompressorDeleter> c(
        libdeflate_alloc_compressor(std::clamp(encoding.level, 0, 12)));
    if (!c) throw Error("not enough memory to encode it");
    Bytes z(libdeflate_zlib_compress_bound(c.get(), size));
    z.size = libdeflate_zlib_compress(c.get(), filtered, size, z.data.get(), z.size);
    if (z.size == 0) throw Error("libdeflate could not compress the pixels");  // the bound was too small: a bug
    return z;
}

}  // namespace

std::string encodeFilteredPng(const PngPixels& px, const unsigned char* filtered, std::size_t size,
                              const PngEncoding& encoding) {
    try {
        const Bytes z = deflate(filtered, size, px.channels, encoding);
        const char* zdata = reinterpret_cast<const char*>(z.data.get());
        std::string out;
        out.reserve(z.size + z.size / 1000 + 256);
        putHeader(out, px);
        // IDAT chunks of at most 1 MiB: any split is valid PNG; this keeps
        // the per-chunk overhead negligible and each chunk modest for
        // streaming decoders.
        constexpr std::size_t idatSize = std::size_t(1) << 20;
        for (std::size_t at = 0; at < z.size; at += idatSize)
            putChunk(out, "IDAT", zdata + at, std::min(idatSize, z.size - at));
        putChunk(out, "IEND", "", 0);
        return out;
    } catch (const std::bad_alloc&) {
        throw Error("not enough memory to encode it");
    }
}

std::string encodePng(const PngPixels& px, const PngEncoding& encoding) {
    try {
        Bytes filtered(filteredSize(px));
        filterRows(px, encoding.filter, filtered.data.get());
        return encodeFilteredPng(px, filtered.data.get(), filtered.size, encoding);
    } catch (const std::bad_alloc&) {
        throw Error("not enough memory to encode it");
    }
}

}  // namespace darkroom::io
