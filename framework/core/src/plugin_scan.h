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

namespace darkroom {

struct ProbeVerdict {
    bool ok = false;
    std::string reason;  // why a plugin is quarantined
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
    };
    std::string probe_;
    std::string cacheFile_;
    std::map<std::string, Entry> entries_;
    bool dirty_ = false;
};

// Runs `probe PLUGIN` with a time limit and interprets how it ended.
ProbeVerdict runProbe(const std::string& probe, const std::string& plugin, double timeoutSeconds);

}  // namespace darkroom
