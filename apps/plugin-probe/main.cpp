// darkroom-plugin-probe FILE: loads a Darkroom plugin the way the host does
// (dlopen, ABI check, registration into a throw-away registrar) and says how
// it went. The host runs it for every new or changed plugin file before
// loading the file itself (framework/core/src/plugin_scan.cpp).
//
// Output: one line "ok" on stdout when everything succeeded, followed by a
// tab and the types it registered ("ok\tColorMapping,backend:embree"), else
// one line "refused: <reason>". A plugin that exits, crashes or hangs while loading
// never lets the line be printed; the host tells those apart by the exit
// status.
#include <darkroom/plugin.h>
#include <darkroom/registrar.h>
#include <darkroom/version.h>

#include <dlfcn.h>
#include <unistd.h>

#include <cstdio>
#include <exception>
#include <string>

namespace {

// Records the types a plugin registers, for the host to load only the
// plugins a pipeline needs.
class RecordingRegistrar final : public darkroom::Registrar {
public:
    std::string types;  // "A,B,backend:embree"
    void addFilter(darkroom::FilterInfo info) override {
        // Constructing the filter and declaring its ports runs plugin code
        // the host will run later; a crash there belongs to the probe.
        if (info.create) {
            auto f = info.create();
            if (f) (void)f->ports();
        }
        add(info.type);
    }
    void addCaptureBackend(darkroom::CaptureBackendInfo info) override {
        if (info.create) (void)info.create();
        add("backend:" + info.type);
    }

private:
    void add(const std::string& type) {
        // A name with the list's separators cannot be listed: the host then
        // knows nothing of the plugin's types and always loads it.
        if (type.find_first_of(",\t\n") != std::string::npos) unlisted = true;
        types += (types.empty() ? "" : ",") + type;
    }

public:
    bool unlisted = false;
};

int answer(const std::string& line) {
    std::fputs((line + "\n").c_str(), stdout);
    std::fflush(stdout);
    // _exit: static destructors of the plugin do not run in the probe.
    ::_exit(0);
}

}  // namespace

int main(int argc, char** argv) {
    if (argc != 2) {
        std::fprintf(stderr, "usage: darkroom-plugin-probe PLUGIN.so\n");
        return 2;
    }
    void* handle = ::dlopen(argv[1], RTLD_NOW | RTLD_LOCAL);
    if (!handle) {
        const char* e = ::dlerror();
        return answer(std::string("refused: cannot load plugin: ") + (e ? e : "unknown error"));
    }
    auto entry = reinterpret_cast<DarkroomPluginEntry>(::dlsym(handle, DARKROOM_PLUGIN_ENTRY_SYMBOL));
    if (!entry) return answer("refused: not a Darkroom plugin: it does not export " DARKROOM_PLUGIN_ENTRY_SYMBOL "()");
    const DarkroomPluginInfo* info = nullptr;
    try {
        info = entry();
    } catch (const std::exception& e) {
        return answer(std::string("refused: an exception escaped " DARKROOM_PLUGIN_ENTRY_SYMBOL "(): ") + e.what());
    } catch (...) {
        return answer("refused: an exception escaped " DARKROOM_PLUGIN_ENTRY_SYMBOL "()");
    }
    // What the host refuses by itself (no information, another ABI, no
    // register function, a registration that reports failure) it also names
    // by itself: only crashes and escaping exceptions are the probe's to tell.
    if (!info || info->abi_version != DARKROOM_ABI_VERSION || !info->register_types) return answer("ok");
    RecordingRegistrar r;
    bool registered = false;
    try {
        char error[1024] = {0};
        registered = info->register_types(&r, error, sizeof error) == 0;
    } catch (const std::exception& e) {
        return answer(std::string("refused: an exception escaped the register function: ") + e.what());
    } catch (...) {
        return answer("refused: an exception escaped the register function");
    }
    // "ok" and the types registered, which the host caches; a plain "ok" when
    // they cannot be listed (the host then loads the plugin whatever it needs).
    return answer(registered && !r.unlisted ? "ok\t" + r.types : "ok");
}
