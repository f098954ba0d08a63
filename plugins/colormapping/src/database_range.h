#pragma once
// One colour scale per database (issue 29): the range of a channel over every
// entry of the Cinema database an image was read from, so that the entries
// of a movie over time, and their legends, share one scale instead of
// flickering. Where it comes from, cheapest first:
//  - a composable image set's CISChannelVarMin / CISChannelVarMax columns;
//  - a cache file of an earlier scan, valid while data.csv and every
//    product keep their modification times and sizes;
//  - a scan of every entry (read as CinemaReader reads it), then cached.
// Within a process a found range is kept while data.csv is unchanged (a
// --foreach run asks once per entry). The cache lives in the user's cache folder ($XDG_CACHE_HOME/darkroom/
// ranges, else ~/.cache/darkroom/ranges), never in the database: a
// database may be read-only, shared or someone else's.
#include <functional>
#include <string>

namespace darkroom {

struct DatabaseRange {
    double low = 0, high = 0;
    bool found = false;        // false when no entry had a finite value
    std::string database;      // the .cdb folder
};

// `source`: the product the image was read from (its metadata "source");
// the database is the nearest folder above it holding a data.csv.
// `selection`: the rows that count (--where syntax; CinemaReader's metadata
// "run.selection", set by a --foreach --where run); empty = every row.
// `positiveOnly` for a log scale. `clip` > 0: the clip-th and (100 - clip)-th
// percentiles of every entry's values instead of the minimum and maximum
// (a scan: the composable columns hold no percentiles; value_histogram.h).
// `progress` gets 0..1 while scanning. Throws darkroom::Error naming what is
// missing.
DatabaseRange databaseRange(const std::string& source, const std::string& selection, const std::string& channel,
                            bool positiveOnly, double clip, const std::function<void(double)>& progress = {});

}  // namespace darkroom
