#pragma once
// Reading and writing images with OpenImageIO, kept behind this header so
// OIIO's heavy headers stay out of everything else.
#include <darkroom/buffer.h>
#include <darkroom/export.h>

#include <string>

namespace darkroom {

struct ImageWriteOptions {
    // EXR: "none", "zip", "piz", "zips", "rle", "dwaa"...; ignored by 8-bit formats.
    std::string compression = "zip";
    // EXR: store float channels (except depth "Z") as half.
    bool halfFloat = false;
    // 8-bit formats: which channels to write as R, G, B, A (must exist; A optional).
    // Default: R, G, B and A when present, else a single channel as grey.
    std::vector<std::string> channels;
};

// Reads PNG, JPEG, TIFF, EXR (and whatever else OIIO reads). 8-bit/16-bit
// integer images are decoded from sRGB to linear float channels named R, G,
// B, A (or Y for grey); EXR keeps every channel with its name, float32
// (half widened), uint32 stays uint32. The camera and attributes written by
// writeImage() come back in the metadata. Throws darkroom::Error naming the file.
DARKROOM_API std::shared_ptr<WritableBuffer> readImage(const std::string& path);

// Writes atomically (temporary file, then rename). EXR: every channel, float32
// unless halfFloat, uint32 kept, camera and attributes in the header. 8-bit
// formats: linear -> sRGB encoded, clamped, alpha straight. Throws darkroom::Error.
DARKROOM_API void writeImage(const Buffer& image, const std::string& path,
                             const ImageWriteOptions& options = {});

}  // namespace darkroom
