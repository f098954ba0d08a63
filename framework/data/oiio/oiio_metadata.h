#pragma once
// BufferMetadata <-> OIIO ImageSpec attributes (the darkroom:* names that
// image_io.h documents). Part of the OpenImageIO module (module.h).
#include <darkroom/buffer.h>

#include <OpenImageIO/imageio.h>

#include <string>
#include <vector>

namespace darkroom::io {

void putMetadata(const BufferMetadata& meta, const std::vector<std::string>& channelOrder,
                 OIIO::ImageSpec& spec);

// Fills meta from the spec; returns the stored channel order (empty if none).
// Throws darkroom::Error (without the file name; the caller adds it) when a
// darkroom:camera attribute is present but malformed.
std::vector<std::string> getMetadata(const OIIO::ImageSpec& spec, BufferMetadata& meta);

}  // namespace darkroom::io
