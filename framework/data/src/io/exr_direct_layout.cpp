// The header checks of the direct EXR decoder (exr_direct_layout.h).
#include "exr_direct_layout.h"

#include <cstring>
#include <string_view>

namespace darkroom::io::exr_direct {

namespace {

// The Core API reports errors through this callback, by default on stderr.
// Silent: a file the direct decoder cannot read goes to OpenEXR's C++ library,
// whose messages readExr words.
void quiet(exr_const_context_t, exr_result_t, const char*) {}

// Lines per chunk of the compressions decoded here; 0 for the others.
int linesPerChunkOf(exr_compression_t c) {
    switch (c) {
        case EXR_COMPRESSION_NONE:
        case EXR_COMPRESSION_ZIPS: return 1;
        case EXR_COMPRESSION_ZIP: return 16;
        default: return 0;
    }
}

bool headerFits(exr_const_context_t ctx, const ExrWindow& window, Layout& out) {
    int parts = 0;
    exr_storage_t storage{};
    exr_lineorder_t order{};
    exr_attr_box2i_t dw{};
    if (exr_get_count(ctx, &parts) != EXR_ERR_SUCCESS || parts != 1) return false;
    if (exr_get_storage(ctx, 0, &storage) != EXR_ERR_SUCCESS || storage != EXR_STORAGE_SCANLINE) return false;
    if (exr_get_compression(ctx, 0, &out.compression) != EXR_ERR_SUCCESS) return false;
    // Decreasing y would store the chunks the other way round; nobody writes it.
    if (exr_get_lineorder(ctx, 0, &order) != EXR_ERR_SUCCESS || order != EXR_LINEORDER_INCREASING_Y) return false;
    if (exr_get_data_window(ctx, 0, &dw) != EXR_ERR_SUCCESS) return false;
    // The window readExr sized the buffer from (OpenEXR's C++ reading of the
    // same header) must be the one the Core API read.
    if (dw.min.x != window.x0 || dw.min.y != window.y0 || window.width <= 0 || window.height <= 0 ||
        std::int64_t(dw.max.x) - dw.min.x + 1 != window.width || std::int64_t(dw.max.y) - dw.min.y + 1 != window.height)
        return false;
    out.window = window;
    out.linesPerChunk = linesPerChunkOf(out.compression);
    if (out.linesPerChunk == 0) return false;
    std::int32_t perChunk = 0, chunks = 0;
    if (exr_get_scanlines_per_chunk(ctx, 0, &perChunk) != EXR_ERR_SUCCESS || perChunk != out.linesPerChunk)
        return false;
    out.chunks = int((std::int64_t(window.height) + out.linesPerChunk - 1) / out.linesPerChunk);
    return exr_get_chunk_count(ctx, 0, &chunks) == EXR_ERR_SUCCESS && chunks == out.chunks;
}

// The plane of a file channel: UINT into a UInt32 plane, HALF and FLOAT into
// a Float32 one, as readExr made them; null when the buffer has no such plane.
std::uint8_t* planeFor(WritableBuffer& buffer, std::string_view name, exr_pixel_type_t type) {
    const auto have = buffer.channelType(name);
    if (!have) return nullptr;
    if (type == EXR_PIXEL_UINT)
        return *have == ChannelType::UInt32 ? reinterpret_cast<std::uint8_t*>(buffer.writeUInt(name)) : nullptr;
    return *have == ChannelType::Float32 ? reinterpret_cast<std::uint8_t*>(buffer.writeFloat(name)) : nullptr;
}

bool channelsFit(exr_const_context_t ctx, WritableBuffer& buffer, Layout& out) {
    const exr_attr_chlist_t* list = nullptr;
    if (exr_get_channels(ctx, 0, &list) != EXR_ERR_SUCCESS || list == nullptr || list->num_channels <= 0) return false;
    if (std::size_t(list->num_channels) != buffer.channels().size()) return false;
    out.lineBytes = 0;
    for (int c = 0; c < list->num_channels; ++c) {
        const exr_attr_chlist_entry_t& e = list->entries[c];
        if (e.x_sampling != 1 || e.y_sampling != 1 || e.name.str == nullptr || e.name.length <= 0) return false;
        if (e.pixel_type != EXR_PIXEL_UINT && e.pixel_type != EXR_PIXEL_HALF && e.pixel_type != EXR_PIXEL_FLOAT)
            return false;
        // The list is sorted and its names distinct (the Core API refuses a
        // header otherwise), so a name matched once is matched once only.
        if (c > 0 && std::string_view(list->entries[c - 1].name.str, std::size_t(list->entries[c - 1].name.length)) >=
                         std::string_view(e.name.str, std::size_t(e.name.length)))
            return false;
        const std::string_view name(e.name.str, std::size_t(e.name.length));
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
    init.flags |= EXR_CONTEXT_FLAG_SILENT_HEADER_PARSE;
    // On failure exr_start_read finishes the context itself.
    if (exr_start_read(&context_, path.c_str(), &init) != EXR_ERR_SUCCESS) context_ = nullptr;
}

CoreFile::~CoreFile() {
    if (context_ != nullptr) exr_finish(&context_);
}

std::optional<Layout> directLayout(const CoreFile& file, const ExrWindow& window, WritableBuffer& buffer) {
    if (!file.isOpen()) return std::nullopt;
    Layout layout;
    if (!headerFits(file.context(), window, layout) || !channelsFit(file.context(), buffer, layout))
        return std::nullopt;
    return layout;
}

}  // namespace darkroom::io::exr_direct
