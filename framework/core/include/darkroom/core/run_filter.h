#pragma once
#include <darkroom/export.h>
#include <darkroom/filter.h>

#include <map>
#include <memory>
#include <string>
#include <vector>

namespace darkroom {

// Runs one filter outside any graph: inputs by port name (several values for a
// `multiple` port), unset value ports take their defaults. Used by tests,
// benchmarks and by nodes that drive other filters. It goes through the same
// node runner as the evaluator (checks, error boundary, output sealing).
// Throws darkroom::Error naming the node.
struct FilterRunResult {
    std::map<std::string, Value> outputs;
    std::vector<std::string> warnings;
};

class Registry;

struct FilterRunOptions {
    int threads = 0;  // 0 = all hardware threads
    std::string inputBase;
    std::string outputDir;
    const Registry* registry = nullptr;  // for Context::createBackend
    // How errors name the node: "node 'runFilter' (Type): ...".
    std::string nodeName = "runFilter";
    std::string nodeType;
    // Planes asked for with Fill::None are filled with a NaN pattern no
    // computation makes (PlanePool::kPoison), so tests catch unwritten pixels.
    // Benchmarks turn it off.
    bool poison = true;
};

// A context with no inputs, for driving a CaptureBackend (or a filter by hand)
// outside a graph. Outputs set on it are kept in `outputs`; parallelFor runs
// in an arena of options.threads threads.
class Context;
DARKROOM_API std::unique_ptr<Context> makeStandaloneContext(const FilterRunOptions& options,
                                                            std::string nodeName = "standalone");

// Runs one execute() of `filter` through the evaluator's node runner, as a
// sequence of its own (beginSequence, execute, endSequence): what the filter
// holds between executes is let go before this returns.
DARKROOM_API FilterRunResult runFilter(Filter& filter,
                                       const std::map<std::string, std::vector<Value>>& inputs,
                                       const FilterRunOptions& options = {});

}  // namespace darkroom
