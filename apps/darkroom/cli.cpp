#include "cli.h"

#include "processes.h"

#include <algorithm>
#include <cstdio>
#include <unistd.h>

namespace darkroom::cli {

void report(const Diagnostics& diagnostics) {
    for (const auto& d : diagnostics) std::fprintf(stderr, "darkroom: %s\n", d.str().c_str());
}

void reportError(const std::string& message) { std::fprintf(stderr, "darkroom: error: %s\n", message.c_str()); }

Registry& loadRegistry(const GlobalOptions& options, const std::set<std::string>* wanted) {
    static Registry registry;
    static bool loaded = false;
    if (!loaded) {
        loaded = true;
        Diagnostics d = registry.loadPlugins(Registry::defaultSearchPath(options.pluginPaths), wanted);
        if (wanted && registry.setAside() &&
            std::any_of(wanted->begin(), wanted->end(), [](const std::string& t) { return !registry.filter(t); })) {
            Diagnostics more = registry.loadSetAside();
            d.insert(d.end(), more.begin(), more.end());
        }
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
