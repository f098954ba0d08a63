#pragma once
// OpenEXR read and written with the OpenEXR library itself, not through
// OpenImageIO: the G-buffers Darkroom writes and reads most are EXR, and
// OpenImageIO drags ~260 shared libraries into the process (OpenVDB, GDAL,
// DICOM, OpenCV, ...) whose start-up costs ~130 MB of memory and a few hundred
// milliseconds. Files are the same as OpenImageIO writes and reads them: the
// same darkroom:* attributes and attribute types, the same channel order
// rules, first part, data window. Internal to the framework.
#include "image_header.h"

#include <darkroom/buffer.h>
#include <darkroom/data/image_io.h>

#include <memory>
#include <string>

namespace darkroom::io {

// True when the file starts with OpenEXR's magic number.
bool isExrFile(const std::string& path);

// Which decoder reads the pixels: the direct one (exr_direct.h) where it can,
// OpenEXR's C++ library for the rest; or the C++ library alone, which the
// tests and the benchmark compare the direct decoder against.
enum class ExrPixelPath { DirectWhenPossible, OpenExrOnly };

std::shared_ptr<WritableBuffer> readExr(const std::string& path,
                                        ExrPixelPath pixels = ExrPixelPath::DirectWhenPossible);
ImageHeader readExrHeader(const std::string& path);
void writeExr(const Buffer& image, const std::string& path, const ImageWriteOptions& options);

}  // namespace darkroom::io
