// ParaView colour-map JSON (sdk/src/colormap_json.cpp), then a table of it.
#include "harness.h"

#include <darkroom/colormap.h>
#include <darkroom/error.h>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    try {
        const darkroom::ColorMapData map = darkroom::loadColorMap(fuzz::writeInput(data, size, "map.json"));
        (void)map.table(16);
        (void)map.sample(0.5);
    } catch (const darkroom::Error&) {
    }
    return 0;
}
