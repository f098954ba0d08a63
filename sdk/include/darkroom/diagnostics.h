#pragma once
#include <darkroom/export.h>

#include <string>
#include <vector>

namespace darkroom {

// One problem found in a pipeline, a plugin or an input file. `where` is what a
// user needs to find it: "pipeline.yaml:12:5", "node 'blur'", a plugin path.
struct Diagnostic {
    enum class Severity { Warning, Error };
    Severity severity = Severity::Error;
    std::string where;
    std::string message;
    std::string node;  // the node concerned, when there is one

    std::string str() const {
        return (where.empty() ? std::string() : where + ": ") +
               (severity == Severity::Warning ? "warning: " : "error: ") + message;
    }
};

using Diagnostics = std::vector<Diagnostic>;

inline bool hasErrors(const Diagnostics& d) {
    for (const auto& x : d)
        if (x.severity == Diagnostic::Severity::Error) return true;
    return false;
}

}  // namespace darkroom
