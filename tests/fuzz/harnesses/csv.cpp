// data.csv: the tolerant and the strict CSV reader in memory, then the Cinema
// database open path (column typing, distinct values) and row lookups.
#include "harness.h"

#include <darkroom/error.h>
#include <darkroom/data/cinema/csv.h>
#include <darkroom/data/cinema/database.h>

#include <filesystem>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    try {
        darkroom::parseCsv(fuzz::text(data, size), "data.csv", {.strict = true});
    } catch (const darkroom::Error&) {
    }
    try {
        fuzz::writeInput(data, size, "data.csv");
        const auto db = darkroom::CinemaDatabase::open(fuzz::scratchFolder());
        for (std::size_t r = 0; r < db.rowCount() && r < 16; ++r) {
            for (std::size_t c = 0; c < db.columns().size(); ++c) (void)db.number(r, c);
            (void)db.entryName(r);
            // Each row's own parameters find a row again.
            (void)db.find(db.formatParameters(r));
        }
    } catch (const darkroom::Error&) {
    }
    return 0;
}
