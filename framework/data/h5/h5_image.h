#pragma once
// pycinema's .h5 images (and the ParaView Cinema plugin's): an HDF5 file with
// a group `channels` (2-D (rows, columns) and 3-D (rows, columns, k) datasets,
// row 0 at the top) and a group `meta` (resolution, camera, other values).
// The convention and where it comes from: docs/formats.md, "pycinema's HDF5
// images". Internal to the data library: products are read through
// readCinemaProduct and written through CinemaWriter (productExtension ".h5").
#include <darkroom/buffer.h>
#include <darkroom/diagnostics.h>

#include <map>
#include <memory>
#include <string>
#include <string_view>
#include <variant>

namespace darkroom::h5 {

struct Image {
    std::shared_ptr<WritableBuffer> buffer;
    Diagnostics warnings;  // conversions stated (depth kept normalised, a resolution that disagrees)
};

// Reads an image from the bytes of an .h5 file; `name` is the file named in
// messages. Channels: `depth` (any case) becomes Z (planar, +inf background),
// `rgba` (uint8, k = 3 or 4) becomes linear R, G, B (A), an unsigned 32-bit
// dataset stays UInt32, every other one is float32 (3-D: name.0 .. name.k-1).
// Meta: the camera into metadata().camera, single numbers and strings into
// metadata().attributes. Throws InputError naming the file and what was
// expected for anything else (no `channels`, other ranks, sizes, types,
// links to other files, external or virtual storage).
Image readImage(std::string_view bytes, const std::string& name);
// The same for a file on disk (read whole, within --max-input-bytes).
Image readImageFile(const std::string& path);

// Further single values for `meta` (the entry's data.csv parameters, as
// pycinema keeps them): a number or a text.
using MetaValues = std::map<std::string, std::variant<double, std::string>>;

// The bytes of an .h5 file of `image` in the same layout (docs/formats.md).
std::string encodeImage(const Buffer& image, const MetaValues& extra = {});
// Writes them atomically (temporary file, fsync, rename). Throws Error naming the path.
void writeImageFile(const Buffer& image, const std::string& path, const MetaValues& extra = {});

}  // namespace darkroom::h5
