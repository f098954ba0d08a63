#include <darkroom/error.h>
#include <darkroom/plugin.h>
#include <darkroom/strings.h>
#include <darkroom/core/registry.h>

#include "plugin_scan.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <dlfcn.h>
#include <filesystem>
#include <set>

namespace darkroom {

namespace fs = std::filesystem;

namespace {

// Collects a plugin's registrations; nothing reaches the registry unless the
// whole register function succeeds.
class StagingRegistrar final : public Registrar {
public:
    std::vector<FilterInfo> filters;
    std::vector<CaptureBackendInfo> backends;
    void addFilter(FilterInfo info) override {
        if (info.type.empty()) throw Error("a filter was registered without a type name");
        if (!info.create) throw Error("filter '" + info.type + "' was registered without a factory");
        filters.push_back(std::move(info));
    }
    void addCaptureBackend(CaptureBackendInfo info) override {
        if (info.type.empty()) throw Error("a capture backend was registered without a type name");
        if (!info.create) throw Error("backend '" + info.type + "' was registered without a factory");
        backends.push_back(std::move(info));
    }
};

std::string describe(const Origin& o) { return o.path.empty() ? "built-in '" + o.plugin + "'" : o.path; }

Diagnostic pluginError(const std::string& path, std::string message) {
    Diagnostic d;
    d.where = path;
    d.message = std::move(message);
    return d;
}

}  // namespace

Registry::Registry() = default;

// Plugins are never unloaded: filters, factories and type_info they own may be
// referenced until the process exits.
Registry::~Registry() = default;

std::vector<std::string> Registry::defaultSearchPath(const std::vector<std::string>& extra) {
    std::vector<std::string> out;
    std::error_code ec;
    const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
    if (!ec) {
        const fs::path dir = (exe.parent_path() / ".." / "lib" / "darkroom" / "plugins").lexically_normal();
        if (fs::is_directory(dir, ec)) out.push_back(dir.string());
    }
    if (const char* env = std::getenv("DARKROOM_PLUGIN_PATH")) {
        std::string s(env);
        std::size_t i = 0;
        while (i <= s.size()) {
            std::size_t j = s.find(':', i);
            if (j == std::string::npos) j = s.size();
            if (j > i) out.push_back(s.substr(i, j - i));
            i = j + 1;
        }
    }
    out.insert(out.end(), extra.begin(), extra.end());
    return out;
}

namespace {

// Whether a plugin whose registered types are `types` is needed for the
// node types `wanted`: one of them, or a capture backend when the host asked
// for every one (kEveryCaptureBackend: a Capture node picks its backend by a
// parameter's value, not by a node type).
bool needed(const std::vector<std::string>& types, const std::set<std::string>& wanted) {
    const bool backends = wanted.count(Registry::kEveryCaptureBackend) > 0;
    return std::any_of(types.begin(), types.end(), [&](const std::string& t) {
        return wanted.count(t) || (backends && t.rfind("backend:", 0) == 0);
    });
}

}  // namespace

Diagnostics Registry::loadSetAside() {
    Diagnostics out;
    std::vector<std::string> files;
    files.swap(setAside_);
    for (const auto& f : files) loadPlugin(f, out);
    return out;
}

Diagnostics Registry::loadPlugins(const std::vector<std::string>& searchPath, const std::set<std::string>* wanted) {
    Diagnostics out;
    std::set<std::string> seen;
    std::vector<std::string> files;
    for (const auto& entry : searchPath) {
        std::error_code ec;
        if (fs::is_regular_file(entry, ec)) {
            const std::string canonical = fs::weakly_canonical(entry, ec).string();
            if (seen.insert(canonical).second) files.push_back(entry);
            continue;
        }
        if (!fs::is_directory(entry, ec)) {
            Diagnostic d = pluginError(entry, ec && ec != std::errc::no_such_file_or_directory
                                                  ? "plugin search path entry cannot be read: " + ec.message()
                                                  : "plugin search path entry does not exist");
            d.severity = Diagnostic::Severity::Warning;
            out.push_back(d);
            continue;
        }
        std::vector<std::string> found;
        fs::directory_iterator it(entry, ec), end;
        for (; !ec && it != end; it.increment(ec)) {
            const std::string name = it->path().filename().string();
            if (name.rfind("darkroom-", 0) != 0 || it->path().extension() != ".so") continue;
            // Error-code forms throughout: a symlink loop or a dangling link
            // is reported, never thrown.
            std::error_code fe;
            const bool regular = it->is_regular_file(fe);
            if (fe) {
                Diagnostic d = pluginError(it->path().string(), "cannot inspect plugin file: " + fe.message() + "; skipped");
                d.severity = Diagnostic::Severity::Warning;
                out.push_back(d);
                continue;
            }
            if (regular) found.push_back(it->path().string());
        }
        if (ec) out.push_back(pluginError(entry, "cannot list plugin folder: " + ec.message()));
        std::sort(found.begin(), found.end());  // deterministic load order
        for (const auto& f : found) {
            std::error_code ce;
            const std::string canonical = fs::weakly_canonical(f, ce).string();
            if (seen.insert(ce ? f : canonical).second) files.push_back(f);
        }
    }

    // New or changed files are first loaded in a child process; those that
    // crash, exit or hang there are named and skipped.
    PluginScan scan;
    if (!scan.available() && !files.empty()) {
        Diagnostic d;
        d.severity = Diagnostic::Severity::Warning;
        d.where = "plugins";
        d.message = "darkroom-plugin-probe was not found beside the Darkroom libraries; plugins are loaded without "
                    "the crash check";
        out.push_back(d);
    }
    for (const auto& f : files) {
        const ProbeVerdict v = scan.check(f);
        if (!v.ok) {
            out.push_back(pluginError(f, "plugin quarantined (tried in a separate process first): " + v.reason +
                                             "; skipped (it is tried again when the file changes)"));
            continue;
        }
        if (wanted && v.types && !needed(*v.types, *wanted)) {
            setAside_.push_back(f);
            continue;
        }
        loadPlugin(f, out);
    }
    scan.save();
    return out;
}

bool Registry::loadPlugin(const std::string& path, Diagnostics& out) {
    void* handle = ::dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (!handle) {
        const char* err = ::dlerror();
        out.push_back(pluginError(path, std::string("cannot load plugin: ") + (err ? err : "unknown error")));
        return false;
    }
    handles_.push_back(handle);
    auto entry = reinterpret_cast<DarkroomPluginEntry>(::dlsym(handle, DARKROOM_PLUGIN_ENTRY_SYMBOL));
    if (!entry) {
        out.push_back(pluginError(path, "not a Darkroom plugin: it does not export " DARKROOM_PLUGIN_ENTRY_SYMBOL "()"));
        return false;
    }
    // No exception may cross the C boundary, but a plugin written without
    // the SDK's macro might let one through: it is caught and named here.
    const DarkroomPluginInfo* info = nullptr;
    try {
        info = entry();
    } catch (const std::exception& e) {
        out.push_back(pluginError(path, std::string("an exception escaped " DARKROOM_PLUGIN_ENTRY_SYMBOL "(): ") + e.what() +
                                            "; skipped"));
        return false;
    } catch (...) {
        out.push_back(pluginError(path, "an exception escaped " DARKROOM_PLUGIN_ENTRY_SYMBOL "(); skipped"));
        return false;
    }
    if (!info) {
        out.push_back(pluginError(path, DARKROOM_PLUGIN_ENTRY_SYMBOL "() returned no plugin information"));
        return false;
    }
    // abi_version is the one field every ABI keeps first; nothing else is read
    // until it matches.
    if (info->abi_version != DARKROOM_ABI_VERSION) {
        out.push_back(pluginError(
            path, "plugin was built for Darkroom plugin ABI version " + std::to_string(info->abi_version) +
                      ", but this host uses ABI version " + std::to_string(DARKROOM_ABI_VERSION) +
                      " (SDK " DARKROOM_SDK_VERSION "); rebuild the plugin against this SDK"));
        return false;
    }
    Origin origin{info->name ? info->name : "", info->version ? info->version : "", path};
    if (origin.plugin.empty() || !info->register_types) {
        out.push_back(pluginError(path, "plugin information lacks a name or a register function"));
        return false;
    }
    StagingRegistrar staging;
    char error[1024] = {0};
    int failed = 0;
    try {
        failed = info->register_types(&staging, error, sizeof error);
    } catch (const std::exception& e) {
        std::snprintf(error, sizeof error, "an exception escaped the register function: %s", e.what());
        failed = 1;
    } catch (...) {
        std::snprintf(error, sizeof error, "an exception escaped the register function");
        failed = 1;
    }
    if (failed != 0) {
        out.push_back(pluginError(path, "plugin '" + origin.plugin + "' failed to register its types: " +
                                            (error[0] ? error : "no reason given") + "; skipped"));
        return false;
    }
    try {
        checkRegistrations(staging.filters);
        commit(origin, std::move(staging.filters), std::move(staging.backends));
    } catch (const Error& e) {
        out.push_back(pluginError(path, std::string(e.what()) + "; plugin '" + origin.plugin + "' skipped"));
        return false;
    }
    plugins_.back().sdkVersion = info->sdk_version ? info->sdk_version : "";
    return true;
}

// Every filter is made once and its ports checked (unique names, defaults
// inside their ranges, enum defaults among the choices), so a misspelt choice
// fails here, naming the type, and never reaches a pipeline.
void Registry::checkRegistrations(const std::vector<FilterInfo>& filters) {
    for (const auto& f : filters) {
        try {
            std::unique_ptr<Filter> made = f.create();
            if (!made) throw Error("its factory returned nothing");
            checkPorts(made->ports());
        } catch (const std::exception& e) {
            throw Error("type '" + f.type + "' is declared wrongly: " + e.what());
        }
    }
}

void Registry::registerBuiltin(const std::string& pluginName, void (*fn)(Registrar&)) {
    StagingRegistrar staging;
    fn(staging);
    checkRegistrations(staging.filters);
    commit(Origin{pluginName, DARKROOM_SDK_VERSION, ""}, std::move(staging.filters),
           std::move(staging.backends));
    plugins_.back().sdkVersion = DARKROOM_SDK_VERSION;
}

void Registry::commit(const Origin& origin, std::vector<FilterInfo> filters,
                      std::vector<CaptureBackendInfo> backends) {
    // Check everything first so a rejected plugin leaves no trace.
    std::set<std::string> mine;
    for (const auto& f : filters) {
        if (!mine.insert(f.type).second)
            throw Error("type '" + f.type + "' is registered twice by " + describe(origin));
        if (auto it = filters_.find(f.type); it != filters_.end())
            throw Error("duplicate filter type '" + f.type + "': already registered by " +
                        describe(it->second.origin) + ", registered again by " + describe(origin));
    }
    std::set<std::string> mineBackends;
    for (const auto& b : backends) {
        if (!mineBackends.insert(b.type).second)
            throw Error("backend '" + b.type + "' is registered twice by " + describe(origin));
        if (auto it = backends_.find(b.type); it != backends_.end())
            throw Error("duplicate capture backend '" + b.type + "': already registered by " +
                        describe(it->second.origin) + ", registered again by " + describe(origin));
    }
    LoadedPlugin plugin{origin, "", {}};
    for (auto& f : filters) {
        plugin.types.push_back(f.type);
        const std::string type = f.type;
        filters_.emplace(type, RegisteredFilter{std::move(f), origin});
    }
    for (auto& b : backends) {
        plugin.types.push_back(b.type);
        const std::string type = b.type;
        backends_.emplace(type, RegisteredBackend{std::move(b), origin});
    }
    plugins_.push_back(std::move(plugin));
}

const RegisteredFilter* Registry::filter(const std::string& type) const {
    auto it = filters_.find(type);
    return it == filters_.end() ? nullptr : &it->second;
}

const RegisteredBackend* Registry::backend(const std::string& type) const {
    auto it = backends_.find(type);
    return it == backends_.end() ? nullptr : &it->second;
}

std::vector<const RegisteredFilter*> Registry::filters() const {
    std::vector<const RegisteredFilter*> out;
    for (const auto& [k, v] : filters_) out.push_back(&v);
    return out;
}

std::vector<std::string> Registry::typeNames(bool withBackends) const {
    std::vector<std::string> out;
    for (const auto& [k, v] : filters_) out.push_back(k);
    if (withBackends)
        for (const auto& [k, v] : backends_) out.push_back(k);
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end()), out.end());
    return out;
}

std::vector<const RegisteredBackend*> Registry::backends() const {
    std::vector<const RegisteredBackend*> out;
    for (const auto& [k, v] : backends_) out.push_back(&v);
    return out;
}

std::unique_ptr<Filter> Registry::createFilter(const std::string& type) const {
    const RegisteredFilter* f = filter(type);
    if (!f)
        throw Error("unknown node type '" + type + "'" + didYouMean(type, typeNames()) +
                    "; `darkroom plugins` lists the available types");
    try {
        std::unique_ptr<Filter> out = f->info.create();
        if (!out) throw Error("the factory returned nothing");
        return out;
    } catch (const std::exception& e) {
        throw Error("cannot create a '" + type + "' (from " + describe(f->origin) + "): " + e.what());
    }
}

std::unique_ptr<CaptureBackend> Registry::createBackend(const std::string& type) const {
    const RegisteredBackend* b = backend(type);
    if (!b) {
        std::string known;
        for (const auto& [k, v] : backends_) known += (known.empty() ? "" : ", ") + k;
        throw Error("unknown capture backend '" + type + "'; available: " +
                    (known.empty() ? std::string("none (is the capture-embree plugin loaded?)") : known));
    }
    try {
        std::unique_ptr<CaptureBackend> out = b->info.create();
        if (!out) throw Error("the factory returned nothing");
        return out;
    } catch (const std::exception& e) {
        throw Error("cannot create capture backend '" + type + "' (from " + describe(b->origin) + "): " + e.what());
    }
}

const PortList& Registry::ports(const std::string& type) const {
    std::lock_guard<std::mutex> lock(portMutex_);
    if (auto it = portCache_.find(type); it != portCache_.end()) return it->second;
    std::unique_ptr<Filter> f = createFilter(type);
    PortList p;
    try {
        p = f->ports();
    } catch (const std::exception& e) {
        throw Error("type '" + type + "' failed to declare its ports: " + e.what());
    }
    return portCache_.emplace(type, std::move(p)).first->second;
}

}  // namespace darkroom
