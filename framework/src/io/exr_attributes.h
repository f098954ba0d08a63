#pragma once
// OpenEXR headers are checked before OpenEXR reads them: it allocates each
// attribute's value at the size the header declares, so a 700-byte file
// declaring a 1.9 GB string attribute made it allocate 1.9 GB while reading
// the header (found by tests/fuzz/harnesses/exr.cpp). Internal to the framework.
#include <string>

namespace darkroom::io {

// Throws InputError naming the file, the attribute and its byte offset when
// an attribute of an OpenEXR header (every part's, for multi-part files)
// declares a negative size or more bytes than the file has left. A header
// this walk cannot follow is left to OpenEXR to report. The walk follows
// OpenEXR's own reading where it ignores the declared size (a channel list
// is read to its end); other fixed-size types whose declared size disagrees
// with their natural size are not followed (docs/formats.md, Fuzzing: open).
void checkExrAttributeSizes(const std::string& path);

}  // namespace darkroom::io
