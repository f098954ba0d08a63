// Every other image format, through the OpenImageIO module's reader
// (framework/data/oiio/oiio_read.cpp). OpenImageIO picks the format from the file
// name, so the first byte of the input chooses the extension (its low bits)
// and the entry point (its high bit: the header only, or the whole image) and
// the rest is the file. One open per input: an open of a file no format
// claims makes OpenImageIO try every format, LibRaw's costly constructor
// included, which dominated the harness when it opened each input twice.
// OpenImageIO is not instrumented; what is checked is Darkroom's use of what
// it returns (sizes, channels, metadata).
#include "harness.h"
#include "../../../framework/data/oiio/module.h"

#include <darkroom/error.h>

#include <iterator>

namespace {
const char* const kExtensions[] = {"png", "tif", "tga", "sgi", "hdr", "ppm", "bmp", "jpg", "psd", "dds"};
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (size == 0) return 0;
    const std::string ext = kExtensions[(data[0] & 0x7f) % std::size(kExtensions)];
    const bool headerOnly = (data[0] & 0x80) != 0;
    const std::string path = fuzz::writeInput(data + 1, size - 1, "input." + ext);
    try {
        if (headerOnly)
            (void)darkroom::oiio_module::readHeader(path);
        else
            (void)darkroom::oiio_module::readImage(path);
    } catch (const darkroom::Error&) {
    }
    return 0;
}

// OpenImageIO 2.4 keeps each failed ImageInput's error text in a per-thread
// table it never frees (ImageInput::geterror); that is OpenImageIO's, not
// Darkroom's, and would stop every run.
extern "C" const char* __lsan_default_suppressions() {
    return "leak:libOpenImageIO.so\n";
}
