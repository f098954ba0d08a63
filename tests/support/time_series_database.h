#pragma once
// A small Cinema database with one `time` parameter, the source the batch
// shading tests (the workflow, CinemaWriter's runs and its staging) read.
#include <string>
#include <vector>

namespace darkroom::test {

// Writes `path` (a .cdb folder) with one 6x4 entry per time; each entry's
// `Z` and `value` channels hold the time, so a shaded entry says which
// source entry it came from.
void writeTimeSeriesDatabase(const std::string& path, const std::vector<double>& times);

}  // namespace darkroom::test
