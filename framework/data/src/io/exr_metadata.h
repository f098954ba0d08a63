#pragma once
// BufferMetadata <-> OpenEXR header attributes: the darkroom:* names and
// attribute types that image_io.h documents and OpenImageIO writes (vectors
// as V3d, numbers as double, sizes as int, text as string). Internal.
#include <darkroom/buffer.h>

#include <ImfHeader.h>

#include <string>
#include <vector>

namespace darkroom::io::exr {

void putMetadata(const BufferMetadata& meta, const std::vector<std::string>& channelOrder, Imf::Header& header);

// Fills meta from the header; returns the stored channel order (empty if
// none). Throws darkroom::Error (without the file name; the caller adds it)
// when a darkroom:camera attribute is present but malformed.
std::vector<std::string> getMetadata(const Imf::Header& header, BufferMetadata& meta);

}  // namespace darkroom::io::exr
