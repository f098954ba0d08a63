#include "commands.h"

#include <CLI/CLI.hpp>
#include <fmt/core.h>
#include <nlohmann/json.hpp>

namespace darkroom::cli {

void addPluginsCommand(CLI::App& app, GlobalOptions& global, Runner& run) {
    auto* cmd = app.add_subcommand("plugins", "List loaded plugins and the node types and capture backends they provide");
    auto json = std::make_shared<bool>(false);
    cmd->add_flag("--json", *json, "Machine-readable output");
    cmd->callback([&global, &run, json] {
        run = [&global, json] {
            const Registry& r = loadRegistry(global);
            if (*json) {
                // Keys in the order written (ordered_json), as scripts reading it expect.
                nlohmann::ordered_json out;
                out["plugins"] = nlohmann::ordered_json::array();
                for (const auto& p : r.plugins())
                    out["plugins"].push_back({{"name", p.origin.plugin}, {"version", p.origin.version},
                                              {"sdkVersion", p.sdkVersion}, {"path", p.origin.path},
                                              {"types", p.types}});
                out["filters"] = nlohmann::ordered_json::array();
                for (const auto* f : r.filters())
                    out["filters"].push_back({{"type", f->info.type}, {"category", f->info.category},
                                              {"plugin", f->origin.plugin}, {"doc", f->info.doc}});
                out["backends"] = nlohmann::ordered_json::array();
                for (const auto* b : r.backends())
                    out["backends"].push_back(
                        {{"type", b->info.type}, {"plugin", b->origin.plugin}, {"doc", b->info.doc}});
                fmt::print("{}\n", out.dump());
                return kOk;
            }
            fmt::print("Plugins:\n");
            for (const auto& p : r.plugins())
                fmt::print("  {} {}  ({})\n", p.origin.plugin, p.origin.version,
                           p.origin.path.empty() ? "built in" : p.origin.path);
            fmt::print("Node types:\n");
            for (const auto* f : r.filters())
                fmt::print("  {:<18} {:<14} {}\n", f->info.type, f->info.category, f->origin.plugin);
            if (!r.backends().empty()) {
                fmt::print("Capture backends:\n");
                for (const auto* b : r.backends()) fmt::print("  {:<18} {}\n", b->info.type, b->origin.plugin);
            }
            return kOk;
        };
    });
}

}  // namespace darkroom::cli
