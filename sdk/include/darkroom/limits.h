#pragma once
#include <darkroom/export.h>

#include <cstdint>
#include <string>

namespace darkroom {

// Limits a user can set (darkroom run/capture --max-*), consulted by readers
// before they allocate and by the host around each node. Exceeding one is a
// darkroom::InputError that names the file or node and the limit. The values
// are process-wide; set them before work starts.
enum class Limit : int {
    ImagePixels,       // width × height of one image or G-buffer a reader may allocate
    InputBytes,        // bytes of one text or binary input read whole (YAML, CSV, JSON, meshes)
    DecodedBytes,      // bytes one decoded array may take (inflated zlib, .npy/.npz members)
    NodeBytes,         // bytes of new planes one node may allocate in one evaluation (0: no limit)
    NodeMilliseconds,  // wall time of one node in one evaluation (0: no limit)
};

DARKROOM_API std::uint64_t limit(Limit which);
DARKROOM_API void setLimit(Limit which, std::uint64_t value);
// The command-line option that sets it, for messages: "--max-image-pixels".
DARKROOM_API const char* limitOption(Limit which);

// Throws InputError when width × height (overflow-safe) exceeds
// limit(Limit::ImagePixels): "<where>: 30000 x 30000 pixels exceed the limit
// of 268435456 (--max-image-pixels)".
DARKROOM_API void checkImagePixels(std::uint64_t width, std::uint64_t height, const std::string& where);
// Throws InputError when `bytes` exceeds limit(which), naming `where` and `what`.
DARKROOM_API void checkBytes(Limit which, std::uint64_t bytes, const std::string& where, const std::string& what);

}  // namespace darkroom
