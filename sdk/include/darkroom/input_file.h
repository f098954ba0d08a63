#pragma once
#include <darkroom/export.h>

#include <cstdint>
#include <string>

namespace darkroom {

// Every reader of a user's file goes through these, so that a FIFO, a device
// (/dev/zero), a directory or a file beyond limit(Limit::InputBytes) is
// refused with a one-line InputError naming the path and `what` ("mesh",
// "pipeline", "colour map") instead of blocking or reading without end.

// Throws InputError unless `path` names an existing regular file (symlinks
// are followed). Returns its size in bytes.
DARKROOM_API std::uint64_t requireRegularFile(const std::string& path, const std::string& what);
// Reads a whole regular file, refusing one over limit(Limit::InputBytes).
DARKROOM_API std::string readInputFile(const std::string& path, const std::string& what);

}  // namespace darkroom
