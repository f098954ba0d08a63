// TTK's .vti products (VTK XML ImageData; ascii, base64, appended, zlib).
#include "harness.h"

#include <darkroom/error.h>
#include <darkroom/data/formats/vti.h>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    try {
        (void)darkroom::readVti(fuzz::writeInput(data, size, "input.vti"));
    } catch (const darkroom::Error&) {
    }
    return 0;
}
