// .npy in memory: the header alone (darkroom info) and the whole array.
#include "harness.h"

#include <darkroom/error.h>
#include <darkroom/data/formats/npy.h>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    try {
        (void)darkroom::parseNpyHeader(fuzz::text(data, size), "fuzz.npy");
    } catch (const darkroom::Error&) {
    }
    try {
        (void)darkroom::parseNpy(fuzz::text(data, size), "fuzz.npy");
    } catch (const darkroom::Error&) {
    }
    return 0;
}
