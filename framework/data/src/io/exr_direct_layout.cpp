// The header checks of the direct EXR decoder (exr_direct_layout.h).
#include "exr_direct_layout.h"

#include <ImfChannelList.h>
#include <ImfPartType.h>

#include <cstring>
#include <string>
#include <string_view>

namespace darkroom::io::exr_direct {

namespace {

// The Core API reports errors through this callback, by default on stderr.
// Silent: a file the direct decoder cannot read goes to OpenEXR's C++ library,
// whose messages readExr words.
void quiet(exr_const_context_t, exr_result_t, const char*) {}

// Lines per chunk of the compressions decoded here; 0 for the others. The
// C++ library's compression must be the same one.
int linesPerChunkOf(exr_compression_t c, Imf::Compression seen) {
    switch (c) {
        case EXR_COMPRESSION_NONE: return seen == Imf::NO_COMPRESSION ? 1 : 0;
        case EXR_COMPRESSION_ZIPS: return seen == Imf::ZIPS_COMPRESSION ? 1 : 0;
        case EXR_COMPRESSION_ZIP: return seen == Imf::ZIP_COMPRESSION ? 16 : 0;
        default: return 0;
    }
}

bool sameType(exr_pixel_type_t core, Imf::PixelType seen) {
    return (core == EXR_PIXEL_UINT && seen == Imf::UINT) || (core == EXR_PIXEL_HALF && seen == Imf::HALF) ||
           (core == EXR_PIXEL_FLOAT && seen == Imf::FLOAT);
}

// One part of scan lines in increasing y (decreasing y would store the
// chunks the other way round; nobody writes it), with the C++ library's data
// window.
bool storageFits(exr_const_context_t ctx, const Imf::Header& header, Window& window) {
    int parts = 0;
    exr_storage_t storage{};
    exr_lineorder_t order{};
    exr_attr_box2i_t dw{};
    if (exr_get_count(ctx, &parts) != EXR_ERR_SUCCESS || parts != 1) return false;
    if (header.hasTileDescription() || (header.hasType() && header.type() != Imf::SCANLINEIMAGE)) return false;
    if (exr_get_storage(ctx, 0, &storage) != EXR_ERR_SUCCESS || storage != EXR_STORAGE_SCANLINE) return false;
    if (exr_get_lineorder(ctx, 0, &order) != EXR_ERR_SUCCESS || order != EXR_LINEORDER_INCREASING_Y ||
        header.lineOrder() != Imf::INCREASING_Y)
        return false;
    const Imath::Box2i seen = header.dataWindow();
    if (exr_get_data_window(ctx, 0, &dw) != EXR_ERR_SUCCESS || dw.min.x != seen.min.x || dw.min.y != seen.min.y ||
        dw.max.x != seen.max.x || dw.max.y != seen.max.y || dw.max.x < dw.min.x || dw.max.y < dw.min.y)
        return false;
    const std::int64_t w = std::int64_t(dw.max.x) - dw.min.x + 1, h = std::int64_t(dw.max.y) - dw.min.y + 1;
    if (w > (1 << 30) || h > (1 << 30)) return false;  // readExr refuses these before
    window = {dw.min.x, dw.min.y, int(w), int(h)};
    return true;
}

bool chunkingFits(exr_const_context_t ctx, const Imf::Header& header, Layout& out) {
    if (exr_get_compression(ctx, 0, &out.compression) != EXR_ERR_SUCCESS) return false;
    out.linesPerChunk = linesPerChunkOf(out.compression, header.compression());
    if (out.linesPerChunk == 0) return false;
    std::int32_t perChunk = 0, chunks = 0;
    if (exr_get_scanlines_per_chunk(ctx, 0, &perChunk) != EXR_ERR_SUCCESS || perChunk != out.linesPerChunk)
        return false;
    out.chunks = int((std::int64_t(out.window.height) + out.linesPerChunk - 1) / out.linesPerChunk);
    return exr_get_chunk_count(ctx, 0, &chunks) == EXR_ERR_SUCCESS && chunks == out.chunks;
}

// The plane of a file channel: UINT into a UInt32 plane, HALF and FLOAT into
// a Float32 one, as readExr made them; null when the buffer has no such plane.
std::uint8_t* planeFor(WritableBuffer& buffer, const std::string& name, exr_pixel_type_t type) {
    const auto have = buffer.channelType(name);
    if (!have) return nullptr;
    if (type == EXR_PIXEL_UINT)
        return *have == ChannelType::UInt32 ? reinterpret_cast<std::uint8_t*>(buffer.writeUInt(name)) : nullptr;
    return *have == ChannelType::Float32 ? reinterpret_cast<std::uint8_t*>(buffer.writeFloat(name)) : nullptr;
}

// The Core API's channels, in the file's order, each with the C++ library's
// type and no subsampling, and exactly the buffer's channels.
bool channelsFit(exr_const_context_t ctx, const Imf::Header& header, WritableBuffer& buffer, Layout& out) {
    const exr_attr_chlist_t* list = nullptr;
    if (exr_get_channels(ctx, 0, &list) != EXR_ERR_SUCCESS || list == nullptr || list->num_channels <= 0) return false;
    std::size_t seenCount = 0;
    for (auto it = header.channels().begin(); it != header.channels().end(); ++it) ++seenCount;
    if (std::size_t(list->num_channels) != seenCount || seenCount != buffer.channels().size()) return false;
    out.lineBytes = 0;
    for (int c = 0; c < list->num_channels; ++c) {
        const exr_attr_chlist_entry_t& e = list->entries[c];
        if (e.name.str == nullptr || e.name.length <= 0) return false;
        const std::string name(e.name.str, std::size_t(e.name.length));
        // Sorted and distinct, as the C++ library orders them (a std::map
        // by strcmp): each buffer plane is then written once.
        if (c > 0 && std::string_view(list->entries[c - 1].name.str, std::size_t(list->entries[c - 1].name.length)) >=
                         std::string_view(name))
            return false;
        const Imf::Channel* seen = header.channels().findChannel(name);
        if (seen == nullptr || !sameType(e.pixel_type, seen->type) || e.x_sampling != 1 || e.y_sampling != 1 ||
            seen->xSampling != 1 || seen->ySampling != 1)
            return false;
        std::uint8_t* plane = planeFor(buffer, name, e.pixel_type);
        if (plane == nullptr) return false;
        const std::size_t bytes = e.pixel_type == EXR_PIXEL_HALF ? 2 : 4;
        out.channels.push_back({e.pixel_type, bytes, plane});
        out.lineBytes += bytes * std::size_t(out.window.width);
    }
    return true;
}

}  // namespace

CoreFile::CoreFile(const std::string& path) {
    exr_context_initializer_t init = EXR_DEFAULT_CONTEXT_INITIALIZER;
    init.error_handler_fn = &quiet;
    // A broken offset table goes to the C++ library, which treats it its own
    // way; the Core API would otherwise rebuild it by scanning the chunks and
    // could read chunks the C++ library does not (found by the exr harness).
    init.flags |= EXR_CONTEXT_FLAG_SILENT_HEADER_PARSE | EXR_CONTEXT_FLAG_DISABLE_CHUNK_RECONSTRUCTION;
    // On failure exr_start_read finishes the context itself.
    if (exr_start_read(&context_, path.c_str(), &init) != EXR_ERR_SUCCESS) context_ = nullptr;
}

CoreFile::~CoreFile() {
    if (context_ != nullptr) exr_finish(&context_);
}

std::optional<Layout> directLayout(const CoreFile& file, const Imf::Header& header, WritableBuffer& buffer) {
    if (!file.isOpen()) return std::nullopt;
    Layout layout;
    if (!storageFits(file.context(), header, layout.window) || layout.window.width != buffer.width() ||
        layout.window.height != buffer.height())
        return std::nullopt;
    if (!chunkingFits(file.context(), header, layout) || !channelsFit(file.context(), header, buffer, layout))
        return std::nullopt;
    return layout;
}

}  // namespace darkroom::io::exr_direct
