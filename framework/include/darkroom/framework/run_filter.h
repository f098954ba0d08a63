#pragma once
#include <darkroom/export.h>
#include <darkroom/filter.h>

#include <map>
#include <string>
#include <vector>

namespace darkroom {

// Runs one filter outside any graph: inputs by port name (several values for a
// `multiple` port), unset value ports take their defaults. Used by tests,
// benchmarks and by nodes that drive other filters. Throws darkroom::Error.
struct FilterRunResult {
    std::map<std::string, Value> outputs;
    std::vector<std::string> warnings;
};

struct FilterRunOptions {
    int threads = 0;  // 0 = all hardware threads
    std::string inputBase;
    std::string outputDir;
};

DARKROOM_API FilterRunResult runFilter(Filter& filter,
                                       const std::map<std::string, std::vector<Value>>& inputs,
                                       const FilterRunOptions& options = {});

}  // namespace darkroom
