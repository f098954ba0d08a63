// darkroom: the headless runner. Lists and describes plugins, validates and
// runs pipelines, captures scenes into Cinema databases and describes them. Exit codes: 0 success, 1 runtime failure, 2 bad usage or input.
#include "commands.h"
#include "limit_options.h"
#include "processes.h"

#include <darkroom/error.h>
#include <darkroom/version.h>

#include <CLI/CLI.hpp>

#include <cstdio>
#include <filesystem>
#include <string>
#include <new>

int main(int argc, char** argv) {
    using namespace darkroom::cli;
    // Under mpirun, every rank runs the same command on its share (docs/scale-out.md).
    ProcessScope scope(&argc, &argv);
    CLI::App app{"Darkroom: deferred shading of scientific datasets (SDK " DARKROOM_SDK_VERSION ")", "darkroom"};
    app.require_subcommand(1);
    // Global options are accepted after the subcommand too:
    // `darkroom run demo.yaml -q`, `darkroom plugins --plugin-path DIR`.
    app.fallthrough();
    app.set_version_flag("--version", "darkroom " DARKROOM_SDK_VERSION);
    GlobalOptions global;
    app.add_option("--plugin-path", global.pluginPaths,
                   "Extra plugin directory or file, searched after the executable's plugin folder and "
                   "DARKROOM_PLUGIN_PATH (repeatable)")
        ->type_name("DIR");
    app.add_flag("-q,--quiet", global.quiet, "No progress output");
    app.add_flag("--progress", global.progress,
                 "Draw the progress bar even when stderr is not a terminal (under mpirun, where rank 0 alone draws it)");

    addLimitOptions(app);

    Runner run;
    addPluginsCommand(app, global, run);
    addDescribeCommand(app, global, run);
    addValidateCommand(app, global, run);
    addRunCommand(app, global, run);
    addCaptureCommand(app, global, run);
    addInfoCommand(app, global, run);

    try {
        app.parse(argc, argv);
    } catch (const CLI::CallForHelp& e) {
        return app.exit(e);
    } catch (const CLI::CallForAllHelp& e) {
        return app.exit(e);
    } catch (const CLI::CallForVersion& e) {
        return app.exit(e);
    } catch (const CLI::ParseError& e) {
        std::fprintf(stderr, "darkroom: error: %s\nRun 'darkroom --help' for usage.\n", e.what());
        return kBadInput;
    }
    try {
        return run ? run() : kBadInput;
    } catch (const darkroom::Cancelled&) {
        reportError("cancelled");
        return kRuntimeFailure;
    } catch (const darkroom::InputError& e) {
        reportError(e.what());
        return failAllProcesses(kBadInput);
    } catch (const std::bad_alloc&) {
        reportError("out of memory (a limit such as --max-image-pixels or --max-node-memory keeps one input "
                    "or node within bounds)");
        return failAllProcesses(kRuntimeFailure);
    } catch (const darkroom::Error& e) {
        reportError(e.what());
        return failAllProcesses(kRuntimeFailure);
    } catch (const std::filesystem::filesystem_error& e) {
        // "filesystem error: cannot create directories: ..." names the path and the reason.
        reportError(e.what());
        return failAllProcesses(kRuntimeFailure);
    } catch (const std::exception& e) {
        // Not an error Darkroom meant to report (std::out_of_range, a
        // library's own exception): said so, rather than its raw text alone.
        reportError(std::string("unexpected internal failure (please report it with the command line): ") + e.what());
        return failAllProcesses(kRuntimeFailure);
    }
}
