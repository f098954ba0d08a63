#include "optional_module.h"

#include <darkroom/error.h>

#include <dlfcn.h>

#include <filesystem>
#include <mutex>

namespace darkroom::io {

namespace {

// What a module is, for opening it and for messages.
struct ModuleSpec {
    const char* file;      // "libdarkroom-oiio.so"
    const char* symbol;    // its one exported entry function
    int version;           // the Entry version this build expects
    const char* what;      // "the OpenImageIO module"
    const char* needs;     // "OpenImageIO", for "reading 'x.tif' needs OpenImageIO, but ..."
};

struct Loaded {
    const void* entry = nullptr;  // the module's Entry, whose first member is its version
    std::string error;
};

// Beside the library this function is in.
std::string besideThisLibrary(const char* file) {
    Dl_info info{};
    if (::dladdr(reinterpret_cast<void*>(&besideThisLibrary), &info) == 0 || !info.dli_fname) return file;
    return (std::filesystem::path(info.dli_fname).parent_path() / file).string();
}

Loaded load(const ModuleSpec& spec) {
    Loaded l;
    const std::string path = besideThisLibrary(spec.file);
    // Never closed: the module stays for the life of the process.
    void* handle = ::dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (!handle) {
        const char* e = ::dlerror();
        l.error = "cannot load " + std::string(spec.what) + " '" + path + "': " + (e ? e : "unknown error");
        return l;
    }
    using EntryFunction = const void* (*)();
    auto fn = reinterpret_cast<EntryFunction>(::dlsym(handle, spec.symbol));
    const void* entry = fn ? fn() : nullptr;
    if (!entry) {
        l.error = "'" + path + "' has no " + spec.symbol + " entry";
        return l;
    }
    // Every module's Entry starts with its version (module.h).
    const int version = *static_cast<const int*>(entry);
    if (version != spec.version) {
        l.error = "'" + path + "' is version " + std::to_string(version) + " of " + spec.what + ", not " +
                  std::to_string(spec.version) + " (a library from another build)";
        return l;
    }
    l.entry = entry;
    return l;
}

// Opens the module once per process; every later call gets the same answer.
template <class Entry>
const Entry& moduleEntry(const ModuleSpec& spec, const std::string& purpose) {
    static std::once_flag once;
    static Loaded loaded;
    std::call_once(once, [&] { loaded = load(spec); });
    if (!loaded.entry)
        throw Error(purpose + " needs " + spec.needs + ", but " + loaded.error + "; " + spec.file +
                    " is built and installed beside libdarkroom-data.so: build or install Darkroom again");
    return *static_cast<const Entry*>(loaded.entry);
}

}  // namespace

const oiio_module::Entry& oiioModule(const std::string& purpose) {
    static const ModuleSpec spec{"libdarkroom-oiio.so", oiio_module::kEntrySymbol, oiio_module::kEntryVersion,
                                 "the OpenImageIO module", "OpenImageIO"};
    return moduleEntry<oiio_module::Entry>(spec, purpose);
}

const h5_module::Entry& h5Module(const std::string& purpose) {
    static const ModuleSpec spec{"libdarkroom-h5.so", h5_module::kEntrySymbol, h5_module::kEntryVersion,
                                 "the HDF5 module", "HDF5"};
    return moduleEntry<h5_module::Entry>(spec, purpose);
}

}  // namespace darkroom::io
