#include "image_writer.h"

#include <darkroom/error.h>
#include <darkroom/framework/image_io.h>

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

PortList ImageWriter::ports() const {
    PortList p;
    p.imageIn("image", "Image to write");
    p.pathIn("path", "",
             "Output file; the extension picks the format (.exr keeps every channel exactly; "
             ".png, .jpg, .tif are 8-bit sRGB). Relative to --output or the pipeline file");
    p.enumIn("compression", {"none", "rle", "zips", "zip", "piz", "pxr24", "b44", "b44a", "dwaa", "dwab"},
             "zip", "EXR compression (pxr24, b44, b44a, dwaa, dwab are lossy); ignored by 8-bit formats");
    p.boolIn("half", false, "EXR: store float channels except depth Z as 16-bit half (lossy)");
    p.stringIn("channels", "",
               "Channels to write, comma separated. 8-bit: 1 (grey), 2 (grey, alpha), 3 (RGB) or 4 "
               "(RGBA); empty = R, G, B(, A), else Y(, A), else the one float channel. EXR: a subset; "
               "empty = all");
    return p;
}

void ImageWriter::execute(Context& ctx) {
    const BufferPtr image = ctx.requireImage("image");
    const std::string& given = ctx.getString("path");
    if (given.empty()) throw Error("ImageWriter: no file given; set 'path' to the output file");
    const std::string path = ctx.resolveOutputPath(given);
    const std::filesystem::path parent = std::filesystem::path(path).parent_path();
    if (!parent.empty()) {
        std::error_code ec;
        std::filesystem::create_directories(parent, ec);
        if (ec) throw Error("cannot create the folder '" + parent.string() + "' for '" + path + "': " + ec.message());
    }
    ImageWriteOptions options;
    options.compression = ctx.getString("compression");
    options.halfFloat = ctx.getBool("half");
    options.channels = splitChannels(ctx.getString("channels"));
    writeImage(*image, path, options);
    ctx.progress(1.0);
}

}  // namespace darkroom
