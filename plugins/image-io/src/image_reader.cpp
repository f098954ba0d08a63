#include "image_reader.h"

#include <darkroom/error.h>
#include <darkroom/framework/image_io.h>

namespace darkroom {

void ImageReader::execute(Context& ctx) {
    const std::string& given = ctx.getString(path_.name());
    if (given.empty()) throw Error("no file given; set 'path' to an image file");
    auto image = readImage(ctx.get(path_));
    // Provenance: where this buffer came from.
    image->metadata().attributes["source"] = given;
    ctx.progress(1.0);
    ctx.set(result_, image);
}

}  // namespace darkroom
