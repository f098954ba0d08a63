#pragma once
// What produced the images a CinemaWriter writes, as the runner describes it
// to the node's `pipeline` input (darkroom/data/cinema/pipeline_origin.h):
// one line per node upstream, "node 'name' (Type)<TAB><digest>", the digest
// over the node's type, its parameters and the edges into it. A resume then
// refuses a database another pipeline wrote, naming the nodes that differ.
#include <darkroom/export.h>
#include <darkroom/core/graph.h>

#include <string>

namespace darkroom::workflows {

// The description of the pipeline upstream of `sink`. The inputs by which an
// entry reader (CinemaReader) chooses its entry, `entry` and `parameters`,
// are left out: --foreach changes them per entry and a resume adds entries.
DARKROOM_API std::string upstreamPipeline(const Graph& g, const std::string& sink);

// Sets `pipeline` on every node that has such a string input, unless an edge
// feeds it or the pipeline file or --set gave it a value.
DARKROOM_API void describeUpstreamPipelines(Graph& g);

}  // namespace darkroom::workflows
