#pragma once
// Reading and writing images. EXR goes through OpenEXR and PNG is written by
// the framework itself (libdeflate); every other format through OpenImageIO,
// in a module the framework opens the first time such a file is met
// (framework/data/oiio/module.h), so runs on EXR and PNG alone never load
// OpenImageIO's hundreds of libraries. Files are the same whichever library
// handles them.
#include <darkroom/buffer.h>
#include <darkroom/export.h>

#include <string>
#include <vector>

namespace darkroom {

struct ImageWriteOptions {
    // EXR: "none", "rle", "zips", "zip", "piz", "pxr24", "b44", "b44a", "dwaa",
    // "dwab" (optionally with a level, "dwaa:45"). pxr24, b44 and dwa are lossy.
    // Ignored by 8-bit formats.
    std::string compression = "zip";
    // EXR: store float channels (except depth "Z") as half; uint32 stays uint32.
    bool halfFloat = false;
    // 8-bit formats: the channels written as grey (1), grey+alpha (2), RGB (3)
    // or RGBA (4); they must be float32. Default: R, G, B (and A when present),
    // else Y (and A), else the one float channel besides Z and A.
    // EXR: when not empty, only these channels are written (names kept).
    std::vector<std::string> channels;
};

// Reads PNG, JPEG, TIFF, EXR (and whatever else OIIO reads), first subimage
// (EXR: first part), its data window. Only regular files are opened (a FIFO
// or a device is refused). EXR is recognised by its magic number.
// - 8/16-bit integer channels are decoded from sRGB to linear float (alpha is
//   not decoded; a file tagged linear is not decoded) and keep OIIO's names:
//   R, G, B, A, or Y (and A) for grey.
// - Float channels (EXR, float TIFF) keep their names and values; half is
//   widened to float32; uint32 stays uint32.
// - Metadata written by writeImage() comes back: the camera from the
//   darkroom:camera:* attributes, attributes from darkroom:attr:*, and the
//   channel order from darkroom:channels (EXR stores channels sorted).
// Throws darkroom::Error naming the file for a missing, unreadable or
// malformed file.
DARKROOM_API std::shared_ptr<WritableBuffer> readImage(const std::string& path);

// Writes atomically (temporary file in the same folder, then rename); the
// format follows the extension. The folder must exist. PNG is written with
// zlib level 2 and the "up" filter (fast; docs/formats.md).
// - EXR: every channel (see options.channels), float32 unless halfFloat,
//   uint32 kept. The header holds the camera as darkroom:camera:position,
//   :forward, :up (double vectors, exact), :projection ("perspective" or
//   "orthographic"), :fovY, :viewHeight (double), :width, :height (int); each
//   metadata attribute K as the string attribute darkroom:attr:K; the channel
//   order as darkroom:channels (comma separated).
// - Other formats are written 8-bit: linear -> sRGB encoded (alpha linear),
//   clamped to [0, 1], NaN written as 0, alpha straight. JPEG drops alpha.
//   No metadata is stored.
// Throws darkroom::Error naming the file.
DARKROOM_API void writeImage(const Buffer& image, const std::string& path,
                             const ImageWriteOptions& options = {});

}  // namespace darkroom
