// readImage() / writeImage(): EXR and PNG with their own libraries, every
// other format through the OpenImageIO module, loaded only when one is met.
#include "io/exr_file.h"
#include "io/image_header.h"
#include "io/optional_module.h"
#include "io/png_file.h"

#include <darkroom/error.h>
#include <darkroom/data/image_io.h>
#include <darkroom/input_file.h>

#include <algorithm>
#include <cctype>
#include <filesystem>

namespace darkroom {

namespace {

namespace fs = std::filesystem;

// Before anything opens the file: a FIFO or a device would block a reader or
// never end (InputError from darkroom::requireRegularFile).
void requireImageFile(const std::string& path) {
    std::error_code ec;
    if (!fs::exists(fs::status(path, ec))) throw InputError("cannot read image '" + path + "': no such file");
    requireRegularFile(path, "image");
}

bool hasExrExtension(const std::string& path) {
    std::string ext = fs::path(path).extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    return ext == ".exr";
}

}  // namespace

std::shared_ptr<WritableBuffer> readImage(const std::string& path) {
    requireImageFile(path);
    if (io::isExrFile(path)) return io::readExr(path);
    return io::oiioModule("reading '" + path + "'").readImage(path);
}

void writeImage(const Buffer& image, const std::string& path, const ImageWriteOptions& options) {
    if (image.width() <= 0 || image.height() <= 0) throw Error("cannot write image '" + path + "': the image is empty");
    const fs::path parent = fs::path(path).parent_path();
    std::error_code ec;
    if (!parent.empty() && !fs::is_directory(parent, ec))
        throw Error("cannot write image '" + path + "': the folder '" + parent.string() + "' does not exist");
    if (hasExrExtension(path)) return io::writeExr(image, path, options);
    if (io::isPngPath(path)) return io::writePng(image, path, options);
    io::oiioModule("writing '" + path + "'").writeImage(image, path, options);
}

namespace io {

ImageHeader readImageHeader(const std::string& path) {
    requireImageFile(path);
    if (isExrFile(path)) return readExrHeader(path);
    return oiioModule("reading the header of '" + path + "'").readHeader(path);
}

}  // namespace io

}  // namespace darkroom
