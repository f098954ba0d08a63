#include "image_writer.h"

#include <darkroom/error.h>
#include <darkroom/data/image_io.h>

#include <filesystem>

namespace darkroom {

namespace {

// "R, G, B" / "R G B" -> names.
std::vector<std::string> splitChannels(const std::string& text) {
    std::vector<std::string> out;
    std::string word;
    for (char c : text + ",") {
        if (c == ',' || c == ' ' || c == '\t') {
            if (!word.empty()) out.push_back(word);
            word.clear();
        } else {
            word += c;
        }
    }
    return out;
}

}  // namespace

void ImageWriter::execute(Context& ctx) {
    const BufferPtr image = ctx.get(image_);
    const std::string& given = ctx.getString(path_.name());
    if (given.empty()) throw Error("no file given; set 'path' to the output file");
    const std::string path = ctx.resolveOutputPath(given);
    const std::filesystem::path parent = std::filesystem::path(path).parent_path();
    if (!parent.empty()) {
        std::error_code ec;
        std::filesystem::create_directories(parent, ec);
        if (ec) throw Error("cannot create the folder '" + parent.string() + "' for '" + path + "': " + ec.message());
    }
    ImageWriteOptions options;
    options.compression = ctx.get(compression_);
    options.halfFloat = ctx.get(half_);
    options.channels = splitChannels(ctx.get(channels_));
    writeImage(*image, path, options);
    ctx.progress(1.0);
}

}  // namespace darkroom
