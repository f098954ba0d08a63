// `darkroom info DB`: what a Cinema database holds.
#include "commands.h"

#include <darkroom/error.h>
#include <darkroom/data/cinema/database.h>

#include <CLI/CLI.hpp>
#include <fmt/core.h>

namespace darkroom::cli {

void addInfoCommand(CLI::App& app, GlobalOptions&, Runner& run) {
    auto* cmd = app.add_subcommand("info", "Describe a Cinema database: rows, columns, channels, image size, camera");
    auto path = std::make_shared<std::string>();
    auto strict = std::make_shared<bool>(false);
    cmd->add_option("DB", *path, "A .cdb folder or its data.csv")->required();
    cmd->add_flag("--strict", *strict, "Treat irregular data.csv rows and cells as errors");
    cmd->callback([&run, path, strict] {
        run = [path, strict] {
            CsvReadOptions o;
            o.strict = *strict;
            try {
                const CinemaDatabase db = CinemaDatabase::open(*path, o);
                const CinemaDescription d = db.describe();
                report(d.warnings);
                fmt::print("{}", formatDescription(d));
                // A product that disagrees with data.csv fails the check, as reading it would.
                if (hasErrors(d.warnings)) return int(kBadInput);
            } catch (const Error& e) {
                reportError(e.what());
                return int(kBadInput);
            }
            return int(kOk);
        };
    });
}

}  // namespace darkroom::cli
