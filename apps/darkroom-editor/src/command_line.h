#pragma once
// The editor's command line, read before QApplication exists (which needs a
// display): --help prints the usage and an unknown option is refused on a
// headless machine too. Qt's own options (-platform, -style, ...) pass on.
#include <string>

namespace editor {

struct CommandLine {
    bool help = false;
    std::string error;  // non-empty: bad usage (exit 2)
};

CommandLine parseCommandLine(int argc, char** argv);
std::string usageText();

}  // namespace editor
