#pragma once
// Each subcommand adds itself to the CLI11 app and sets `run` to its body,
// which returns the process exit code.
#include "cli.h"

#include <functional>

namespace CLI {
class App;
}

namespace darkroom::cli {

using Runner = std::function<int()>;

void addPluginsCommand(CLI::App& app, GlobalOptions& global, Runner& run);
void addDescribeCommand(CLI::App& app, GlobalOptions& global, Runner& run);
void addValidateCommand(CLI::App& app, GlobalOptions& global, Runner& run);
void addRunCommand(CLI::App& app, GlobalOptions& global, Runner& run);
void addCaptureCommand(CLI::App& app, GlobalOptions& global, Runner& run);
void addInfoCommand(CLI::App& app, GlobalOptions& global, Runner& run);

}  // namespace darkroom::cli
