// Pipeline YAML: parsePipeline with an empty registry (every node a
// placeholder), then the canonical text of what was read, read again.
#include "harness.h"

#include <darkroom/error.h>
#include <darkroom/core/pipeline.h>
#include <darkroom/core/registry.h>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    static const darkroom::Registry registry;
    try {
        darkroom::Diagnostics diagnostics;
        const darkroom::Graph graph = darkroom::parsePipeline(std::string(fuzz::text(data, size)), "fuzz.yaml",
                                                              registry, diagnostics);
        darkroom::Diagnostics again;
        (void)darkroom::parsePipeline(darkroom::serializePipeline(graph), "saved.yaml", registry, again);
    } catch (const darkroom::Error&) {
    }
    return 0;
}
