#pragma once
// Plugins are first loaded in a child process (darkroom-plugin-probe), as
// audio hosts scan their plugins: one that crashes, calls exit() or hangs
// while loading or registering is caught there, named and quarantined, and
// the host goes on without it. Verdicts are cached per file, by modification
// time and size, so only new or changed files are probed.
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace darkroom {

struct ProbeVerdict {
    ProbeVerdict() = default;
    ProbeVerdict(bool ok_, std::string reason_, std::optional<std::vector<std::string>> types_ = std::nullopt)
        : ok(ok_), reason(std::move(reason_)), types(std::move(types_)) {}
    bool ok = false;
    std::string reason;  // why a plugin is quarantined
    // The filter types it registers and its capture backends (as
    // "backend:NAME"), when the probe said: a host that needs only some types
    // loads only the plugins that have them (Registry::loadPlugins).
    std::optional<std::vector<std::string>> types;
};

class PluginScan {
public:
    // Reads the cache file (see cachePath()) if there is one.
    PluginScan();

    // Whether isolation is possible: the probe executable was found.
    bool available() const { return !probe_.empty(); }
    const std::string& probePath() const { return probe_; }

    // The verdict on one plugin file: cached when the file is unchanged,
    // otherwise probed now and remembered.
    ProbeVerdict check(const std::string& path);

    // Writes the cache atomically, when something changed and it has a place.
    void save();

    // $DARKROOM_PLUGIN_CACHE, else $XDG_CACHE_HOME/darkroom/..., else
    // ~/.cache/darkroom/...; empty when none can be determined.
    static std::string cachePath();

private:
    struct Entry {
        std::int64_t mtimeNs = 0;
        std::uintmax_t size = 0;
        ProbeVerdict verdict;
        // Probed by a probe that lists types (it may have listed none it
        // could: then the plugin is always loaded, and not probed again).
        bool typesAsked = false;
    };
    std::string probe_;
    std::string cacheFile_;
    std::map<std::string, Entry> entries_;
    bool dirty_ = false;
};

// The types a probe's "ok" line lists ("ok\tA,B,backend:embree"); none
// when it lists none (a bare "ok").
std::optional<std::vector<std::string>> typesSaid(const std::string& probeOutput);

// Runs `probe PLUGIN` with a time limit and interprets how it ended.
ProbeVerdict runProbe(const std::string& probe, const std::string& plugin, double timeoutSeconds);

}  // namespace darkroom
