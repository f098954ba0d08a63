#pragma once
// OpenEXR headers are checked before OpenEXR reads them: it allocates each
// attribute's value at the size the header declares, so a 700-byte file
// declaring a 1.9 GB string attribute made it allocate 1.9 GB while reading
// the header (found by tests/fuzz/harnesses/exr.cpp). Internal to the framework.
#include <string>

namespace darkroom::io {

// Throws InputError naming the file, the attribute and its byte offset when
// an attribute of an OpenEXR header (every part's, for multi-part files)
// declares a negative size or more bytes than the file has left, when a
// preview image or a string of a string vector is larger than what holds it,
// and when a part's data window or tile size exceeds --max-image-pixels (or
// its channels --max-decoded-bytes): OpenEXR sizes its line and tile buffers
// from them when the file is opened. The walk steps over the bytes OpenEXR
// reads, not those declared, where the two differ: a channel list is read to
// its end and the fixed-size types (int, box2i, v3f ...) at their own size.
// A header this walk cannot follow is left to OpenEXR to report.
void checkExrAttributeSizes(const std::string& path);

}  // namespace darkroom::io
