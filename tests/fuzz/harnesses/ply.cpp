// PLY (ascii and binary), through the reader's file entry point.
#include "harness.h"

#include <darkroom/error.h>
#include <darkroom/scene/mesh_readers.h>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    try {
        (void)darkroom::readPly(fuzz::writeInput(data, size, "input.ply"));
    } catch (const darkroom::Error&) {
    }
    return 0;
}
