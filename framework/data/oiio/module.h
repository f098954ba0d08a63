#pragma once
// The OpenImageIO module: every image format besides the framework's own EXR
// and PNG code, in a library of its own (libdarkroom-oiio.so) that the
// framework opens on first use (framework/data/src/io/optional_module.cpp). Linking
// OpenImageIO loads ~260 shared libraries whose start-up costs ~130 MB and a
// few hundred milliseconds; a run that reads and writes only EXR and PNG
// never pays it.
#include "../src/io/image_header.h"

#include <darkroom/buffer.h>
#include <darkroom/data/image_io.h>

#include <memory>
#include <string>

namespace darkroom::oiio_module {

std::shared_ptr<WritableBuffer> readImage(const std::string& path);
io::ImageHeader readHeader(const std::string& path);
void writeImage(const Buffer& image, const std::string& path, const ImageWriteOptions& options);

// What the module's one exported symbol returns. `version` comes first (the
// loader reads it before anything else) and changes whenever
// this struct or the functions' signatures do; the framework refuses another.
struct Entry {
    int version;
    std::shared_ptr<WritableBuffer> (*readImage)(const std::string& path);
    io::ImageHeader (*readHeader)(const std::string& path);
    void (*writeImage)(const Buffer& image, const std::string& path, const ImageWriteOptions& options);
};
constexpr int kEntryVersion = 1;
constexpr const char* kEntrySymbol = "darkroom_oiio_module";

}  // namespace darkroom::oiio_module
