#include "commands.h"
#include "json_writer.h"

#include <CLI/CLI.hpp>
#include <fmt/core.h>

namespace darkroom::cli {

void addPluginsCommand(CLI::App& app, GlobalOptions& global, Runner& run) {
    auto* cmd = app.add_subcommand("plugins", "List loaded plugins and the node types and capture backends they provide");
    auto json = std::make_shared<bool>(false);
    cmd->add_flag("--json", *json, "Machine-readable output");
    cmd->callback([&global, &run, json] {
        run = [&global, json] {
            const Registry& r = loadRegistry(global);
            if (*json) {
                JsonWriter w;
                w.beginObject();
                w.key("plugins").beginArray();
                for (const auto& p : r.plugins()) {
                    w.beginObject();
                    w.key("name").value(p.origin.plugin).key("version").value(p.origin.version);
                    w.key("sdkVersion").value(p.sdkVersion).key("path").value(p.origin.path);
                    w.key("types").beginArray();
                    for (const auto& t : p.types) w.value(t);
                    w.endArray().endObject();
                }
                w.endArray();
                w.key("filters").beginArray();
                for (const auto* f : r.filters()) {
                    w.beginObject().key("type").value(f->info.type).key("category").value(f->info.category);
                    w.key("plugin").value(f->origin.plugin).key("doc").value(f->info.doc).endObject();
                }
                w.endArray();
                w.key("backends").beginArray();
                for (const auto* b : r.backends()) {
                    w.beginObject().key("type").value(b->info.type).key("plugin").value(b->origin.plugin);
                    w.key("doc").value(b->info.doc).endObject();
                }
                w.endArray().endObject();
                fmt::print("{}\n", w.str());
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
