#pragma once
// The plugin boundary. A plugin exports exactly one C function,
// `darkroom_plugin_entry`, returning a plain struct. The host reads
// `abi_version` before touching anything else, so a plugin built against
// another SDK is refused cleanly; no C++ exception crosses this boundary.
#include <darkroom/export.h>
#include <darkroom/registrar.h>
#include <darkroom/version.h>

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <exception>

extern "C" {

struct DarkroomPluginInfo {
    std::uint32_t abi_version;   // must equal the host's DARKROOM_ABI_VERSION
    const char* sdk_version;     // DARKROOM_SDK_VERSION the plugin was built with
    const char* name;            // plugin name, e.g. "colormapping"
    const char* version;         // plugin's own version
    // Registers the plugin's types. Returns 0 on success; otherwise writes a
    // NUL-terminated message into error (at most error_size bytes) and returns non-zero.
    int (*register_types)(void* registrar, char* error, std::size_t error_size);
};

typedef const DarkroomPluginInfo* (*DarkroomPluginEntry)(void);
}

#define DARKROOM_PLUGIN_ENTRY_SYMBOL "darkroom_plugin_entry"

// Defines the entry point. REGISTER_FN is `void fn(darkroom::Registrar&)`;
// exceptions it throws are turned into the error message.
#define DARKROOM_PLUGIN(NAME, VERSION, REGISTER_FN)                                              \
    static int darkroom_register_types_(void* registrar, char* error, std::size_t error_size) { \
        try {                                                                                   \
            REGISTER_FN(*static_cast<darkroom::Registrar*>(registrar));                         \
            return 0;                                                                           \
        } catch (const std::exception& e) {                                                     \
            std::strncpy(error, e.what(), error_size - 1);                                      \
            error[error_size - 1] = '\0';                                                       \
        } catch (...) {                                                                         \
            std::strncpy(error, "unknown exception", error_size - 1);                           \
            error[error_size - 1] = '\0';                                                       \
        }                                                                                       \
        return 1;                                                                               \
    }                                                                                           \
    extern "C" DARKROOM_EXPORT const DarkroomPluginInfo* darkroom_plugin_entry(void) {          \
        static const DarkroomPluginInfo info{DARKROOM_ABI_VERSION, DARKROOM_SDK_VERSION, NAME,  \
                                             VERSION, &darkroom_register_types_};               \
        return &info;                                                                           \
    }
