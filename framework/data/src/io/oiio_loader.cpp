#include "oiio_loader.h"

#include <darkroom/error.h>

#include <dlfcn.h>

#include <filesystem>
#include <mutex>

namespace darkroom::io {

namespace {

struct Loaded {
    const oiio_module::Entry* entry = nullptr;
    std::string error;
};

// Beside the library this function is in (the build tree and the install
// tree keep both in the same folder).
std::string modulePath() {
    Dl_info info{};
    if (::dladdr(reinterpret_cast<void*>(&modulePath), &info) == 0 || !info.dli_fname) return "libdarkroom-oiio.so";
    return (std::filesystem::path(info.dli_fname).parent_path() / "libdarkroom-oiio.so").string();
}

Loaded load() {
    Loaded l;
    const std::string path = modulePath();
    // Never closed: the module stays for the life of the process.
    void* handle = ::dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (!handle) {
        const char* e = ::dlerror();
        l.error = "cannot load the OpenImageIO module '" + path + "': " + (e ? e : "unknown error");
        return l;
    }
    using EntryFunction = const oiio_module::Entry* (*)();
    auto fn = reinterpret_cast<EntryFunction>(::dlsym(handle, oiio_module::kEntrySymbol));
    const oiio_module::Entry* entry = fn ? fn() : nullptr;
    if (!entry) {
        l.error = "'" + path + "' has no " + oiio_module::kEntrySymbol + " entry";
        return l;
    }
    if (entry->version != oiio_module::kEntryVersion) {
        l.error = "'" + path + "' is version " + std::to_string(entry->version) + " of the OpenImageIO module, not " +
                  std::to_string(oiio_module::kEntryVersion) + " (a library from another build)";
        return l;
    }
    l.entry = entry;
    return l;
}

}  // namespace

const oiio_module::Entry& oiioModule(const std::string& purpose) {
    static std::once_flag once;
    static Loaded loaded;
    std::call_once(once, [] { loaded = load(); });
    if (!loaded.entry) throw Error(purpose + " needs OpenImageIO, but " + loaded.error);
    return *loaded.entry;
}

}  // namespace darkroom::io
