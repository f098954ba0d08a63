#pragma once
// The marker file Darkroom writes into every database folder it creates: it
// says the folder is Darkroom's (so --overwrite may remove what data.csv
// lists there) and records what the database is made from (so --resume can
// refuse to complete it from something else). Private to the cinema area.
#include <darkroom/data/cinema/writer.h>

#include <optional>
#include <string>
#include <vector>

namespace darkroom::cinema_detail {

inline constexpr const char* kMarkerFileName = ".darkroom-database";

// The marker's text for these origin items: deterministic (no time, no pid),
// so a resumed database ends byte-identical to an uninterrupted one.
std::string markerText(const std::vector<CinemaOriginItem>& origin);

// The origin recorded in `<folder>/.darkroom-database`; nullopt when there is
// no marker. Throws darkroom::Error naming the file when it cannot be read.
std::optional<std::vector<CinemaOriginItem>> readMarker(const std::string& folder);

// "the scene file changed since the capture began (resolution 64x64 → 32x32)",
// or empty when `recorded` and `now` agree.
std::string describeOriginChange(const std::vector<CinemaOriginItem>& recorded,
                                 const std::vector<CinemaOriginItem>& now);

}  // namespace darkroom::cinema_detail
