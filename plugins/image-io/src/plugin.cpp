#include "image_reader.h"
#include "image_writer.h"

#include <darkroom/plugin.h>

namespace {

void registerTypes(darkroom::Registrar& r) {
    r.addFilter<darkroom::ImageReader>(
        "ImageReader", "Input/Output",
        "Reads an image file with OpenImageIO. EXR keeps every channel, its name and float32 "
        "values (half is widened, uint32 ids stay uint32) and the camera written by Darkroom; "
        "8/16-bit PNG, JPEG and TIFF are decoded from sRGB to linear R, G, B, A (Y for grey).");
    r.addFilter<darkroom::ImageWriter>(
        "ImageWriter", "Input/Output",
        "Writes an image file atomically, creating its folder. EXR stores every channel exactly "
        "(or as half when asked), with the camera and attributes in the header; PNG, JPEG and "
        "TIFF are 8-bit, sRGB-encoded from linear, clamped, NaN written as 0.");
}

}  // namespace

DARKROOM_PLUGIN("image-io", "0.1.0", registerTypes)
