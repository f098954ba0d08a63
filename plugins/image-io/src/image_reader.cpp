#include "image_reader.h"

#include <darkroom/error.h>
#include <darkroom/framework/image_io.h>

namespace darkroom {

PortList ImageReader::ports() const {
    PortList p;
    p.pathIn("path", "", "Image file to read (PNG, JPEG, TIFF, EXR, ...); relative to the pipeline file");
    p.imageOut("image",
               "Every EXR channel with its name (float32, uint32 kept), or linear R, G, B(, A) / Y "
               "decoded from sRGB for 8/16-bit images; the camera travels in the metadata");
    return p;
}

void ImageReader::execute(Context& ctx) {
    const std::string& given = ctx.getString("path");
    if (given.empty()) throw Error("ImageReader: no file given; set 'path' to an image file");
    auto image = readImage(ctx.resolveInputPath(given));
    // Provenance: where this buffer came from.
    image->metadata().attributes["source"] = given;
    ctx.progress(1.0);
    ctx.setOutput("image", BufferPtr(std::move(image)));
}

}  // namespace darkroom
