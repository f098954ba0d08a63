#include "image_writer.h"

#include <darkroom/error.h>
#include <darkroom/strings.h>
#include <darkroom/data/image_io.h>

#include <filesystem>

namespace darkroom {

void ImageWriter::execute(Context& ctx) {
    const BufferPtr image = ctx.get(image_);
    if (ctx.getString(path_.name()).empty()) throw Error("no file given; set 'path' to the output file");
    const std::string path = ctx.get(path_);
    const std::filesystem::path parent = std::filesystem::path(path).parent_path();
    if (!parent.empty()) {
        std::error_code ec;
        std::filesystem::create_directories(parent, ec);
        if (ec) throw Error("cannot create the folder '" + parent.string() + "' for '" + path + "': " + ec.message());
    }
    ImageWriteOptions options;
    options.compression = ctx.get(compression_);
    options.halfFloat = ctx.get(half_);
    options.channels = splitNames(ctx.get(channels_));
    writeImage(*image, path, options);
    ctx.progress(1.0);
}

}  // namespace darkroom
