#pragma once
// What the direct EXR decoder (exr_direct.h) needs to know of a file, read
// from its header with OpenEXR's Core C API, and whether it can take the file
// at all. Internal to the data library.
#include "exr_direct.h"

#include <openexr.h>

#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

namespace darkroom::io::exr_direct {

// The Core API's read context for one file, finished on every way out. The
// header is parsed when it opens; reading chunks from it afterwards is
// documented as safe from several threads at once.
class CoreFile {
public:
    explicit CoreFile(const std::string& path);
    ~CoreFile();
    CoreFile(const CoreFile&) = delete;
    CoreFile& operator=(const CoreFile&) = delete;

    bool isOpen() const { return context_ != nullptr; }
    exr_const_context_t context() const { return context_; }

private:
    exr_context_t context_ = nullptr;
};

// One channel of the file, in the file's order, and the plane its samples go to.
struct ChannelTarget {
    exr_pixel_type_t type;
    std::size_t bytesPerSample;  // in the file: 2 for HALF, 4 for UINT and FLOAT
    std::uint8_t* plane;         // the buffer's plane (float or uint32), row 0
};

// The data window as readExr lays it out: buffer pixel (0, 0) is the file's
// pixel (x0, y0).
struct Window {
    int x0 = 0, y0 = 0, width = 0, height = 0;
};

struct Layout {
    Window window;
    exr_compression_t compression;
    int linesPerChunk = 0;
    int chunks = 0;
    std::size_t lineBytes = 0;  // one scan line of every channel, as stored
    std::vector<ChannelTarget> channels;
};

// The layout when the direct decoder can take the file and the Core API read
// its header as OpenEXR's C++ library did (`header`; see readExrDirect),
// nothing otherwise.
std::optional<Layout> directLayout(const CoreFile& file, const Imf::Header& header, WritableBuffer& buffer);

}  // namespace darkroom::io::exr_direct
