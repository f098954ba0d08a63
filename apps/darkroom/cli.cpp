#include "cli.h"

#include "processes.h"

#include <cstdio>
#include <unistd.h>

namespace darkroom::cli {

void report(const Diagnostics& diagnostics) {
    for (const auto& d : diagnostics) std::fprintf(stderr, "darkroom: %s\n", d.str().c_str());
}

void reportError(const std::string& message) { std::fprintf(stderr, "darkroom: error: %s\n", message.c_str()); }

Registry& loadRegistry(const GlobalOptions& options) {
    static Registry registry;
    static bool loaded = false;
    if (!loaded) {
        loaded = true;
        Diagnostics d = registry.loadPlugins(Registry::defaultSearchPath(options.pluginPaths));
        // A plugin that fails to load is reported and skipped; it is not fatal.
        for (auto& x : d) x.severity = Diagnostic::Severity::Warning;
        report(d);
    }
    return registry;
}

bool stderrIsTerminal() { return ::isatty(STDERR_FILENO) == 1; }

bool showProgress(const GlobalOptions& options) {
    return processGroup().lead() && !options.quiet && (options.progress || stderrIsTerminal());
}

}  // namespace darkroom::cli
