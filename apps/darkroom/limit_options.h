#pragma once
// The runner's --max-* options (darkroom/limits.h): set while the command
// line is parsed, so they hold before any file is read or node runs.
#include <cstdint>
#include <string>

namespace CLI {
class App;
}

namespace darkroom::cli {

void addLimitOptions(CLI::App& app);

// "4G", "512M", "1.5k", "1048576" -> bytes (K, M, G, T are powers of 1024; a
// trailing B or iB is allowed). Throws std::invalid_argument with the reason.
std::uint64_t parseSize(const std::string& text);

}  // namespace darkroom::cli
