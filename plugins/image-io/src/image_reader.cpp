#include "image_reader.h"

#include <darkroom/error.h>
#include <darkroom/input_file.h>
#include <darkroom/data/image_io.h>

namespace darkroom {

void ImageReader::execute(Context& ctx) {
    const std::string& given = ctx.getString(path_.name());
    if (given.empty()) throw InputError("no file given; set 'path' to an image file");
    const std::string path = ctx.get(path_);
    // A missing file, a folder or a FIFO is the user's input, not a failure
    // of the run: the runner exits 2 for it, naming the node and the path.
    (void)requireRegularFile(path, "image");
    auto image = readImage(path);
    // Provenance: where this buffer came from.
    image->metadata().attributes["source"] = given;
    ctx.progress(1.0);
    ctx.set(result_, image);
}

}  // namespace darkroom
