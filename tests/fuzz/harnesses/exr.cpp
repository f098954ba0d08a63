// The framework's native OpenEXR reader (framework/data/src/io/exr_file.cpp):
// header only (darkroom info), then pixels. OpenEXR itself is not
// instrumented; what is checked is Darkroom's use of it.
#include "harness.h"
#include "io/exr_file.h"

#include <darkroom/error.h>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string path = fuzz::writeInput(data, size, "input.exr");
    try {
        (void)darkroom::io::readExrHeader(path);
    } catch (const darkroom::Error&) {
    }
    try {
        (void)darkroom::io::readExr(path);
    } catch (const darkroom::Error&) {
    }
    return 0;
}
