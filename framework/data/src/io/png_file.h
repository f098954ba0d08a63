#pragma once
// PNG written natively (png_encoder.h: libdeflate), not through OpenImageIO
// (see exr_file.h for why): the runner's most common output. Internal to the
// framework.
#include <darkroom/buffer.h>
#include <darkroom/data/image_io.h>

#include <string>

namespace darkroom::io {

bool isPngPath(const std::string& path);  // by extension, as OpenImageIO chooses
void writePng(const Buffer& image, const std::string& path, const ImageWriteOptions& options);

}  // namespace darkroom::io
