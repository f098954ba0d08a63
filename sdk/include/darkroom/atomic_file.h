#pragma once
#include <darkroom/export.h>

#include <string>
#include <string_view>

namespace darkroom {

// Writing a file so that readers see the old file or the complete new one,
// never a torn one: write to temporaryPathFor(path), then commitFile().
//
// A unique name in the same directory (so the rename cannot cross file
// systems), keeping the extension so format-sniffing writers (OIIO) still work.
DARKROOM_API std::string temporaryPathFor(const std::string& path);
// Creates a new, empty temporary file beside `path` (a name as temporaryPathFor
// gives, made with O_CREAT | O_EXCL | O_NOFOLLOW, so a file or a symbolic link
// planted under a predictable name is never opened, truncated or followed: the
// next name is tried) and returns its name, for writers that open files
// themselves (OpenImageIO, FFmpeg, libzip). Throws darkroom::Error naming `path`.
DARKROOM_API std::string createTemporaryFile(const std::string& path);
// fsyncs the temporary file, renames it over `path` and fsyncs the folder;
// every step checked: throws darkroom::Error naming `path` and the errno text
// (the temporary file removed).
DARKROOM_API void commitFile(const std::string& temporary, const std::string& path);
// Writes bytes atomically, every write, the fsync and the close checked;
// throws darkroom::Error naming the path (what was at `path` stays, no temporary file is left).
DARKROOM_API void writeFileAtomic(const std::string& path, std::string_view bytes);

}  // namespace darkroom
