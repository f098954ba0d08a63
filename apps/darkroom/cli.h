#pragma once
// Shared plumbing of the runner's subcommands: exit codes, error printing,
// the plugin registry built from the search path.
#include <darkroom/diagnostics.h>
#include <darkroom/core/registry.h>

#include <set>
#include <string>
#include <vector>

namespace darkroom::cli {

enum ExitCode : int { kOk = 0, kRuntimeFailure = 1, kBadInput = 2 };

struct GlobalOptions {
    std::vector<std::string> pluginPaths;  // --plugin-path, searched after the defaults
    bool quiet = false;
    bool progress = false;  // --progress: draw the bar even when stderr is not a terminal
};

// Prints one line per diagnostic on stderr ("darkroom: <where>: error: <message>").
void report(const Diagnostics& diagnostics);
void reportError(const std::string& message);

// Loads plugins from the default search path plus --plugin-path. Plugins that
// fail are reported as warnings and skipped; the runner goes on. With
// `wanted` (the node types of the pipeline a command runs), only the plugins
// that register one of them or a capture backend are loaded, unless one of
// them is then still missing: every plugin is loaded then, so that messages
// and suggestions know every type. The first call decides.
Registry& loadRegistry(const GlobalOptions& options, const std::set<std::string>* wanted = nullptr);

// True when stderr is a terminal (progress bars only then).
bool stderrIsTerminal();

// Whether this process draws the progress bar: not with -q; on rank 0 only
// under mpirun; when stderr is a terminal, or with --progress (an mpirun
// rank's stderr is a pipe to mpirun even when mpirun's is a terminal).
bool showProgress(const GlobalOptions& options);

}  // namespace darkroom::cli
