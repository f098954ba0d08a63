// .npz archives (libzip, then each .npy member): headers only, then values.
#include "harness.h"

#include <darkroom/error.h>
#include <darkroom/data/formats/npy.h>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string path = fuzz::writeInput(data, size, "input.npz");
    try {
        (void)darkroom::readNpzHeaders(path);
    } catch (const darkroom::Error&) {
    }
    try {
        (void)darkroom::readNpz(path);
    } catch (const darkroom::Error&) {
    }
    return 0;
}
