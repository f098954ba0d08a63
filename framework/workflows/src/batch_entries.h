#pragma once
// Which rows a `run --foreach` shades, and what each entry is called. A
// Spec D database has one picture per row. A composable image set (TTK,
// Ascent, ParaView) has one row per CHANNEL of a picture (Depth, Elevation,
// SSSAO of one object): the batch shades one entry per layer, through the
// layer's first row (the reader reads the whole layer from any of its rows),
// named by the parameters that tell the layers apart ("object=000") rather
// than by every column of that row.
#include <darkroom/data/cinema/database.h>

#include <cstddef>
#include <map>
#include <string>
#include <vector>

namespace darkroom::workflows::batch {

struct BatchEntries {
    std::vector<std::size_t> rows;             // one per entry, in database order
    std::map<std::size_t, std::string> names;  // file-name-safe name of each row's entry
};

// The entries among `selected` rows (database order).
BatchEntries batchEntries(const CinemaDatabase& db, const std::vector<std::size_t>& selected);

}  // namespace darkroom::workflows::batch
