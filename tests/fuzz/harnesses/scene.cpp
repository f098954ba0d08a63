// Scene YAML: parseSceneFile in memory; mesh files it names are looked up in
// an empty folder of this process's own.
#include "harness.h"

#include <darkroom/error.h>
#include <darkroom/framework/scene/scene_file.h>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    try {
        (void)darkroom::parseSceneFile(std::string(fuzz::text(data, size)), "fuzz.yaml", fuzz::scratchFolder());
    } catch (const darkroom::Error&) {
    }
    return 0;
}
