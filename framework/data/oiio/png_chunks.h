#pragma once
// PNG files are checked before OpenImageIO opens them: libpng allocates each
// ancillary chunk (tEXt, zTXt, iCCP, ...) at the length its header declares,
// so a 200-byte file declaring a 1.9 GB tEXt chunk made it allocate 1.9 GB
// while reading the header (found by tests/fuzz/harnesses/image.cpp).
#include <string>

namespace darkroom::oiio_module {

// Throws InputError naming the file, the chunk and its byte offset when a
// chunk of a PNG file (by its signature, whatever the extension) declares
// more bytes than the file has left. Files that are not PNG pass untouched.
void checkPngChunks(const std::string& path);

}  // namespace darkroom::oiio_module
