#pragma once
#include <darkroom/export.h>
#include <darkroom/diagnostics.h>
#include <darkroom/registrar.h>

#include <map>
#include <memory>
#include <mutex>
#include <set>
#include <string>
#include <vector>

namespace darkroom {

// Where a registered type came from.
struct Origin {
    std::string plugin;   // plugin name ("builtin" for the host's own)
    std::string version;  // plugin version
    std::string path;     // shared library path, empty for builtins
};

struct RegisteredFilter {
    FilterInfo info;
    Origin origin;
};

struct RegisteredBackend {
    CaptureBackendInfo info;
    Origin origin;
};

struct LoadedPlugin {
    Origin origin;
    std::string sdkVersion;
    std::vector<std::string> types;  // filter and backend type names it registered
};

// The one registry of filters and capture backends, shared by the runner and
// the editor. Plugins are loaded once and never unloaded during a run.
class DARKROOM_API Registry {
public:
    Registry();
    ~Registry();
    Registry(const Registry&) = delete;
    Registry& operator=(const Registry&) = delete;

    // The plugin directory next to the running executable
    // (<exe>/../lib/darkroom/plugins), then each entry of DARKROOM_PLUGIN_PATH
    // (colon separated), then `extra` (from --plugin-path), in that order.
    static std::vector<std::string> defaultSearchPath(const std::vector<std::string>& extra = {});

    // Loads every darkroom-*.so in each directory (or the file itself when an
    // entry is a file). Failures are reported in the returned diagnostics with
    // the plugin's path and reason, and the plugin is skipped. New or changed
    // files are first loaded in a child process (darkroom-plugin-probe): one
    // that crashes, exits or hangs there is quarantined, not loaded.
    //
    // `wanted`, when given: the node types the host needs (a pipeline's),
    // and kEveryCaptureBackend when it creates capture backends (a pipeline
    // with a Capture node, which picks one by a parameter's value). A plugin
    // the scan knows registers none of them is not loaded but kept aside
    // (dlopen of a plugin linking FFmpeg or pango costs more than many a
    // pipeline's run, and Embree's backend about 5 ms); loadSetAside() loads
    // those later, e.g. when a type turns out to be missing.
    Diagnostics loadPlugins(const std::vector<std::string>& searchPath,
                            const std::set<std::string>* wanted = nullptr);
    static constexpr const char* kEveryCaptureBackend = "backend:*";
    // Loads the plugins loadPlugins set aside; none: nothing happens.
    Diagnostics loadSetAside();
    std::size_t setAside() const { return setAside_.size(); }
    // Loads one plugin file; returns false and appends a diagnostic on failure.
    bool loadPlugin(const std::string& path, Diagnostics& out);
    // Registers types from code linked into the host (tests, builtins).
    // Throws darkroom::Error on a duplicate type name.
    void registerBuiltin(const std::string& pluginName, void (*fn)(Registrar&));

    const RegisteredFilter* filter(const std::string& type) const;
    const RegisteredBackend* backend(const std::string& type) const;
    std::vector<const RegisteredFilter*> filters() const;    // sorted by type
    std::vector<const RegisteredBackend*> backends() const;  // sorted by type
    // The type names of filters() (and, with `backends`, of backends()),
    // sorted: what a "did you mean" picks from.
    std::vector<std::string> typeNames(bool withBackends = false) const;
    const std::vector<LoadedPlugin>& plugins() const { return plugins_; }

    // Creates a filter through the plugin error boundary; throws darkroom::Error
    // naming the type when unknown or when the factory throws.
    std::unique_ptr<Filter> createFilter(const std::string& type) const;
    std::unique_ptr<CaptureBackend> createBackend(const std::string& type) const;

    // Ports of a type, cached (ports() is cheap but called very often).
    const PortList& ports(const std::string& type) const;

private:
    static void checkRegistrations(const std::vector<FilterInfo>& filters);
    void commit(const Origin& origin, std::vector<FilterInfo> filters,
                std::vector<CaptureBackendInfo> backends);
    std::map<std::string, RegisteredFilter> filters_;
    std::map<std::string, RegisteredBackend> backends_;
    std::vector<LoadedPlugin> plugins_;
    mutable std::mutex portMutex_;
    mutable std::map<std::string, PortList> portCache_;
    std::vector<void*> handles_;
    std::vector<std::string> setAside_;  // plugin files loadPlugins did not load (`wanted`)
};

}  // namespace darkroom
