#pragma once
// What produced the images a CinemaWriter writes, in the form its database
// records (the marker's origin items), so that a resume refuses a database
// another pipeline wrote instead of mixing old and new entries.
//
// The runner describes the pipeline upstream of each writer one node per
// line, "node 'name' (Type)<TAB><digest of its type, parameters and the
// edges into it>", and hands the text to the node's `pipeline` input; the
// node records each line as an origin item. Comparing items per node lets a
// refusal name the nodes that changed.
#include <darkroom/export.h>
#include <darkroom/data/cinema/writer.h>

#include <string>
#include <vector>

namespace darkroom {

// The origin items' source: "the pipeline upstream of the writer".
DARKROOM_API extern const char* const kUpstreamPipelineSource;

// The origin items a `pipeline` text describes (empty text: none). Throws
// darkroom::Error naming the line when one has no tab.
DARKROOM_API std::vector<CinemaOriginItem> pipelineOriginItems(const std::string& text);

// "" when the recorded items of kUpstreamPipelineSource equal `now`'s; else
// the nodes that differ, e.g. "node 'map' (ColorMapping) changed, node 'blur'
// (Blur) added"; or that the database records no pipeline at all.
DARKROOM_API std::string describePipelineChange(const std::vector<CinemaOriginItem>& recorded,
                                                const std::vector<CinemaOriginItem>& now);

}  // namespace darkroom
