// The direct EXR decoder (exr_direct.h): raw chunks through OpenEXR's Core C
// API, inflated by libdeflate, the zip pre-pass undone, lines written into
// the planes; chunks in parallel.
#include "exr_direct.h"

#include "exr_direct_layout.h"
#include "exr_zip.h"

#include <Imath/half.h>
#include <libdeflate.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <atomic>
#include <cstring>
#include <memory>
#include <vector>

namespace darkroom::io {

namespace {

using exr_direct::ChannelTarget;
using exr_direct::CoreFile;
using exr_direct::Layout;

struct DecompressorDeleter {
    void operator()(libdeflate_decompressor* d) const { libdeflate_free_decompressor(d); }
};

// One thread's working memory: a decompressor (not shareable between
// threads) and the chunk as read, as inflated and as restored. Grown to the
// largest chunk once and kept for the thread's life (a few hundred KiB per
// thread): made afresh for each file, the vectors' zeroing and the pages the
// kernel had to clear for them came back with every --foreach entry.
struct Scratch {
    std::unique_ptr<libdeflate_decompressor, DecompressorDeleter> inflater{libdeflate_alloc_decompressor()};
    std::vector<std::uint8_t> packed, inflated, raw;
};

// One line of a channel, as stored (little-endian, as this machine is), into
// its plane's row. HALF is widened with Imath's conversion, the one OpenEXR's
// C++ library uses, so that the pixels (NaN payloads included) are the same.
void copyLine(const ChannelTarget& c, const std::uint8_t* src, int width, std::uint8_t* row) {
    if (c.type != EXR_PIXEL_HALF) {
        std::memcpy(row, src, std::size_t(width) * 4);
        return;
    }
    float* out = reinterpret_cast<float*>(row);
    for (int x = 0; x < width; ++x) {
        std::uint16_t bits;
        std::memcpy(&bits, src + 2 * std::size_t(x), 2);
        out[x] = imath_half_to_float(bits);
    }
}

// A chunk's lines, each channel's whole line after the other (in the file's
// channel order), into the planes' rows.
void scatterLines(const Layout& layout, int firstRow, int lines, const std::uint8_t* raw) {
    const std::size_t width = std::size_t(layout.window.width);
    for (int l = 0; l < lines; ++l) {
        const std::size_t row = std::size_t(firstRow + l);
        for (const ChannelTarget& c : layout.channels) {
            copyLine(c, raw, layout.window.width, c.plane + row * width * 4);
            raw += c.bytesPerSample * width;
        }
    }
}

// The chunk's info from its offset-table entry and leader, checked against
// what the header says it must be: its first line, its line count, its size.
bool chunkInfo(exr_const_context_t ctx, const Layout& layout, int chunk, exr_chunk_info_t& info) {
    const int firstRow = chunk * layout.linesPerChunk;
    const int lines = std::min(layout.linesPerChunk, layout.window.height - firstRow);
    const int y = layout.window.y0 + firstRow;  // no overflow: the window is checked against the header's
    if (exr_read_scanline_chunk_info(ctx, 0, y, &info) != EXR_ERR_SUCCESS) return false;
    const std::uint64_t expected = std::uint64_t(lines) * layout.lineBytes;
    return info.start_y == y && info.height == lines && info.width == layout.window.width &&
           info.compression == std::uint8_t(layout.compression) && info.unpacked_size == expected &&
           info.packed_size > 0 && info.packed_size <= expected;
}

// The chunk's bytes as stored before compression: the chunk itself when it
// was kept uncompressed (OpenEXR stores a chunk as is when compressing would
// not make it smaller: packed size = unpacked size), else inflated and the
// zip pre-pass undone. Null when anything does not add up.
const std::uint8_t* rawChunk(exr_const_context_t ctx, const Layout& layout, const exr_chunk_info_t& info,
                             Scratch& s) {
    const std::size_t packed = std::size_t(info.packed_size), unpacked = std::size_t(info.unpacked_size);
    if (s.packed.size() < packed) s.packed.resize(packed);
    if (exr_read_chunk(ctx, 0, &info, s.packed.data()) != EXR_ERR_SUCCESS) return nullptr;
    if (packed == unpacked) return s.packed.data();
    if (layout.compression == EXR_COMPRESSION_NONE || !s.inflater) return nullptr;
    if (s.inflated.size() < unpacked) s.inflated.resize(unpacked);
    if (s.raw.size() < unpacked) s.raw.resize(unpacked);
    std::size_t in = 0, out = 0;
    if (libdeflate_zlib_decompress_ex(s.inflater.get(), s.packed.data(), packed, s.inflated.data(), unpacked, &in,
                                      &out) != LIBDEFLATE_SUCCESS ||
        in != packed || out != unpacked)
        return nullptr;
    undoZipPrepass(s.inflated.data(), unpacked, s.raw.data());
    return s.raw.data();
}

bool decodeChunk(exr_const_context_t ctx, const Layout& layout, int chunk, Scratch& s) {
    exr_chunk_info_t info{};
    if (!chunkInfo(ctx, layout, chunk, info)) return false;
    const std::uint8_t* raw = rawChunk(ctx, layout, info, s);
    if (raw == nullptr) return false;
    scatterLines(layout, chunk * layout.linesPerChunk, info.height, raw);
    return true;
}

}  // namespace

bool readExrDirect(const std::string& path, const Imf::Header& header, WritableBuffer& buffer) {
    const CoreFile file(path);
    const std::optional<Layout> layout = exr_direct::directLayout(file, header, buffer);
    if (!layout) return false;
    const exr_const_context_t ctx = file.context();
    // The first chunk's info on this thread: it loads the offset table
    // (the Core API loads it once, whichever thread asks first) and sends a
    // file whose table is broken to the C++ library before any work is done.
    exr_chunk_info_t first{};
    if (!chunkInfo(ctx, *layout, 0, first)) return false;

    std::atomic<bool> failed{false};
    tbb::parallel_for(tbb::blocked_range<int>(0, layout->chunks), [&](const tbb::blocked_range<int>& range) {
        static thread_local Scratch s;
        for (int chunk = range.begin(); chunk != range.end(); ++chunk) {
            if (failed.load(std::memory_order_relaxed)) return;
            if (!decodeChunk(ctx, *layout, chunk, s)) failed.store(true, std::memory_order_relaxed);
        }
    });
    return !failed.load();
}

}  // namespace darkroom::io
